#pragma once
// Independent reference for large deflection: the planar elastica of an
// inextensible, unshearable cantilever (Euler 1744; Bisshopp & Drucker 1945)
// clamped at s = 0 along +x and loaded at its free end s = L by a dead force P
// in -z. With theta(s) the downward angle of the tangent and L = 1,
//   theta'' = -alpha cos(theta),  theta(0) = 0,  theta'(1) = 0,  alpha = P L^2 / (E I),
//   x' = cos(theta),  w' = sin(theta)  (w = downward deflection).
// Solved here by shooting on the root curvature theta'(0) (bisection) with a
// classical fourth-order Runge-Kutta march; nothing from coilsim is used.
#include <array>
#include <cmath>
#include <stdexcept>

namespace coilsim::test {

struct ElasticaTip {
  double horizontal = 0;     // u / L = 1 - x_tip / L (shortening)
  double vertical = 0;       // w / L (downward)
  double rotation = 0;       // tip angle, rad
  double rootCurvature = 0;  // theta'(0) L
};

namespace detail {
using ElasticaY = std::array<double, 4>;  // theta, theta', x, w

inline ElasticaY elasticaRate(const ElasticaY& y, double alpha) {
  return {y[1], -alpha * std::cos(y[0]), std::cos(y[0]), std::sin(y[0])};
}

// March from s = 0 to s = 1 with the given root curvature.
inline ElasticaY shootElastica(double alpha, double rootCurvature, int steps) {
  ElasticaY y{0.0, rootCurvature, 0.0, 0.0};
  const double h = 1.0 / steps;
  auto axpy = [](const ElasticaY& a, double s, const ElasticaY& b) {
    ElasticaY r;
    for (int i = 0; i < 4; ++i) r[i] = a[i] + s * b[i];
    return r;
  };
  for (int k = 0; k < steps; ++k) {
    const ElasticaY k1 = elasticaRate(y, alpha);
    const ElasticaY k2 = elasticaRate(axpy(y, 0.5 * h, k1), alpha);
    const ElasticaY k3 = elasticaRate(axpy(y, 0.5 * h, k2), alpha);
    const ElasticaY k4 = elasticaRate(axpy(y, h, k3), alpha);
    for (int i = 0; i < 4; ++i) y[i] += h / 6.0 * (k1[i] + 2 * k2[i] + 2 * k3[i] + k4[i]);
  }
  return y;
}
}  // namespace detail

// Tip of the elastica for load parameter alpha = P L^2 / EI (0 < alpha <~ 20).
// The root curvature equals alpha x_tip / L <= alpha, and theta'(1) changes
// sign between 0 and alpha, so bisection on [0, alpha] brackets the
// equilibrium. RK4 with `steps` steps has a truncation error ~ steps^-4.
// Throws std::runtime_error if the bracket does not hold.
inline ElasticaTip solveElastica(double alpha, int steps = 2000) {
  double lo = 0.0, hi = alpha;
  auto endCurvature = [&](double k0) { return detail::shootElastica(alpha, k0, steps)[1]; };
  if (!(endCurvature(lo) < 0 && endCurvature(hi) > 0))
    throw std::runtime_error("elastica shooting: root curvature not bracketed");
  for (int it = 0; it < 200 && hi - lo > 1e-15 * alpha; ++it) {
    const double mid = 0.5 * (lo + hi);
    (endCurvature(mid) < 0 ? lo : hi) = mid;
  }
  const double k0 = 0.5 * (lo + hi);
  const auto y = detail::shootElastica(alpha, k0, steps);
  return {1.0 - y[2], y[3], y[0], k0};
}

}  // namespace coilsim::test
