// Each physical term of the reference rod alone: buoyancy, the compliant
// catheter tube, self-contact.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "test_support.h"

namespace refrod {
namespace {

// Small deflections are linear in the load, so water scales a cantilever's
// sag by the net weight 1 - rho_f / rho exactly (to the solver tolerance).
TEST(Effects, BuoyancyScalesTheWeight) {
  const double L = 0.05;
  RodSpec air = testing::straightWire(L, 50);
  RodSpec water = air;
  air.coil = wireSection(0.15e-3, 6e9, 0.39, 21450, 0, Vec3(0, 0, -0.1));
  water.coil = wireSection(0.15e-3, 6e9, 0.39, 21450, 1000, Vec3(0, 0, -0.1));
  Rod a = initialRod(air, L, 0), w = initialRod(water, L, 0);
  ASSERT_TRUE(minimise(air, a).converged);
  ASSERT_TRUE(minimise(water, w).converged);
  std::printf("[ measured ] water/air sag ratio minus (1 - rho_f/rho): %.2e\n",
              w.x.back().z() / a.x.back().z() - (1 - 1000.0 / 21450));
  EXPECT_NEAR(w.x.back().z() / a.x.back().z(), 1 - 1000.0 / 21450, 1e-5);
}

// A straight coil a beyond a free tube b clamped at its base, end load P:
// the stepped cantilever, delta = P ((a+b)^3 - a^3) / (3 EI_tube+coil) +
// P a^3 / (3 EI_coil) (unit-load method). Linear regime (delta ~ 1e-3 L);
// 1e-3 covers the two grids (h = 0.25 mm on the coil, 0.5 mm on the tube).
TEST(Effects, CompliantTubeIsASteppedCantilever) {
  const double a = 0.02, b = 0.01;
  RodSpec spec = testing::straightWire(0.03, 120);
  spec.tubeLength = b;
  spec.tubeEdges = 20;
  spec.tube = tubeSection(0.3e-3, 0.21e-3, 1e9, 0.4, 1200, spec.coil, 0.15e-3, 21450, 0, Vec3::Zero());
  const double P = 1e-6;
  spec.endForce = Vec3(0, 0, -P);
  Rod rod = initialRod(spec, a, 0);
  const SolveReport rep = minimise(spec, rod);
  ASSERT_TRUE(rep.converged) << rep.message;
  const double L = a + b;
  const double expected = P * (L * L * L - a * a * a) / (3 * spec.tube.EI1) + P * a * a * a / (3 * spec.coil.EI1);
  std::printf("[ measured ] stepped cantilever: relative error %.2e\n", -rod.x.back().z() / expected - 1);
  EXPECT_NEAR(-rod.x.back().z() / expected, 1.0, 1e-3);
  // The exit (the tube's end, node at s = 0) moved: the declared tip is not where the coil leaves.
  int J = 0;
  while (rod.key[J + 1] < 0) ++J;
  EXPECT_LT(rod.x[J].z(), -1e-3 * expected);
}

// A helix wound tighter than the wire (pitch 0.12 mm, wire diameter 0.2 mm):
// without contact its loops interpenetrate at the rest pitch; with it the
// loops sit a wire diameter apart, within the penalty's 0.02 mm.
double loopGap(bool contact) {
  RodSpec s;
  const double D = 4e-3, p = 0.12e-3;
  s.length = 2.5 * std::hypot(M_PI * D, p);
  s.coilEdges = 100;
  s.coil = wireSection(0.1e-3, 6e9, 0.39, 21450, 0, Vec3::Zero());
  s.restDarboux = testing::helixDarboux(D, p, true);
  s.contact = contact;
  SolveReport rep;
  const Rod rod = deployStatic(s, s.length, 0, s.h(), &rep);
  EXPECT_TRUE(rep.converged) << rep.message;
  // Smallest distance between nodes about one turn apart.
  const double turn = std::hypot(M_PI * D, p);
  double d = 1;
  for (int i = 0; i < rod.nodes(); ++i)
    for (int j = i + 1; j < rod.nodes(); ++j)
      if (std::abs(rod.s[j] - rod.s[i] - turn) < 0.1 * turn) d = std::min(d, (rod.x[j] - rod.x[i]).norm());
  return d;
}

TEST(Effects, SelfContactKeepsLoopsAWireDiameterApart) {
  const double free = loopGap(false), g = loopGap(true);
  std::printf("[ measured ] loop distance one turn apart: %.4f mm without contact, %.4f mm with\n", free * 1e3, g * 1e3);
  EXPECT_LT(free, 0.13e-3);
  EXPECT_GT(g, 0.18e-3);
  EXPECT_LT(g, 0.205e-3);
}

}  // namespace
}  // namespace refrod
