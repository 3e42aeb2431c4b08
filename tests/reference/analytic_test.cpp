// Analytic checks of the reference rod in statics: small-deflection
// cantilevers, the large-deflection elastica, and convergence with the grid.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "test_support.h"

namespace refrod {
namespace {

using testing::fullyDeployed;
using testing::straightWire;

// Weight so small that the tip deflects by 1e-3 L: the geometrically
// nonlinear correction is O((w/L)^2) = 1e-6 relative, shear O(r^2/L^2) =
// 1e-5, so the 5e-4 tolerance is the discretisation error of 100 edges.
TEST(Cantilever, DistributedWeightSmallDeflection) {
  const double L = 0.05;
  RodSpec spec = straightWire(L, 100, 0.1);
  SolveReport rep;
  const Rod rod = fullyDeployed(spec, &rep);
  ASSERT_TRUE(rep.converged) << rep.message;
  const double w = -spec.coil.weight.z(), EI = spec.coil.EI1;
  const double expected = w * std::pow(L, 4) / (8 * EI);
  const double tip = -rod.x.back().z();
  std::printf("[ measured ] w L^4/8EI: relative error %.2e\n", tip / expected - 1);
  EXPECT_NEAR(tip / expected, 1.0, 5e-4) << "tip " << tip << " m, w L^4 / 8 EI = " << expected;
}

TEST(Cantilever, TipLoadSmallDeflection) {
  const double L = 0.05;
  RodSpec spec = straightWire(L, 100);
  spec.endForce = Vec3(0, 0, -1e-6);
  SolveReport rep;
  const Rod rod = fullyDeployed(spec, &rep);
  ASSERT_TRUE(rep.converged) << rep.message;
  const double expected = 1e-6 * std::pow(L, 3) / (3 * spec.coil.EI1);
  const double tip = -rod.x.back().z();
  std::printf("[ measured ] P L^3/3EI: relative error %.2e\n", tip / expected - 1);
  EXPECT_NEAR(tip / expected, 1.0, 5e-4) << "tip " << tip << " m, P L^3 / 3 EI = " << expected;
}

// The cantilever elastica with a dead tip load P normal to the clamp. With
// theta the slope angle, EI theta'^2 / 2 = P (sin theta0 - sin theta) gives
//   L sqrt(2P/EI) = int_0^theta0 dtheta / sqrt(sin theta0 - sin theta),
//   x = 2 sqrt(EI sin theta0 / 2P),  y = sqrt(EI/2P) int sin / sqrt(...),
// integrated here with theta = theta0 - t^2 (which removes the endpoint
// singularity) by composite Simpson, theta0 found by bisection.
struct Elastica {
  double x, y;  // tip over L
};
double simpson(double a, double b, int n, auto f) {
  const double h = (b - a) / n;
  double s = f(a) + f(b);
  for (int i = 1; i < n; ++i) s += (i % 2 ? 4 : 2) * f(a + i * h);
  return s * h / 3;
}
Elastica elastica(double alpha) {  // alpha = P L^2 / EI
  const auto integral = [](double th0, auto num) {
    return simpson(0.0, std::sqrt(th0), 2000, [&](double t) {
      const double th = th0 - t * t;
      const double den = t == 0 ? std::sqrt(std::cos(th0)) : std::sqrt((std::sin(th0) - std::sin(th)) / (t * t));
      return 2 * num(th) / den;
    });
  };
  double lo = 1e-9, hi = M_PI / 2 - 1e-9;
  for (int i = 0; i < 100; ++i) {
    const double mid = 0.5 * (lo + hi);
    (integral(mid, [](double) { return 1.0; }) < std::sqrt(2 * alpha) ? lo : hi) = mid;
  }
  const double th0 = 0.5 * (lo + hi), sc = 1 / std::sqrt(2 * alpha);
  return {2 * std::sqrt(std::sin(th0)) * sc, integral(th0, [](double th) { return std::sin(th); }) * sc};
}

TEST(Elastica, QuadratureReproducesBisshoppDrucker) {
  // Bisshopp & Drucker (1945): PL^2/EI = 1 deflects the tip by y/L = 0.3017
  // and draws it in by 0.0564 (x/L = 0.9436; an RK4 shooting of theta'' = -alpha cos theta agrees to 1e-6); small loads tend to the linear
  // y/L = alpha/3.
  const Elastica a = elastica(1.0), s = elastica(1e-3);
  EXPECT_NEAR(a.x, 0.9436, 2e-4);
  EXPECT_NEAR(a.y, 0.3017, 2e-4);
  EXPECT_NEAR(s.y / (1e-3 / 3), 1.0, 1e-5);
}

// Tip of the rod under P = alpha EI / L^2, over L.
Elastica simulated(double alpha, int edges, SolveReport* rep) {
  const double L = 0.05;
  RodSpec spec = straightWire(L, edges);
  spec.endForce = Vec3(0, 0, -alpha * spec.coil.EI1 / (L * L));
  const Rod rod = fullyDeployed(spec, rep);
  return {rod.x.back().x() / L, -rod.x.back().z() / L};
}

// Large deflection: the tip is within 1e-3 L of the elliptic-integral
// solution with 100 edges (measured about 1e-4 L; the bound leaves room for
// the O(h^2) discretisation, the shear and stretch compliance r^2/L^2 ~ 1e-5).
TEST(Elastica, LargeDeflectionTipLoad) {
  for (const double alpha : {1.0, 3.0, 5.0}) {
    SolveReport rep;
    const Elastica s = simulated(alpha, 100, &rep), e = elastica(alpha);
    ASSERT_TRUE(rep.converged) << rep.message;
    std::printf("[ measured ] elastica PL^2/EI = %g: tip error %.2e L\n", alpha, std::hypot(s.x - e.x, s.y - e.y));
    EXPECT_NEAR(s.x, e.x, 1e-3) << "alpha " << alpha;
    EXPECT_NEAR(s.y, e.y, 1e-3) << "alpha " << alpha;
  }
}

// The error falls with the grid, at about second order: from 10 to 40 edges
// it drops by more than 8 (16 at exact second order).
TEST(Convergence, ElasticaErrorFallsWithRefinement) {
  const Elastica e = elastica(3.0);
  double err[3];
  const int n[3] = {10, 20, 40};
  for (int i = 0; i < 3; ++i) {
    SolveReport rep;
    const Elastica s = simulated(3.0, n[i], &rep);
    ASSERT_TRUE(rep.converged) << rep.message;
    err[i] = std::hypot(s.x - e.x, s.y - e.y);
  }
  std::printf("[ measured ] elastica error with 10, 20, 40 edges: %.2e %.2e %.2e L\n", err[0], err[1], err[2]);
  EXPECT_LT(err[1], err[0]);
  EXPECT_LT(err[2], err[1]);
  EXPECT_LT(err[2], err[0] / 8) << err[0] << " " << err[1] << " " << err[2];
}

}  // namespace
}  // namespace refrod
