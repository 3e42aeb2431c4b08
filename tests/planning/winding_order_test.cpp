// The winding order W (planning/winding_order.h) against its closed-form
// values: 1 for concentric turns wound one way (a planar spool, joined by
// radial steps that wind about nothing), (1 - k^2) / (1 + k^2) for a turn of
// radius 1 one way and one of radius k the other, 0 for equal turns both
// ways, and of order 1 / sqrt(N) for an isotropic random walk of N steps
// (central limit).
#include "planning/winding_order.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace coilsim::planning {
namespace {

// A circle of radius `rho` at height `z` on the axis `n` through `c`, cut
// into `k` chords, wound `sense` (+1 right-handed about n).
void appendCircle(std::vector<Vec3>& p, const Vec3& c, const Vec3& n, double rho, double z, int k, double sense) {
  const Vec3 u = n.unitOrthogonal(), v = n.cross(u);
  for (int i = 0; i <= k; ++i) {
    const double a = sense * 2 * M_PI * i / k;
    p.push_back(c + z * n + rho * (std::cos(a) * u + std::sin(a) * v));
  }
}

TEST(WindingOrder, ConcentricTurnsWoundOneWayGiveOne) {
  const Vec3 c(0.3, -0.2, 0.1), n = Vec3(1, 2, 2).normalized();
  std::vector<Vec3> p;
  // Radii and chord counts differ; every turn starts on the same ray, so the
  // steps between turns are radial.
  appendCircle(p, c, n, 1.0, 0.0, 7, 1);
  appendCircle(p, c, n, 0.6, 0.0, 40, 1);
  appendCircle(p, c, n, 0.9, 0.0, 13, 1);
  const WindingOrder w = windingOrder(p, c);
  EXPECT_NEAR(w.order, 1.0, 1e-12);
  EXPECT_NEAR(w.axis.dot(n), 1.0, 1e-12);
}

TEST(WindingOrder, TurnsWoundBothWaysCancelByTheirWinding) {
  // Turn i winds rho_i^2 k sin(2 pi / k) with k chords: with the same k the
  // ratio is that of rho^2, (1 - 0.25) / (1 + 0.25) = 0.6.
  std::vector<Vec3> p;
  appendCircle(p, Vec3::Zero(), Vec3::UnitZ(), 1.0, 0.0, 24, 1);
  appendCircle(p, Vec3::Zero(), Vec3::UnitZ(), 0.5, 0.0, 24, -1);
  EXPECT_NEAR(windingOrder(p, Vec3::Zero()).order, 0.6, 1e-12);
  std::vector<Vec3> q;
  appendCircle(q, Vec3::Zero(), Vec3::UnitZ(), 1.0, 0.0, 24, 1);
  appendCircle(q, Vec3::Zero(), Vec3::UnitZ(), 1.0, 0.0, 24, -1);
  EXPECT_EQ(windingOrder(q, Vec3::Zero()).order, 0.0);
}

TEST(WindingOrder, AnIsotropicRandomWalkHasNoOrder) {
  // N unit steps of random direction, kept in a unit ball by reflection at
  // its centre: |J| grows as sqrt(N), the lever sum as N, so W ~ 1 / sqrt(N)
  // (about 0.007 here); 0.05 is seven times that.
  std::mt19937 rng(16);
  std::normal_distribution<double> g;
  std::vector<Vec3> p{Vec3::Zero()};
  for (int i = 0; i < 20000; ++i) {
    Vec3 next = p.back() + 0.05 * Vec3(g(rng), g(rng), g(rng)).normalized();
    if (next.norm() > 1) next = p.back() - (next - p.back());
    p.push_back(next);
  }
  EXPECT_LT(windingOrder(p, Vec3::Zero()).order, 0.05);
}

TEST(WindingOrder, NoLineNoOrder) {
  EXPECT_EQ(windingOrder({}, Vec3::Zero()).order, 0.0);
  EXPECT_EQ(windingOrder({Vec3::UnitX(), Vec3::UnitX()}, Vec3::Zero()).order, 0.0);
}

}  // namespace
}  // namespace coilsim::planning
