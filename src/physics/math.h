#pragma once
// Small fixed-size types and rotation helpers shared by the physics core.
// Rotations: unit quaternions for storage, rotation vectors (axis * angle)
// for increments and for the beam's local rotational deformation.
#include <Eigen/Core>
#include <Eigen/Geometry>

namespace coilsim {

using Vec3 = Eigen::Vector3d;
using Vec6 = Eigen::Matrix<double, 6, 1>;
using Mat3 = Eigen::Matrix3d;
using Mat6 = Eigen::Matrix<double, 6, 6>;
using Mat12 = Eigen::Matrix<double, 12, 12>;
using Quat = Eigen::Quaterniond;

// exp map: rotation vector -> unit quaternion. Exact for any angle; uses the
// series near zero so that tiny increments lose no precision.
Quat quatExp(const Vec3& rotationVector);

// log map: unit quaternion -> rotation vector with angle in [0, pi].
Vec3 quatLog(const Quat& q);

// The rotation taking unit vector `from` onto unit vector `to` with the least
// angle (no roll about either). Antiparallel input picks any perpendicular axis.
Quat minimalRotation(const Vec3& from, const Vec3& to);

// Skew-symmetric cross-product matrix: skew(a) * b == a.cross(b).
inline Mat3 skew(const Vec3& a) {
  Mat3 s;
  s << 0, -a.z(), a.y(), a.z(), 0, -a.x(), -a.y(), a.x(), 0;
  return s;
}

// Any unit vector orthogonal to the unit vector `v` (deterministic).
Vec3 anyPerpendicular(const Vec3& v);

// Cubic Hermite interpolation between samples p0, p1 with unit tangents t0,
// t1 a chord h apart, at s in [0, 1] (s outside extrapolates the cubic).
inline Vec3 hermite(const Vec3& p0, const Vec3& t0, const Vec3& p1, const Vec3& t1, double h, double s) {
  const double s2 = s * s, s3 = s2 * s;
  return (2 * s3 - 3 * s2 + 1) * p0 + (s3 - 2 * s2 + s) * h * t0 + (-2 * s3 + 3 * s2) * p1 + (s3 - s2) * h * t1;
}

}  // namespace coilsim
