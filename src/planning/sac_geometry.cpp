// Volumes, inside tests and clipped lengths against a closed triangle surface.
#include "planning/sac_geometry.h"

#include "geometry/sac_morphology.h"
#include "geometry/volume.h"

#include <algorithm>
#include <array>
#include <map>
#include <stdexcept>
#include <vector>

namespace coilsim::planning {
namespace {

// Möller-Trumbore: parameter t of the line o + t d through triangle (a, b, c), or false.
bool lineTriangle(const Vec3& o, const Vec3& d, const Vec3& a, const Vec3& b, const Vec3& c, double& t) {
  const Vec3 e1 = b - a, e2 = c - a, p = d.cross(e2);
  const double det = e1.dot(p);
  if (std::abs(det) < 1e-30) return false;
  const double inv = 1.0 / det;
  const Vec3 s = o - a;
  const double u = s.dot(p) * inv;
  if (u < 0 || u > 1) return false;
  const Vec3 q = s.cross(e1);
  const double v = d.dot(q) * inv;
  if (v < 0 || u + v > 1) return false;
  t = e2.dot(q) * inv;
  return true;
}

}  // namespace

Sac makeSac(std::shared_ptr<const TriangleMesh> mesh, const Plane& neck) {
  Sac sac;
  sac.query = std::make_shared<const geometry::MeshQuery>(*mesh);
  sac.mesh = std::move(mesh);
  sac.neck = neck;
  sac.neck.normal.normalize();
  // Pieces on the sac side: the one nearest any point holds every triangle
  // reaching that side exactly when there is one piece.
  const TriangleMesh& m = *sac.mesh;
  const geometry::Plane cut{sac.neck.point, sac.neck.normal};
  size_t above = 0;
  for (const auto& f : m.triangles)
    above += sac.neck.signedDistance(m.vertices[f[0]]) > 0 || sac.neck.signedDistance(m.vertices[f[1]]) > 0 ||
             sac.neck.signedDistance(m.vertices[f[2]]) > 0;
  const std::vector<char> any = geometry::sacPiece(m, cut, sac.neck.point);
  if (size_t(std::count(any.begin(), any.end(), char(1))) == above) return sac;
  // Several pieces: the sac's is the one over the neck's point.
  Eigen::AlignedBox3d box;
  for (const Vec3& v : m.vertices) box.extend(v);
  const Vec3 start = sac.neck.point + 1e-9 * box.diagonal().norm() * sac.neck.normal;
  const int hit = sac.query->inside(start) ? sac.query->firstHit(start, sac.neck.normal) : -1;
  if (hit < 0)
    throw std::invalid_argument(
        "the neck plane cuts the surface into several pieces on the sac side, and its point is not inside the "
        "surface, so which piece is the sac cannot be told: put the point in the ostium");
  const auto& f = m.triangles[size_t(hit)];
  sac.pieceSeed = (m.vertices[f[0]] + m.vertices[f[1]] + m.vertices[f[2]]) / 3.0;
  sac.piece = std::make_shared<const std::vector<char>>(geometry::sacPiece(m, cut, sac.pieceSeed));
  return sac;
}

double sacVolume(const Sac& sac) {
  if (!sac.piece) return volumeOnSide(*sac.mesh, sac.neck);
  return geometry::measureSac(*sac.mesh, geometry::Plane{sac.neck.point, sac.neck.normal}, sac.pieceSeed, 0, true).volume;
}

namespace {

// Under the sac's piece: the ray along the normal, which stays on the sac
// side, leaves the inside through the piece bounding the point's region.
bool underSacPiece(const Sac& sac, const Vec3& x) {
  if (!sac.piece) return true;
  const int hit = sac.query->firstHit(x, sac.neck.normal);
  return hit >= 0 && (*sac.piece)[size_t(hit)];
}

}  // namespace

bool inSac(const Sac& sac, const Vec3& x) {
  return sac.neck.signedDistance(x) >= 0 && sac.query->inside(x) && underSacPiece(sac, x);
}

double enclosedVolume(const TriangleMesh& mesh) { return geometry::enclosedVolume(mesh); }

double volumeOnSide(const TriangleMesh& mesh, const Plane& plane) {
  return geometry::volumeAbovePlane(mesh, geometry::Plane{plane.point, plane.normal.normalized()});
}

bool insideSurface(const Sac& sac, const Vec3& x) { return sac.query->inside(x); }

namespace {

double lengthOnSide(const Sac& sac, const Vec3& a, const Vec3& b, bool sacSide) {
  const double len = (b - a).norm();
  if (len == 0) return 0;
  const Vec3 d = b - a;
  std::vector<double> cuts{0.0, 1.0};
  const double sa = sac.neck.signedDistance(a), sb = sac.neck.signedDistance(b);
  if ((sa < 0) != (sb < 0)) cuts.push_back(sa / (sa - sb));
  // Only triangles whose box meets the segment's box can cut it.
  const Vec3 lo = a.cwiseMin(b), hi = a.cwiseMax(b);
  for (const auto& t : sac.mesh->triangles) {
    const Vec3& p0 = sac.mesh->vertices[t[0]];
    const Vec3& p1 = sac.mesh->vertices[t[1]];
    const Vec3& p2 = sac.mesh->vertices[t[2]];
    if ((p0.cwiseMax(p1).cwiseMax(p2).array() < lo.array()).any() ||
        (p0.cwiseMin(p1).cwiseMin(p2).array() > hi.array()).any())
      continue;
    double s = 0;
    if (lineTriangle(a, d, p0, p1, p2, s) && s > 0 && s < 1) cuts.push_back(s);
  }
  std::sort(cuts.begin(), cuts.end());
  double inside = 0;
  for (size_t i = 0; i + 1 < cuts.size(); ++i) {
    if (cuts[i + 1] - cuts[i] <= 0) continue;
    const Vec3 m = a + 0.5 * (cuts[i] + cuts[i + 1]) * d;
    const bool above = sac.neck.signedDistance(m) >= 0;
    if (sacSide != above && !(above && sac.piece)) continue;
    if (!sac.query->inside(m)) continue;
    if ((above && underSacPiece(sac, m)) == sacSide) inside += (cuts[i + 1] - cuts[i]) * len;
  }
  return inside;
}

}  // namespace

double lengthInSac(const Sac& sac, const Vec3& a, const Vec3& b) { return lengthOnSide(sac, a, b, true); }
double lengthBeyondNeck(const Sac& sac, const Vec3& a, const Vec3& b) { return lengthOnSide(sac, a, b, false); }

TriangleMesh makeIcosphere(const Vec3& centre, double radius, int subdivisions, const std::string& name) {
  const double g = (1.0 + std::sqrt(5.0)) / 2.0;
  std::vector<Vec3> v = {{-1, g, 0}, {1, g, 0}, {-1, -g, 0}, {1, -g, 0}, {0, -1, g}, {0, 1, g},
                         {0, -1, -g}, {0, 1, -g}, {g, 0, -1}, {g, 0, 1}, {-g, 0, -1}, {-g, 0, 1}};
  for (Vec3& p : v) p.normalize();
  std::vector<Eigen::Vector3i> f = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
                                    {11, 10, 2}, {10, 7, 6}, {7, 1, 8},   {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
                                    {3, 8, 9},  {4, 9, 5},  {2, 4, 11},  {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
  for (int s = 0; s < subdivisions; ++s) {
    std::map<std::pair<int, int>, int> mid;
    auto midpoint = [&](int i, int j) {
      const auto key = std::minmax(i, j);
      if (auto it = mid.find(key); it != mid.end()) return it->second;
      v.push_back((v[i] + v[j]).normalized());
      return mid[key] = int(v.size()) - 1;
    };
    std::vector<Eigen::Vector3i> next;
    next.reserve(f.size() * 4);
    for (const auto& t : f) {
      const int a = midpoint(t[0], t[1]), b = midpoint(t[1], t[2]), c = midpoint(t[2], t[0]);
      next.push_back({t[0], a, c});
      next.push_back({t[1], b, a});
      next.push_back({t[2], c, b});
      next.push_back({a, b, c});
    }
    f.swap(next);
  }
  TriangleMesh m;
  m.name = name;
  m.vertices.reserve(v.size());
  for (const Vec3& p : v) m.vertices.push_back(centre + radius * p);
  m.triangles = std::move(f);
  return m;
}

}  // namespace coilsim::planning
