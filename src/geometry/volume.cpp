#include "geometry/volume.h"

#include <array>
#include <cmath>

namespace coilsim::geometry {
namespace {

// The part of triangle abc with plane.side >= 0, as a polygon of at most 4
// vertices (Sutherland-Hodgman against one plane).
// cut[k] marks vertices made by the cut.
int clipTriangle(const Vec3& a, const Vec3& b, const Vec3& c, const Plane& plane, std::array<Vec3, 4>& out,
                 std::array<bool, 4>& cut) {
  const std::array<const Vec3*, 3> v{&a, &b, &c};
  const std::array<double, 3> s{plane.side(a), plane.side(b), plane.side(c)};
  int n = 0;
  for (int k = 0; k < 3; ++k) {
    const int j = (k + 1) % 3;
    if (s[k] >= 0) cut[n] = false, out[n++] = *v[k];
    if ((s[k] >= 0) != (s[j] >= 0)) {
      const double t = s[k] / (s[k] - s[j]);
      cut[n] = true, out[n++] = *v[k] + t * (*v[j] - *v[k]);
    }
  }
  return n;
}

}  // namespace

double enclosedVolume(const TriangleMesh& m) {
  double v = 0;
  for (const Eigen::Vector3i& f : m.triangles)
    v += m.vertices[f[0]].dot(m.vertices[f[1]].cross(m.vertices[f[2]]));
  return v / 6.0;
}

double volumeAbovePlane(const TriangleMesh& m, const Plane& plane) {
  double v = 0;
  std::array<Vec3, 4> poly;
  std::array<bool, 4> cut;
  for (const Eigen::Vector3i& f : m.triangles) {
    // Relative to a point of the plane: the closing cap then adds nothing.
    const Vec3 a = m.vertices[f[0]] - plane.point, b = m.vertices[f[1]] - plane.point,
               c = m.vertices[f[2]] - plane.point;
    const int n = clipTriangle(a, b, c, Plane{Vec3::Zero(), plane.normal}, poly, cut);
    for (int k = 1; k + 1 < n; ++k) v += poly[0].dot(poly[k].cross(poly[k + 1]));
  }
  return v / 6.0;
}

double sectionArea(const TriangleMesh& m, const Plane& plane) {
  // The cap is bounded by the clipped triangles' cut segments; its area is
  // the sum of the cut segments' signed areas about the plane point, seen along the normal.
  double area = 0;
  std::array<Vec3, 4> poly;
  std::array<bool, 4> cut;
  for (const Eigen::Vector3i& f : m.triangles) {
    const Vec3 a = m.vertices[f[0]] - plane.point, b = m.vertices[f[1]] - plane.point,
               c = m.vertices[f[2]] - plane.point;
    const int n = clipTriangle(a, b, c, Plane{Vec3::Zero(), plane.normal}, poly, cut);
    // The polygon's edge between its two cut vertices lies in the plane.
    for (int k = 0; k < n; ++k)
      if (cut[k] && cut[(k + 1) % n]) area += 0.5 * poly[k].cross(poly[(k + 1) % n]).dot(plane.normal);
  }
  // The surface runs around the cap against the normal's sense.
  return std::abs(area);
}

}  // namespace coilsim::geometry
