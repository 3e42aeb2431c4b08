// Comparison of a simulated stage with a measured centre line: where the
// catheter tip lies on the measured curve. Reference: the curve itself (a
// simulation sampled on the measured curve must agree with it).
#include "validation/compare.h"

#include <gtest/gtest.h>

#include <cmath>

namespace coilsim::validation {
namespace {

// Two flat turns of a 4 mm radius loop leaving the tip along x and curling
// towards z: the second turn passes through the tip again, as the loops of
// a coil without self-contact do when they sink onto each other.
Vec3 loop(double s) {
  const double R = 4e-3;
  return {R * std::sin(s / R), 0, R * (1 - std::cos(s / R))};
}

TEST(Comparison, TipIsFoundAtTheStartNotOnALoopPassingOverIt) {
  const double length = 2 * 2 * M_PI * 4e-3;
  Measurement m;
  m.tip.direction = Vec3::UnitX();
  m.tip.normal = Vec3::UnitZ();
  Stage st;
  st.deployed = length;
  st.pointSigma = 0.01e-3;
  for (double s = 0; s <= length + 1e-9; s += 0.5e-3) st.centerline.push_back(loop(s));
  // The first measured point 30 um behind the tip (noise), so the tip is
  // projected onto the curve; the second turn passes through it exactly.
  st.centerline.front() = Vec3(-30e-6, 0, 0);
  m.stages.push_back(st);
  StageSim sim;
  for (double s = 0; s <= length + 1e-9; s += 1e-3) sim.x.push_back(loop(s)), sim.s.push_back(s);
  const Comparison cmp(m);
  const StageComparison c = cmp.compare({sim}).front();
  ASSERT_TRUE(c.ok()) << c.message();
  EXPECT_NEAR(c.arcScale, 1.0, 2e-3);
  double worst = 0;
  for (size_t i = 0; i < c.sim.size(); ++i) worst = std::max(worst, (c.sim[i] - c.meas[i]).norm());
  // 0.1 mm: the displaced first point bends the spline's start by tens of
  // um; entered on the second turn, the curves are 23 mm apart.
  EXPECT_LT(worst, 0.1e-3) << "the measured curve was entered at the wrong arc length";
}

}  // namespace
}  // namespace coilsim::validation
