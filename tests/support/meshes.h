#pragma once
// Test surfaces for the contact tests, built in memory (no files): an
// icosphere (a closed cavity when seen from inside), a plane as a grid of
// triangles, a box. Winding: counter-clockwise seen from outside, so the
// triangle normals point out of the closed surface (into the wall material,
// away from where rods live) - the convention of physics/triangle_mesh.h.
#include <array>
#include <cmath>
#include <map>
#include <memory>
#include <utility>
#include <vector>

#include "physics/triangle_mesh.h"

namespace coilsim::test {

// Sphere of circumradius `radius` about `centre`: the icosahedron with each
// triangle split in four `levels` times (20 * 4^levels triangles), vertices
// pushed onto the sphere.
inline TriangleMesh icosphere(double radius, int levels, const Vec3& centre = Vec3::Zero()) {
  const double t = (1 + std::sqrt(5.0)) / 2;
  std::vector<Vec3> v = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0}, {0, -1, t}, {0, 1, t},
                         {0, -1, -t}, {0, 1, -t}, {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
  for (Vec3& p : v) p.normalize();
  std::vector<Eigen::Vector3i> f = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                                    {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                                    {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                                    {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
  for (int l = 0; l < levels; ++l) {
    std::map<std::pair<int, int>, int> mid;
    const auto middle = [&](int a, int b) {
      const auto key = std::minmax(a, b);
      const auto it = mid.find(key);
      if (it != mid.end()) return it->second;
      v.push_back((v[a] + v[b]).normalized());
      return mid[key] = int(v.size()) - 1;
    };
    std::vector<Eigen::Vector3i> g;
    for (const auto& tri : f) {
      const int a = middle(tri[0], tri[1]), b = middle(tri[1], tri[2]), c = middle(tri[2], tri[0]);
      g.push_back({tri[0], a, c});
      g.push_back({tri[1], b, a});
      g.push_back({tri[2], c, b});
      g.push_back({a, b, c});
    }
    f = std::move(g);
  }
  TriangleMesh m;
  m.name = "icosphere";
  for (const Vec3& p : v) m.vertices.push_back(centre + radius * p);
  m.triangles = std::move(f);
  return m;
}

// Square plane through `origin`, n x n cells of 2 * halfSize / n, whose
// triangles face `intoWall` (unit): rods rest on the side -intoWall.
inline TriangleMesh plane(const Vec3& origin, const Vec3& intoWall, double halfSize, int n) {
  const Vec3 w = intoWall.normalized();
  const Vec3 u = (std::abs(w.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY()).cross(w).normalized();
  const Vec3 vv = w.cross(u);  // (u, vv, w) right-handed: counter-clockwise in (u, vv) faces +w
  TriangleMesh m;
  m.name = "plane";
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i)
      m.vertices.push_back(origin + (-halfSize + 2 * halfSize * i / n) * u + (-halfSize + 2 * halfSize * j / n) * vv);
  const auto id = [n](int i, int j) { return j * (n + 1) + i; };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      m.triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      m.triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  return m;
}

// Axis-aligned box [lo, hi], two triangles per face, normals outwards.
inline TriangleMesh box(const Vec3& lo, const Vec3& hi) {
  TriangleMesh m;
  m.name = "box";
  for (int k = 0; k < 8; ++k) m.vertices.push_back(Vec3(k & 1 ? hi.x() : lo.x(), k & 2 ? hi.y() : lo.y(), k & 4 ? hi.z() : lo.z()));
  const std::array<std::array<int, 4>, 6> faces = {{{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                                                   {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}}};
  for (const auto& q : faces) {
    m.triangles.push_back({q[0], q[1], q[2]});
    m.triangles.push_back({q[0], q[2], q[3]});
  }
  return m;
}

inline Obstacle obstacleOf(TriangleMesh mesh, double friction = 0.3) {
  Obstacle o;
  o.name = mesh.name;
  o.mesh = std::make_shared<const TriangleMesh>(std::move(mesh));
  o.friction = friction;
  return o;
}

// Inscribed-sphere distance of a convex closed mesh: for a point inside,
// the distance to the surface is the least distance to the face planes
// (exact for convex polyhedra, independent of the contact code's
// closest-point queries). Negative when outside.
inline double convexClearance(const TriangleMesh& m, const Vec3& p) {
  double d = INFINITY;
  for (const auto& t : m.triangles) {
    const Vec3 a = m.vertices[t[0]];
    const Vec3 n = (m.vertices[t[1]] - a).cross(m.vertices[t[2]] - a).normalized();
    d = std::min(d, n.dot(a - p));
  }
  return d;
}

// The same clearance for many points: the face planes as one matrix, and a
// shortcut for points deep inside (the clearance is at least the inscribed
// radius about `centre` minus the distance from it), which are the most.
class ConvexCavity {
 public:
  explicit ConvexCavity(const TriangleMesh& m, const Vec3& centre = Vec3::Zero()) : centre_(centre) {
    normals_.resize(Eigen::Index(m.triangles.size()), 3);
    offsets_.resize(Eigen::Index(m.triangles.size()));
    for (size_t t = 0; t < m.triangles.size(); ++t) {
      const Vec3 a = m.vertices[m.triangles[t][0]];
      const Vec3 n = (m.vertices[m.triangles[t][1]] - a).cross(m.vertices[m.triangles[t][2]] - a).normalized();
      normals_.row(Eigen::Index(t)) = n.transpose();
      offsets_[Eigen::Index(t)] = n.dot(a - centre);
    }
    inscribed_ = offsets_.minCoeff();
  }
  // Exact clearance of p (negative outside) when it is below `atLeast`;
  // otherwise any value >= atLeast.
  double clearance(const Vec3& p, double atLeast) const {
    const Vec3 q = p - centre_;
    const double bound = inscribed_ - q.norm();
    if (bound >= atLeast) return bound;
    return (offsets_ - normals_ * q).minCoeff();
  }
  double inscribedRadius() const { return inscribed_; }

 private:
  Vec3 centre_;
  Eigen::Matrix<double, Eigen::Dynamic, 3> normals_;  // (ntriangle x 3)
  Eigen::VectorXd offsets_;                          // (ntriangle)
  double inscribed_ = 0;
};

}  // namespace coilsim::test
