#include "geometry/mesh_query.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "physics/contact/geometry.h"  // closestPointTriangle (Ericson 5.1.5), shared with contact

namespace coilsim::geometry {
namespace {

constexpr int kLeafSize = 4;

// Slab test of a ray against a box; false when it misses.
bool rayHitsBox(const Eigen::AlignedBox3d& box, const Vec3& o, const Vec3& invDir) {
  double t0 = 0, t1 = std::numeric_limits<double>::infinity();
  for (int k = 0; k < 3; ++k) {
    double a = (box.min()[k] - o[k]) * invDir[k], b = (box.max()[k] - o[k]) * invDir[k];
    if (a > b) std::swap(a, b);
    if (std::isnan(a) || std::isnan(b)) continue;  // ray parallel to the slab, origin inside it
    t0 = std::max(t0, a), t1 = std::min(t1, b);
    if (t0 > t1) return false;
  }
  return true;
}

// Directions for parity rays: irrational-looking, so axis-aligned meshes
// (boxes, grids) are not grazed systematically.
const std::array<Vec3, 6> kRayDirections = {
    Vec3(0.5773, 0.5917, 0.5628).normalized(), Vec3(-0.3127, 0.8391, -0.4451).normalized(),
    Vec3(0.7159, -0.2846, -0.6374).normalized(), Vec3(-0.6583, -0.5271, 0.5376).normalized(),
    Vec3(0.1213, -0.9178, 0.3782).normalized(), Vec3(-0.8717, 0.1399, -0.4697).normalized()};

}  // namespace

MeshQuery::MeshQuery(const TriangleMesh& mesh) : mesh_(mesh) {
  const int n = int(mesh_.triangles.size());
  order_.resize(n);
  std::vector<Vec3> centres(n);
  for (int t = 0; t < n; ++t) {
    order_[t] = t;
    const Eigen::Vector3i& f = mesh_.triangles[t];
    centres[t] = (mesh_.vertices[f[0]] + mesh_.vertices[f[1]] + mesh_.vertices[f[2]]) / 3.0;
  }
  nodes_.reserve(2 * size_t(n) / kLeafSize + 2);
  if (n > 0) build(0, n, centres);
}

// Median split along the longest axis of the centres' box.
int MeshQuery::build(int first, int count, std::vector<Vec3>& centres) {
  const int index = int(nodes_.size());
  nodes_.emplace_back();
  Eigen::AlignedBox3d box, centreBox;
  for (int i = first; i < first + count; ++i) {
    const Eigen::Vector3i& f = mesh_.triangles[order_[i]];
    for (int k = 0; k < 3; ++k) box.extend(mesh_.vertices[f[k]]);
    centreBox.extend(centres[order_[i]]);
  }
  nodes_[index].box = box;
  if (count <= kLeafSize) {
    nodes_[index].first = first, nodes_[index].count = count;
    return index;
  }
  int axis = 0;
  centreBox.sizes().maxCoeff(&axis);
  const int mid = first + count / 2;
  std::nth_element(order_.begin() + first, order_.begin() + mid, order_.begin() + first + count,
                   [&](int a, int b) { return centres[a][axis] < centres[b][axis]; });
  const int left = build(first, mid - first, centres);
  const int right = build(mid, first + count - mid, centres);
  nodes_[index].left = left, nodes_[index].right = right;
  return index;
}

namespace {

// Moeller-Trumbore: where the ray o + t dir meets the plane of triangle
// (a, b, c), in barycentric u, v and ray parameter t. False when the ray is
// parallel to the plane (`inPlane` then says whether it lies in it).
struct RayCrossing {
  double u = 0, v = 0, t = 0;
};
bool rayTrianglePlane(const Vec3& o, const Vec3& dir, const Vec3& a, const Vec3& b, const Vec3& c, RayCrossing& x,
                      bool& inPlane) {
  const Vec3 e1 = b - a, e2 = c - a, pv = dir.cross(e2);
  const double det = e1.dot(pv);
  const double scale = e1.norm() * e2.norm();
  if (std::abs(det) <= 1e-12 * scale) {
    inPlane = std::abs((o - a).dot(e1.cross(e2))) <= 1e-12 * scale * (o - a).norm();
    return false;
  }
  const double invDet = 1.0 / det;
  const Vec3 tv = o - a, qv = tv.cross(e1);
  x.u = tv.dot(pv) * invDet;
  x.v = dir.dot(qv) * invDet;
  x.t = e2.dot(qv) * invDet;
  return true;
}

}  // namespace

template <class Visit>
bool MeshQuery::walkRay(const Vec3& o, const Vec3& dir, Visit&& visit) const {
  if (nodes_.empty()) return true;
  const Vec3 inv = dir.cwiseInverse();
  int stack[128];
  int top = 0;
  stack[top++] = 0;
  while (top) {
    const Node& node = nodes_[stack[--top]];
    if (!rayHitsBox(node.box, o, inv)) continue;
    if (node.left >= 0) {
      stack[top++] = node.left, stack[top++] = node.right;
      continue;
    }
    for (int i = node.first; i < node.first + node.count; ++i) {
      const Eigen::Vector3i& f = mesh_.triangles[order_[i]];
      if (!visit(order_[i], mesh_.vertices[f[0]], mesh_.vertices[f[1]], mesh_.vertices[f[2]])) return false;
    }
  }
  return true;
}

int MeshQuery::crossings(const Vec3& o, const Vec3& dir) const {
  int count = 0;
  const bool clear = walkRay(o, dir, [&](int, const Vec3& a, const Vec3& b, const Vec3& c) {
    // Barycentric margins: a hit too near an edge is ambiguous (it may be
    // counted twice or not at all), so ask for another ray; so is a ray
    // lying in a triangle's plane.
    RayCrossing x;
    bool inPlane = false;
    if (!rayTrianglePlane(o, dir, a, b, c, x, inPlane)) return !inPlane;
    constexpr double eps = 1e-9;
    if (x.u < -eps || x.v < -eps || x.u + x.v > 1 + eps || x.t < 0) return true;
    if (x.u < eps || x.v < eps || x.u + x.v > 1 - eps) return false;
    ++count;
    return true;
  });
  return clear ? count : -1;
}

int MeshQuery::firstHit(const Vec3& o, const Vec3& dir) const {
  int hit = -1;
  double nearest = std::numeric_limits<double>::infinity();
  walkRay(o, dir, [&](int triangle, const Vec3& a, const Vec3& b, const Vec3& c) {
    RayCrossing x;
    bool inPlane = false;
    if (!rayTrianglePlane(o, dir, a, b, c, x, inPlane)) return true;
    if (x.u < 0 || x.v < 0 || x.u + x.v > 1 || !(x.t > 0) || x.t >= nearest) return true;
    nearest = x.t, hit = triangle;
    return true;
  });
  return hit;
}

bool MeshQuery::inside(const Vec3& p) const {
  for (const Vec3& d : kRayDirections) {
    const int n = crossings(p, d);
    if (n >= 0) return n % 2 == 1;
  }
  // Every ray grazed something: the point is on (or within rounding of) the surface.
  return false;
}

ClosestPoint MeshQuery::closest(const Vec3& p) const {
  ClosestPoint best;
  if (nodes_.empty()) return best;
  double best2 = std::numeric_limits<double>::infinity();
  int stack[128];
  int top = 0;
  stack[top++] = 0;
  while (top) {
    const Node& node = nodes_[stack[--top]];
    if (node.box.squaredExteriorDistance(p) >= best2) continue;
    if (node.left >= 0) {
      // Visit the nearer child first so the bound tightens early.
      const double dl = nodes_[node.left].box.squaredExteriorDistance(p);
      const double dr = nodes_[node.right].box.squaredExteriorDistance(p);
      if (dl < dr) stack[top++] = node.right, stack[top++] = node.left;
      else stack[top++] = node.left, stack[top++] = node.right;
      continue;
    }
    for (int i = node.first; i < node.first + node.count; ++i) {
      const Eigen::Vector3i& f = mesh_.triangles[order_[i]];
      const Vec3 q = closestPointTriangle(p, mesh_.vertices[f[0]], mesh_.vertices[f[1]], mesh_.vertices[f[2]]);
      const double d2 = (q - p).squaredNorm();
      if (d2 < best2) best2 = d2, best.point = q, best.triangle = order_[i];
    }
  }
  best.distance = std::sqrt(best2);
  return best;
}

double MeshQuery::signedDistance(const Vec3& p) const {
  const double d = closest(p).distance;
  return inside(p) ? -d : d;
}

}  // namespace coilsim::geometry
