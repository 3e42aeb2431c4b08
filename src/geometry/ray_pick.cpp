#include "geometry/ray_pick.h"

#include <algorithm>
#include <cmath>

namespace coilsim::geometry {
namespace {

// Moller-Trumbore: the distance along unit `d` to triangle (a, b, c), or
// a negative value when the ray misses it or runs parallel to it.
double crossAt(const Vec3& o, const Vec3& d, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 e1 = b - a, e2 = c - a;
  const Vec3 p = d.cross(e2);
  const double det = e1.dot(p);
  const double scale = e1.norm() * e2.norm();
  if (!(std::abs(det) > 1e-12 * scale)) return -1;
  const Vec3 s = o - a;
  const double u = s.dot(p) / det;
  if (u < 0 || u > 1) return -1;
  const Vec3 q = s.cross(e1);
  const double v = d.dot(q) / det;
  if (v < 0 || u + v > 1) return -1;
  return e2.dot(q) / det;
}

}  // namespace

std::vector<double> rayHits(const TriangleMesh& mesh, const Vec3& origin, const Vec3& direction) {
  std::vector<double> hits;
  if (!origin.allFinite() || !direction.allFinite() || !(direction.norm() > 0)) return hits;
  const Vec3 d = direction.normalized();
  for (const Eigen::Vector3i& f : mesh.triangles) {
    const double t = crossAt(origin, d, mesh.vertices[f[0]], mesh.vertices[f[1]], mesh.vertices[f[2]]);
    if (t >= 0) hits.push_back(t);
  }
  std::sort(hits.begin(), hits.end());
  // A ray through a shared edge meets both triangles at one distance: one crossing.
  const double merge = 1e-9 * (hits.empty() ? 1.0 : std::max(1.0, hits.back()));
  hits.erase(std::unique(hits.begin(), hits.end(), [merge](double a, double b) { return b - a <= merge; }), hits.end());
  return hits;
}

std::optional<Vec3> firstHit(const TriangleMesh& mesh, const Vec3& origin, const Vec3& direction) {
  const std::vector<double> hits = rayHits(mesh, origin, direction);
  if (hits.empty()) return std::nullopt;
  return Vec3(origin + hits.front() * direction.normalized());
}

std::optional<Vec3> firstLumenMiddle(const TriangleMesh& mesh, const Vec3& origin, const Vec3& direction) {
  const std::vector<double> hits = rayHits(mesh, origin, direction);
  if (hits.size() < 2) return std::nullopt;
  return Vec3(origin + 0.5 * (hits[0] + hits[1]) * direction.normalized());
}

}  // namespace coilsim::geometry
