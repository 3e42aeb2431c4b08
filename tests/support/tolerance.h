#pragma once
// Tolerances that carry their reason, and assertions that print the measured
// error next to the bound. Every numerical comparison in the physics tests
// goes through these helpers, so no bare number hides in an EXPECT_NEAR and a
// failure says why the bound was what it was.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>
#include <string>

#include "physics/math.h"

namespace coilsim::test {

// A bound on an error, with the one-line argument that sets it.
struct Tolerance {
  double bound = 0;
  std::string why;
};

inline constexpr double kEpsilon = std::numeric_limits<double>::epsilon();

// Round-off of quantities of size `scale` after `operations` dependent
// floating point operations (each adds at most one epsilon of the scale).
inline Tolerance roundoff(double scale, double operations, const std::string& what) {
  return {scale * operations * kEpsilon, "round-off: " + what};
}

inline double relativeError(double actual, double expected) {
  return std::abs(actual - expected) / std::abs(expected);
}

namespace detail {
inline ::testing::AssertionResult verdict(const std::string& what, double error, const Tolerance& tol,
                                          const std::string& detail) {
  // One line per comparison so CI logs double as a table of measured errors.
  std::printf("[ measured ] %-58s error %.3e  bound %.3e\n", what.c_str(), error, tol.bound);
  if (std::isfinite(error) && error <= tol.bound) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << what << ": error " << error << " exceeds " << tol.bound << " ("
                                       << tol.why << ")" << detail;
}
}  // namespace detail

// |actual - expected| <= bound.
inline ::testing::AssertionResult nearAbs(const std::string& what, double actual, double expected,
                                          const Tolerance& tol) {
  std::ostringstream d;
  d.precision(12);
  d << "; actual " << actual << ", expected " << expected;
  return detail::verdict(what, std::abs(actual - expected), tol, d.str());
}

// |actual - expected| / |expected| <= bound.
inline ::testing::AssertionResult nearRel(const std::string& what, double actual, double expected,
                                          const Tolerance& tol) {
  std::ostringstream d;
  d.precision(12);
  d << "; actual " << actual << ", expected " << expected;
  return detail::verdict(what + " (relative)", relativeError(actual, expected), tol, d.str());
}

// |actual - expected| (Euclidean) <= bound.
inline ::testing::AssertionResult nearVec(const std::string& what, const Vec3& actual, const Vec3& expected,
                                          const Tolerance& tol) {
  std::ostringstream d;
  d.precision(10);
  d << "; actual (" << actual.transpose() << "), expected (" << expected.transpose() << ")";
  return detail::verdict(what, (actual - expected).norm(), tol, d.str());
}

// value <= bound, for quantities that should vanish (residuals, drifts).
inline ::testing::AssertionResult small(const std::string& what, double value, const Tolerance& tol) {
  return detail::verdict(what, std::abs(value), tol, "");
}

// Angle of the rotation taking frame a to frame b, in [0, pi].
inline double angleBetween(const Quat& a, const Quat& b) {
  return a.angularDistance(b);
}

}  // namespace coilsim::test
