// Sleeping rods (physics/sleep.cpp). References: the rule as docs/contact.md
// states it (a free rod whose nodes all stay slower than the speed for the
// stated time sleeps; a sleeping rod pressed by awake rods with more than
// the wake force wakes), the pose of a frozen rod (bit for bit), the contact
// distance r1 + r2 (a sleeping rod is as solid as an awake one: at most 10 %
// of it pressed in, as tests/physics/contact_rod_test.cpp holds between
// awake coils), and runs without sleeping.
#include <gtest/gtest.h>

#include <cmath>

#include "physics/contact/geometry.h"
#include "physics/integrator.h"
#include "physics/sleep.h"
#include "support/meshes.h"
#include "support/rod_models.h"

namespace coilsim {
namespace {

constexpr double kRadius = 0.127e-3;  // a 0.010 inch wire
constexpr double kLength = 5e-3;
constexpr int kBeams = 10;
constexpr double kDt = 1e-3;

RodDef wire(const Vec3& at, const Vec3& along, const Vec3& normal) {
  RodDef r = test::straightRod(kLength, kBeams, test::platinum(), circularSection(kRadius, test::kPlatinumPoisson));
  r.placement = {at, along, normal};
  return r;
}

SleepSettings settings(double speedMmS, double timeS, double wakeForceMn) {
  return sleepSettings(true, std::vector<double>{speedMmS * 1e-3, timeS, wakeForceMn * 1e-3});
}

// A straight wire dropped from 20 um onto a floor, under gravity, damped.
Model wireOnFloor(const SleepSettings& sleep) {
  ModelDef def = test::modelOf({wire(Vec3(-0.5 * kLength, 0, 1.2 * kRadius), Vec3::UnitX(), Vec3::UnitY())},
                               {"gravity", "wall_contact"}, Vec3(0, 0, -9.81));
  def.obstacles.push_back(test::obstacleOf(test::plane(Vec3::Zero(), Vec3(0, 0, -1), 4e-3, 8)));
  def.damping.massCoeff = 20;
  def.timeStep = kDt;
  def.sleep = sleep;
  return compileModel(def);
}

// Whether every node of r is slower than `speed`, rotation counted at half the segment.
bool stillAt(const RodState& r, double speed) {
  for (int i = 0; i < r.activeNodes; ++i)
    if (r.v[i].norm() >= speed || r.w[i].norm() * 0.5 * kLength / kBeams >= speed) return false;
  return true;
}

TEST(Sleep, ARodAtRestOnAWallFallsAsleepAfterTheStatedTimeAndStaysBitIdentical) {
  const SleepSettings sleep = settings(0.5, 0.05, 0.5);
  const Model model = wireOnFloor(sleep);
  State s = makeState(model);
  RodState& r = s.rods[0];
  int stillSteps = 0, steps = 0;
  for (; steps < 2000 && !r.asleep; ++steps) {
    ASSERT_TRUE(step(model, s).ok()) << s.warnings.back();
    stillSteps = stillAt(r, sleep.speed) ? stillSteps + 1 : 0;
    // Asleep exactly when it has been still for the stated time, not before.
    EXPECT_EQ(r.asleep, stillSteps >= int(std::lround(sleep.time / kDt))) << "step " << steps;
  }
  ASSERT_TRUE(r.asleep) << "the wire never came to rest";
  EXPECT_GT(steps, int(sleep.time / kDt));
  EXPECT_FALSE(r.contact.wall.empty()) << "the wire should rest on the floor";
  const std::vector<Vec3> x = r.x;
  const std::vector<Quat> q = r.q;
  const size_t wallContacts = r.contact.wall.size();
  ASSERT_TRUE(test::run(model, s, 300));
  EXPECT_TRUE(r.asleep);
  for (int i = 0; i < r.activeNodes; ++i) {
    EXPECT_EQ(r.x[i], x[i]) << i;
    EXPECT_EQ(r.q[i].coeffs(), q[i].coeffs()) << i;
    EXPECT_EQ(r.v[i], Vec3::Zero());
    EXPECT_EQ(r.w[i], Vec3::Zero());
  }
  EXPECT_EQ(r.contact.wall.size(), wallContacts) << "its wall contacts are kept, not detected again";
  EXPECT_EQ(s.sleep.sleeps, 1);
  EXPECT_EQ(s.sleep.wakes, 0);
}

TEST(Sleep, ARunWhoseRodsNeverSleepIsBitIdenticalToOneWithoutSleeping) {
  // Speed 0: nothing is slower than that, so the rule runs and never acts.
  const Model on = wireOnFloor(settings(0.0, 0.05, 0.5)), off = wireOnFloor(SleepSettings{});
  State a = makeState(on), b = makeState(off);
  ASSERT_TRUE(test::run(on, a, 400));
  ASSERT_TRUE(test::run(off, b, 400));
  EXPECT_FALSE(a.rods[0].asleep);
  for (int i = 0; i < a.rods[0].activeNodes; ++i) {
    EXPECT_EQ(a.rods[0].x[i], b.rods[0].x[i]);
    EXPECT_EQ(a.rods[0].v[i], b.rods[0].v[i]);
  }
}

TEST(Sleep, SwitchingSleepingOffOrChangingTheModelWakesTheRodAtRest) {
  Model model = wireOnFloor(settings(0.5, 0.05, 0.5));
  State s = makeState(model);
  for (int i = 0; i < 2000 && !s.rods[0].asleep; ++i) ASSERT_TRUE(step(model, s).ok());
  ASSERT_TRUE(s.rods[0].asleep);
  model.gravity = Vec3(0, 0, -2 * 9.81);  // an edit from outside (a UI)
  ASSERT_TRUE(step(model, s).ok());
  EXPECT_FALSE(s.rods[0].asleep);
  for (int i = 0; i < 2000 && !s.rods[0].asleep; ++i) ASSERT_TRUE(step(model, s).ok());
  ASSERT_TRUE(s.rods[0].asleep);
  setSleeping(model, false);
  ASSERT_TRUE(step(model, s).ok());
  EXPECT_FALSE(s.rods[0].asleep);
  EXPECT_EQ(s.sleep.wakes, 2);
}

// Wire A along x asleep at the origin; wire B along y across its middle,
// free, touching it (0.1 nm pressed in, 0.02 mN at the pair stiffness, so the contact is in the implicit
// solve from the first step), pressed down onto it by loads adding up to
// `force` (no gravity, no damping but the contact's own). The wire weighs
// 0.053 mN: the loads are of that order, as a coil's are.
struct Crossing {
  Model model;
  State state;
};

Crossing crossing(double forceMn, double wakeForceMn) {
  RodDef below = wire(Vec3(-0.5 * kLength, 0, 0), Vec3::UnitX(), Vec3::UnitY());
  RodDef above = wire(Vec3(0, -0.5 * kLength, 2 * kRadius - 0.1e-9), Vec3::UnitY(), Vec3::UnitX());
  for (int i = 0; i <= kBeams; ++i) above.loads.push_back({i, Vec3(0, 0, -forceMn * 1e-3 / (kBeams + 1)), Vec3::Zero()});
  ModelDef def = test::modelOf({below, above}, {"rod_contact"});
  for (EffectUse& u : def.effects) u.set("friction_static", 0), u.set("friction_dynamic", 0);
  def.timeStep = kDt;
  // B must not fall asleep itself while it rests on A.
  def.sleep = settings(0.5, 1000, wakeForceMn);
  Crossing c{compileModel(def), {}};
  c.state = makeState(c.model);
  c.state.rods[0].asleep = true;
  return c;
}

double closestBetween(const RodState& a, const RodState& b) {
  double d = INFINITY;
  for (int i = 0; i + 1 < a.activeNodes; ++i)
    for (int j = 0; j + 1 < b.activeNodes; ++j)
      d = std::min(d, closestSegmentSegment(a.x[i], a.x[i + 1], b.x[j], b.x[j + 1]).distance);
  return d;
}

TEST(Sleep, AnAwakeRodPressingBelowTheWakeForceRestsOnTheSleepingOneWithoutPassingThrough) {
  Crossing c = crossing(0.05, 0.2);
  const std::vector<Vec3> x = c.state.rods[0].x;
  double closest = INFINITY;
  for (int i = 0; i < 300; ++i) {
    ASSERT_TRUE(step(c.model, c.state).ok()) << c.state.warnings.back();
    closest = std::min(closest, closestBetween(c.state.rods[0], c.state.rods[1]));
  }
  EXPECT_TRUE(c.state.rods[0].asleep);
  for (int i = 0; i < c.state.rods[0].activeNodes; ++i) EXPECT_EQ(c.state.rods[0].x[i], x[i]);
  EXPECT_LT(closest, 2 * kRadius) << "the rods never pressed: the test would prove nothing";
  EXPECT_GT(closest, 0.9 * 2 * kRadius) << "more than 10 % of r1 + r2 pressed into the sleeping rod";
  // At rest on it: the awake rod got its force from the sleeping one.
  double vmax = 0;
  for (const Vec3& v : c.state.rods[1].v) vmax = std::max(vmax, v.norm());
  EXPECT_LT(vmax, 1e-4);
  EXPECT_EQ(c.state.sleep.wakes, 0);
}

TEST(Sleep, AnAwakeRodPressingAboveTheWakeForceWakesItFromItsFrozenPoseAtRest) {
  const double forceMn = 0.6;
  Crossing c = crossing(forceMn, 0.2);
  int woke = -1;
  for (int i = 0; i < 300 && woke < 0; ++i) {
    ASSERT_TRUE(step(c.model, c.state).ok()) << c.state.warnings.back();
    if (!c.state.rods[0].asleep) woke = i;
  }
  ASSERT_GE(woke, 0) << "pressed with 3 times the wake force, the rod stayed asleep";
  // Woken from its frozen pose at rest.
  for (const Vec3& v : c.state.rods[0].v) EXPECT_EQ(v, Vec3::Zero());
  // Pushed on, the woken rod moves with the awake one.
  const double z0 = c.state.rods[0].x[kBeams / 2].z();
  ASSERT_TRUE(test::run(c.model, c.state, 20));
  EXPECT_LT(c.state.rods[0].x[kBeams / 2].z(), z0);
}

TEST(Sleep, RodsDrivenOrHeldNeverSleep) {
  ModelDef def = test::modelOf({test::clamped(wire(Vec3::Zero(), Vec3::UnitX(), Vec3::UnitY()))}, {});
  def.timeStep = kDt;
  def.sleep = settings(0.5, 0.01, 0.5);
  const Model model = compileModel(def);
  State s = makeState(model);
  ASSERT_TRUE(test::run(model, s, 100));
  EXPECT_FALSE(canSleep(model, s, 0));
  EXPECT_FALSE(s.rods[0].asleep);
}

TEST(Sleep, BadThresholdsAreRefusedByName) {
  EXPECT_THROW(sleepSettings(true, std::vector<double>{-1, 0.1, 1e-3}), std::invalid_argument);
  EXPECT_THROW(sleepSettings(true, std::vector<double>{1e-3, NAN, 1e-3}), std::invalid_argument);
  EXPECT_THROW(sleepSettings(true, std::vector<double>{1e-3, 0.1}), std::invalid_argument);
  try {
    sleepSettings(true, std::vector<double>{1e-3, 0.1, -1});
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("wake_force_mn"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace coilsim
