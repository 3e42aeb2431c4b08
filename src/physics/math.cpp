#include "physics/math.h"

#include <cmath>

namespace coilsim {

Quat quatExp(const Vec3& r) {
  const double a2 = r.squaredNorm();
  // Beam increments and per-step rotations are small: there the Taylor
  // series of cos(a/2) and sin(a/2)/a, exact to double precision below
  // 0.05 rad, saves sin, cos and a square root in the hot path.
  if (a2 < 0.0025) {
    const double x = 0.25 * a2;  // (a/2)^2
    const double c = 1 - x / 2 * (1 - x / 12 * (1 - x / 30 * (1 - x / 56 * (1 - x / 90))));
    const double s = 0.5 * (1 - x / 6 * (1 - x / 20 * (1 - x / 42 * (1 - x / 72 * (1 - x / 110)))));
    return Quat(c, s * r.x(), s * r.y(), s * r.z());
  }
  const double angle = std::sqrt(a2), half = 0.5 * angle;
  const double s = std::sin(half) / angle;
  return Quat(std::cos(half), s * r.x(), s * r.y(), s * r.z());
}

Vec3 quatLog(const Quat& qIn) {
  Quat q = qIn;
  if (q.w() < 0) q.coeffs() = -q.coeffs();  // shortest rotation, angle <= pi
  const Vec3 v = q.vec();
  const double s2 = v.squaredNorm();
  // Small rotations (|v| / w < 0.03): 2 atan(x) / x as its series in
  // x^2 = |v|^2 / w^2, exact to double precision there; no atan2 or sqrt.
  if (s2 < 9e-4 * q.w() * q.w()) {
    const double x2 = s2 / (q.w() * q.w());
    const double f = 2 * (1 - x2 * (1. / 3 - x2 * (1. / 5 - x2 * (1. / 7 - x2 * (1. / 9 - x2 * (1. / 11 - x2 / 13))))));
    return v * (f / q.w());
  }
  const double sinHalf = std::sqrt(s2);
  const double angle = 2.0 * std::atan2(sinHalf, q.w());
  return v * (angle / sinHalf);
}

Vec3 anyPerpendicular(const Vec3& v) {
  const Vec3 a = std::abs(v.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY();
  return v.cross(a).normalized();
}

Quat minimalRotation(const Vec3& from, const Vec3& to) {
  // q = (|a||b| + a.b, a x b), normalised, is the half-angle rotation taking
  // a onto b: no trigonometry, and this runs for every beam in every step.
  const double norms = std::sqrt(from.squaredNorm() * to.squaredNorm());
  const double c = from.dot(to);
  if (c < (-1.0 + 1e-12) * norms) return Quat(Eigen::AngleAxisd(M_PI, anyPerpendicular(from)));
  const Vec3 axis = from.cross(to);
  Quat q(norms + c, axis.x(), axis.y(), axis.z());
  return q.normalized();
}

}  // namespace coilsim
