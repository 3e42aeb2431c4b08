#pragma once
// Geometry read off node points, independently of coilsim's rest-shape code:
// the helix through four consecutive samples (exact for a helix sampled at
// equal arc length), a least-squares sphere, a circle through three points.
#include <Eigen/Dense>
#include <cmath>
#include <vector>

#include "physics/math.h"

namespace coilsim::test {

struct HelixFit {
  double radius = 0;    // R, loop radius
  double c = 0;         // pitch / (2 pi), signed: > 0 right-handed, < 0 left-handed
  double curvature = 0; // R / (R^2 + c^2)
  double torsion = 0;   // c / (R^2 + c^2)
};

// The helix through p0..p3, assumed equally spaced along it. Samples of a
// helix at equal arc length are images of each other under one screw motion,
// so the chords e_k = p_{k+1} - p_k are turned by a fixed angle dphi about
// the axis a and keep their axial part: the chord differences are normal to
// a, a ~ (e1 - e0) x (e2 - e1) (oriented so the turn is positive), dphi is
// the angle between the chords' normal parts, R = |e_perp| / (2 sin(dphi/2))
// and c = (e . a) / dphi. Exact up to round-off; a right-handed helix (the
// chords turn counter-clockwise while advancing along +a) has c > 0.
inline HelixFit helixThrough(const Vec3& p0, const Vec3& p1, const Vec3& p2, const Vec3& p3) {
  const Vec3 e0 = p1 - p0, e1 = p2 - p1, e2 = p3 - p2;
  const Vec3 a = (e1 - e0).cross(e2 - e1).normalized();
  const Vec3 n0 = e0 - e0.dot(a) * a, n1 = e1 - e1.dot(a) * a;
  const double dphi = std::atan2(n0.cross(n1).dot(a), n0.dot(n1));
  HelixFit h;
  h.radius = n0.norm() / (2.0 * std::sin(0.5 * dphi));
  h.c = e0.dot(a) / dphi;
  const double r2 = h.radius * h.radius + h.c * h.c;
  h.curvature = h.radius / r2;
  h.torsion = h.c / r2;
  return h;
}

struct Sphere {
  Vec3 centre = Vec3::Zero();
  double radius = 0;
};

// Algebraic least-squares sphere: |x|^2 = 2 c.x + (R^2 - |c|^2), linear in
// (c, R^2 - |c|^2); exact when the points lie on a sphere.
inline Sphere fitSphere(const std::vector<Vec3>& points) {
  const int n = int(points.size());
  Eigen::MatrixXd a(n, 4);
  Eigen::VectorXd b(n);
  for (int i = 0; i < n; ++i) {
    a.row(i) << 2 * points[i].x(), 2 * points[i].y(), 2 * points[i].z(), 1.0;
    b[i] = points[i].squaredNorm();
  }
  const Eigen::Vector4d s = a.colPivHouseholderQr().solve(b);
  Sphere out;
  out.centre = s.head<3>();
  out.radius = std::sqrt(s[3] + out.centre.squaredNorm());
  return out;
}

// Radius of the circle through three points (circumradius).
inline double circumradius(const Vec3& a, const Vec3& b, const Vec3& c) {
  const double ab = (b - a).norm(), bc = (c - b).norm(), ca = (a - c).norm();
  return ab * bc * ca / (2.0 * (b - a).cross(c - a).norm());
}

}  // namespace coilsim::test
