#pragma once
// Free vibration of a clamped-free Euler-Bernoulli beam (e.g. Rao, Vibration
// of Continuous Systems, 2nd ed., sec. 11.5; Blevins, Formulas for Natural
// Frequency and Mode Shape, table 8-1): frequency equation
//   cos(beta L) cosh(beta L) + 1 = 0,  omega_k = (beta_k L)^2 sqrt(E I / (rho A L^4)),
// beta_1 L = 1.87510, beta_2 L = 4.69409, and mode shapes
//   phi(x) = cosh bx - cos bx - sigma (sinh bx - sin bx),
//   sigma = (cosh bL + cos bL) / (sinh bL + sin bL).
#include <cmath>

namespace coilsim::test {

// Published roots beta_k L (Blevins table 8-1), to the digits quoted there.
inline constexpr double kCantileverBetaL[] = {1.87510407, 4.69409113};

// Root k (1-based) of cos x cosh x + 1 = 0 by bisection near (2k - 1) pi / 2.
inline double cantileverRoot(int k) {
  auto f = [](double x) { return std::cos(x) * std::cosh(x) + 1.0; };
  double lo = (k - 1) * M_PI + 0.1, hi = k * M_PI;  // one sign change per interval for k >= 1
  if (k == 1) lo = 1.0, hi = 2.5;
  for (int it = 0; it < 200; ++it) {
    const double mid = 0.5 * (lo + hi);
    ((f(lo) < 0) == (f(mid) < 0) ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

// omega_k of a uniform cantilever (rad/s).
inline double cantileverOmega(double betaL, double length, double ei, double massPerLength) {
  return betaL * betaL * std::sqrt(ei / (massPerLength * std::pow(length, 4)));
}

struct ModeShape {
  double betaL, length, sigma;
  explicit ModeShape(double bL, double L)
      : betaL(bL), length(L), sigma((std::cosh(bL) + std::cos(bL)) / (std::sinh(bL) + std::sin(bL))) {}
  // Deflection at x, normalised so that the tip value is 2 (its classical value).
  double value(double x) const {
    const double b = betaL / length * x;
    return std::cosh(b) - std::cos(b) - sigma * (std::sinh(b) - std::sin(b));
  }
  // Slope d phi / dx.
  double slope(double x) const {
    const double k = betaL / length, b = k * x;
    return k * (std::sinh(b) + std::sin(b) - sigma * (std::cosh(b) - std::cos(b)));
  }
};

}  // namespace coilsim::test
