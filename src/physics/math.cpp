#include "physics/math.h"

#include <cmath>

namespace coilsim {

Quat quatExp(const Vec3& r) {
  const double angle = r.norm();
  const double half = 0.5 * angle;
  // sin(half)/angle, with its Taylor series where angle is tiny.
  const double s = angle < 1e-8 ? 0.5 - angle * angle / 48.0 : std::sin(half) / angle;
  return Quat(std::cos(half), s * r.x(), s * r.y(), s * r.z());
}

Vec3 quatLog(const Quat& qIn) {
  Quat q = qIn;
  if (q.w() < 0) q.coeffs() = -q.coeffs();  // shortest rotation, angle <= pi
  const Vec3 v = q.vec();
  const double sinHalf = v.norm();
  if (sinHalf < 1e-10) return 2.0 * v / std::max(q.w(), 1e-300) * 1.0;  // 2 v / w ~ angle * axis
  const double angle = 2.0 * std::atan2(sinHalf, q.w());
  return v * (angle / sinHalf);
}

Vec3 anyPerpendicular(const Vec3& v) {
  const Vec3 a = std::abs(v.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY();
  return v.cross(a).normalized();
}

Quat minimalRotation(const Vec3& from, const Vec3& to) {
  const double c = from.dot(to);
  if (c < -1.0 + 1e-12) return Quat(Eigen::AngleAxisd(M_PI, anyPerpendicular(from)));
  Quat q;
  q.setFromTwoVectors(from, to);
  return q.normalized();
}

}  // namespace coilsim
