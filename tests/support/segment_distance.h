#pragma once
// The tests' own closest distance between two segments, an independent
// reference for the contact code's (physics/contact/geometry.cpp).
#include <algorithm>

#include "physics/math.h"

namespace coilsim::test {

// Distance between segments p0-p1 and q0-q1 (Ericson, Real-Time Collision
// Detection 5.1.9, clamped; the textbook form, without the contact code's
// handling of near-parallel pairs).
inline double segmentDistance(const Vec3& p0, const Vec3& p1, const Vec3& q0, const Vec3& q1) {
  const Vec3 d1 = p1 - p0, d2 = q1 - q0, r = p0 - q0;
  const double a = d1.squaredNorm(), e = d2.squaredNorm(), f = d2.dot(r), c = d1.dot(r), b = d1.dot(d2);
  const double denom = a * e - b * b;
  double s = denom > 1e-30 ? std::clamp((b * f - c * e) / denom, 0.0, 1.0) : 0.0;
  double t = (b * s + f) / e;
  if (t < 0) {
    t = 0;
    s = std::clamp(-c / a, 0.0, 1.0);
  } else if (t > 1) {
    t = 1;
    s = std::clamp((b - c) / a, 0.0, 1.0);
  }
  return (p0 + s * d1 - (q0 + t * d2)).norm();
}

}  // namespace coilsim::test
