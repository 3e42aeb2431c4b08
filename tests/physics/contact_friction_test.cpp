// Wall friction (physics/contact/response.h, effects/wall_contact.cpp)
// against Coulomb's law on an inclined plane: a straight rod lying on a plane
// whose slope is raised slowly (gravity turned, the same thing) to angle a
// sticks while tan a < mu_s and slides above with acceleration
// g (sin a - mu_d cos a) (a block on an incline: the rod lies straight along
// the slope, so it moves as one rigid body). Each test runs under both
// wall laws: the penalty (rigid = 0) and a constraint per node (rigid = 1),
// whose Coulomb cap is the multiplier of the step's own solve.
#include <gtest/gtest.h>

#include <cmath>

#include "physics/contact/detect.h"
#include "physics/integrator.h"
#include "support/meshes.h"
#include "support/rod_models.h"

namespace coilsim {
namespace {

constexpr double kG = 9.81, kMuStatic = 0.4, kMuDynamic = 0.3, kRadius = 0.15e-3;

struct Incline {
  Model model;
  State state;
};

// A 10 mm rod along +x on the plane z = 0; gravity tilted by `angle` about y
// so the slope runs down towards +x (the same as tilting the plane); the
// wall a penalty or (rigid) constraints.
Incline incline(double angle, bool rigid) {
  RodDef rod = test::straightRod(0.01, 20, test::platinum(), circularSection(kRadius, test::kPlatinumPoisson));
  // Placed already pressed in by its weight (w cos a / k per length), so the
  // wall carries it from the first step: dropped from the contact surface it
  // would bounce off the penalty and start sliding, and between atan(mu_d)
  // and atan(mu_s) a sliding rod rightly goes on sliding.
  const double weightPerLength = test::platinum().density * M_PI * kRadius * kRadius * kG * std::cos(angle);
  const double stiffness = EffectRegistry::global().use("wall_contact").value("stiffness_n_mm2");
  rod.placement.position = Vec3(-0.005, 0, (1 + kWallSkin) * kRadius - weightPerLength / stiffness);
  ModelDef def = test::modelOf({rod}, {"gravity"}, kG * Vec3(std::sin(angle), 0, -std::cos(angle)));
  def.damping.massCoeff = 0;  // no Rayleigh drag: friction alone must hold or slow the rod
  def.damping.stiffnessCoeff = 0;
  def.effects.push_back(EffectRegistry::global().use("wall_contact"));
  def.effects.back().set("friction_static", kMuStatic);
  def.effects.back().set("friction_dynamic", kMuDynamic);
  def.effects.back().set("rigid", rigid ? 1.0 : 0.0);
  def.obstacles.push_back(test::obstacleOf(test::plane(Vec3::Zero(), -Vec3::UnitZ(), 0.5, 12)));
  Incline r{compileModel(def), {}};
  r.state = makeState(r.model);
  return r;
}

double meanX(const RodState& r) {
  double s = 0;
  for (int i = 0; i < r.activeNodes; ++i) s += r.x[i].x();
  return s / r.activeNodes;
}

double meanVx(const RodState& r) {
  double s = 0;
  for (int i = 0; i < r.activeNodes; ++i) s += r.v[i].x();
  return s / r.activeNodes;
}

// Raises the slope from 0 to `angle` over 0.3 s (a plane tilted by hand),
// then holds it for `holdSteps` steps.
void tiltTo(Incline& s, double angle, int holdSteps) {
  const int ramp = 300;
  for (int i = 1; i <= ramp + holdSteps; ++i) {
    const double a = angle * std::min(1.0, double(i) / ramp);
    s.model.gravity = kG * Vec3(std::sin(a), 0, -std::cos(a));
    ASSERT_TRUE(step(s.model, s.state).ok()) << "step " << i;
  }
}

// The wall law under test: false the penalty, true the constraint.
class ContactFrictionTest : public ::testing::TestWithParam<bool> {};

TEST_P(ContactFrictionTest, RodSticksBelowTheStaticAngle) {
  // 15 deg is below atan(mu_d) = 16.7 deg, 20 deg between it and atan(mu_s) =
  // 21.8 deg: the rod must stay (static coefficient), not creep at the dynamic one.
  for (const double degrees : {15.0, 20.0}) {
    Incline s = incline(0.0, GetParam());
    const double x0 = meanX(s.state.rods[0]);
    tiltTo(s, degrees * M_PI / 180, 500);
    const double moved = meanX(s.state.rods[0]) - x0;
    // Sliding at g (sin a - mu_d cos a) would be metres per second squared;
    // the regularised stick spring allows micrometres of creep at most.
    std::printf("[ measured ] %.0f deg: moved %.3g um in 0.8 s while sticking\n", degrees, moved * 1e6);
    EXPECT_LT(std::abs(moved), 2e-6) << degrees << " deg";
  }
}

TEST_P(ContactFrictionTest, RodSlidesAboveTheStaticAngleWithCoulombsAcceleration) {
  for (const double degrees : {25.0, 35.0}) {
    const double a = degrees * M_PI / 180;
    Incline s = incline(0.0, GetParam());
    tiltTo(s, a, 100);
    const double t1 = s.state.time, v1 = meanVx(s.state.rods[0]);
    for (int i = 0; i < 150; ++i) ASSERT_TRUE(step(s.model, s.state).ok());
    const double measured = (meanVx(s.state.rods[0]) - v1) / (s.state.time - t1);
    const double expected = kG * (std::sin(a) - kMuDynamic * std::cos(a));
    std::printf("[ measured ] %.0f deg: acceleration %.4f m/s2, Coulomb %.4f m/s2 (%.2f %%)\n", degrees, measured,
                expected, 100 * (measured - expected) / expected);
    EXPECT_NEAR(measured, expected, 0.03 * expected) << degrees << " deg";
  }
}

TEST_P(ContactFrictionTest, WithoutFrictionTheRodAcceleratesAtGSinA) {
  const double a = 10 * M_PI / 180;
  Incline s = incline(a, GetParam());
  s.model.effects.back().set("friction_static", 0);
  s.model.effects.back().set("friction_dynamic", 0);
  for (int i = 0; i < 50; ++i) ASSERT_TRUE(step(s.model, s.state).ok());
  const double t1 = s.state.time, v1 = meanVx(s.state.rods[0]);
  for (int i = 0; i < 200; ++i) ASSERT_TRUE(step(s.model, s.state).ok());
  const double measured = (meanVx(s.state.rods[0]) - v1) / (s.state.time - t1);
  EXPECT_NEAR(measured, kG * std::sin(a), 0.01 * kG * std::sin(a));
}

INSTANTIATE_TEST_SUITE_P(WallLaw, ContactFrictionTest, ::testing::Values(false, true),
                         [](const ::testing::TestParamInfo<bool>& i) { return i.param ? "Constraint" : "Penalty"; });

}  // namespace
}  // namespace coilsim
