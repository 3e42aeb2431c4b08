// Static equilibria with contacts (src/physics/statics.cpp with the static
// path of src/physics/contact/response.cpp).
// Reference: a heavy cantilever (load w per length, stiffness EI) clamped
// horizontally a height delta above a rigid flat support lies on it beyond
// a touchdown distance a from the clamp, where deflection delta, slope and
// moment (the support is flat) match those of the resting part: on [0, a]
//   y(x) = w x^4 / (24 EI) - w a x^3 / (9 EI) + w a^2 x^2 / (12 EI),
// and y(a) = delta gives a = (72 EI delta / w)^(1/4) (Euler-Bernoulli; the
// same derivation as for a heavy strip lifted off a table, e.g. Timoshenko
// & Gere, Mechanics of Materials, on beams with a contact edge). Here the
// support is a second wire held straight under the cantilever: the
// cantilever's centre line comes to rest at the contact distance r1 + r2
// from it.
#include <gtest/gtest.h>

#include <cmath>

#include "support/rod_models.h"

namespace coilsim::test {
namespace {

constexpr double kRadius = 0.05e-3, kLength = 0.04, kHeight = 0.4e-3, kGravity = 9.81;

struct Lying {
  Model model;
  State state;
  StaticReport report;
};

// The cantilever (rod 0, clamped at x = 0) over the held support (rod 1).
Lying lieDown(bool contact) {
  const Section s = circularSection(kRadius, kPlatinumPoisson);
  const int beams = 80;
  RodDef arm = clamped(straightRod(kLength, beams, platinum(), s));
  arm.placement.position = Vec3(0, 0, kHeight);
  RodDef support = straightRod(kLength + 2e-3, 42, platinum(), s);
  support.placement.position = Vec3(-1e-3, 0, 0);
  for (int i = 0; i <= 42; ++i) support.constraints.push_back({i, kAllDofs});
  ModelDef def = modelOf({arm, support}, {"gravity"}, Vec3(0, 0, -kGravity));
  if (contact) def.effects.push_back(EffectRegistry::global().use("rod_contact"));
  Lying out{compileModel(def), {}, {}};
  out.state = makeState(out.model);
  StaticOptions o = tightStatic(8);
  o.positionTolerance = 1e-12;
  out.report = solveStatic(out.model, out.state, o);
  return out;
}

TEST(StaticsContactTest, HeavyCantileverLiesOnAFlatSupportBeyondTheTouchdownDistance) {
  const Lying l = lieDown(true);
  ASSERT_TRUE(l.report.converged()) << l.report.message();
  const RodModel& rm = l.model.rods[0];
  const double ei = rm.material.youngModulus * rm.section.iy;
  const double w = rm.material.density * rm.section.area * kGravity;
  const double delta = kHeight - 2 * kRadius;
  const double a = std::pow(72 * ei * delta / w, 0.25);
  ASSERT_LT(a, 0.8 * kLength) << "the arm must be long enough to lie on the support";
  const auto y = [&](double x) {
    return w * std::pow(x, 4) / (24 * ei) - w * a * std::pow(x, 3) / (9 * ei) + w * a * a * x * x / (12 * ei);
  };
  double lifted = 0, resting = 0;
  int onSupport = 0;
  for (const Vec3& x : l.state.rods[0].x) {
    const double deflection = kHeight - x.z();
    if (x.x() <= a) lifted = std::max(lifted, std::abs(deflection - y(x.x())));
    else resting = std::max(resting, std::abs(deflection - delta)), ++onSupport;
  }
  std::printf("[ measured ] touchdown a = %.2f mm; largest deflection error %.2f um lifted, %.2f um resting on the "
              "support (%d nodes; delta = %.0f um)\n",
              a * 1e3, lifted * 1e6, resting * 1e6, onSupport, delta * 1e6);
  // The lifted part: 80 beams of 0.5 mm resolve the quartic to well under
  // 1 % of delta; the touchdown is where the penalty's point contacts
  // (one per segment pair) stand in for a continuous support.
  EXPECT_LT(lifted, 0.01 * delta);
  // The resting part sits at the contact distance: the penalty's depth
  // under w L_e (nanometres) and the static smoothing's float (under 1 um).
  EXPECT_LT(resting, 2e-6);
  EXPECT_GT(onSupport, 10);
}

// The control: without the contact the same arm sinks through the support
// (a free heavy cantilever's tip falls w L^4 / (8 EI), far below delta).
TEST(StaticsContactTest, WithoutContactTheArmSinksThroughTheSupport) {
  const Lying l = lieDown(false);
  ASSERT_TRUE(l.report.converged()) << l.report.message();
  EXPECT_LT(l.state.rods[0].x.back().z(), -kHeight);
}

}  // namespace
}  // namespace coilsim::test
