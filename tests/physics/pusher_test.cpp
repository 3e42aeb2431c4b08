// The force-limited pusher (physics/pusher.h). References: force balance on
// a wire stalled against a rigid stop (the stop carries exactly the push
// force limit), the commanded kinematics when the limit is not reached
// (inserted length = speed x time), and a Richardson-style penalty
// refinement of a coil jammed in a cavity (the sustained wall load must not
// follow the penalty once the pusher's limit is the compliance in series).
#include "physics/pusher.h"

#include <gtest/gtest.h>

#include <cmath>

#include "physics/contact/detect.h"
#include "physics/contact/wall_load.h"
#include "physics/deployment.h"
#include "physics/effect.h"
#include "physics/rest_shape.h"
#include "physics/run.h"
#include "physics/section.h"
#include "support/meshes.h"

namespace coilsim {
namespace {

constexpr double kWire = 0.15e-3;  // m, wire radius

// A straight steel wire (20 mm, 40 beams) in a rigid catheter at the origin
// along +x, 2 mm out, no gravity, frictionless wall contact, and, when
// `stopAt` > 0, a rigid flat stop across the axis at x = stopAt.
Model straightWire(double maxPushForce, double stopAt, double wallScale = 1.0) {
  ModelDef def;
  def.damping = {50.0, 0.0};
  def.timeStep = 1e-3;
  EffectUse wall = EffectRegistry::global().use("wall_contact");
  wall.set("stiffness_n_mm2", 200e6 * wallScale);
  wall.set("stiffness_per_rigidity_1_mm3", 0);  // the penalty exactly as given
  wall.set("friction_static", 0);
  wall.set("friction_dynamic", 0);
  def.effects.push_back(wall);
  if (stopAt > 0) def.obstacles.push_back(test::obstacleOf(test::plane(Vec3(stopAt, 0, 0), Vec3::UnitX(), 2e-3, 8), 0));
  DeploymentDef d;
  d.coilLength = 0.02;
  d.coilBeams = 40;
  d.coilRest = makeStraight(d.coilLength, d.coilBeams);
  d.coilMaterial = {200e9, shearModulusOf(200e9, 0.3), 7800};
  d.coilSection = circularSection(kWire, 0.3);
  d.tip.normal = Vec3(0, 0, 1);
  d.initialDeployed = 2e-3;
  d.maxPushSpeed = 0.05;
  d.maxPushForce = maxPushForce;
  def.device = d;
  return compileModel(def);
}

double totalWallForce(const Model& model, const State& state) {
  const RodState& chain = state.rods[size_t(model.device->chainRod)];
  double sum = 0;
  for (int i = 0; i < chain.activeNodes; ++i) sum += chain.contact.wallForce[size_t(i)];
  return sum;
}

TEST(Pusher, StalledAgainstARigidStopTheStopCarriesExactlyTheForceLimit) {
  // The stop is 3 mm ahead of the wire's end; the push asks for 6 mm. Euler
  // buckling of 5 mm of this wire needs tens of newtons, so the wire stays
  // straight and, at rest, the only forces on it are the pusher's and the
  // stop's: they balance (no gravity; damping vanishes at rest).
  const double limit = 0.05;  // N
  const Model model = straightWire(limit, 5e-3);
  State state = makeState(model);
  ASSERT_EQ(command(model, state, {DeviceCommand::Kind::Push, 0.01, 6e-3}), "");
  for (int s = 0; s < 800; ++s) ASSERT_TRUE(advance(model, state).ok()) << "step " << s;
  const PusherState& p = state.device.pusher;
  EXPECT_TRUE(p.stalled);
  EXPECT_LT(state.device.deployed, 2e-3 + 6e-3 - 1e-3);  // far from what was asked: stalled at the stop
  EXPECT_GT(state.device.motion.pushRate, 0.0);          // still pushing, as a hand that feels the stop
  EXPECT_NEAR(p.force, limit, 1e-3 * limit);
  EXPECT_NEAR(totalWallForce(model, state), limit, 0.01 * limit);
}

TEST(Pusher, BelowTheLimitTheInsertionFollowsTheCommandedSpeedExactly) {
  // A free wire pushed 5 mm at 10 mm/s needs only the force to accelerate
  // and drag it, far below 50 mN: the deployed length is speed x time at
  // every step, and the push ends exactly at its distance.
  const Model model = straightWire(0.05, 0);
  State state = makeState(model);
  ASSERT_EQ(command(model, state, {DeviceCommand::Kind::Push, 0.01, 5e-3}), "");
  for (int s = 1; s <= 600; ++s) {
    ASSERT_TRUE(advance(model, state).ok());
    const double expected = 2e-3 + std::min(0.01 * 1e-3 * s, 5e-3);
    ASSERT_NEAR(state.device.deployed, expected, 1e-15) << "step " << s;
    ASSERT_FALSE(state.device.pusher.stalled) << "step " << s;
    ASSERT_LT(state.device.pusher.force, 0.05) << "step " << s;
  }
  EXPECT_EQ(state.device.motion.pushRate, 0.0);
}

// A platinum helix (5 mm loops, 0.8 mm pitch, 0.15 mm wire, 60 mm) pushed
// at 10 mm/s without end into a closed 6 mm sphere (the catheter tip 0.5 mm
// inside its near wall, the far wall 5.5 mm ahead), wall friction 0.3: the
// coil's end runs into the wall at a grazing angle and, at the registered
// limit, jams there with about 4.6 mm out. Returns the largest sustained
// wall load of 3 s of pushing.
double jammedPushLoad(double wallScale, double maxPushForce = kMaxPushForce.defaultValue * kMaxPushForce.toSI) {
  ModelDef def;
  def.damping = {1.0, 0.0};
  def.timeStep = 1e-3;
  EffectUse wall = EffectRegistry::global().use("wall_contact");
  wall.set("stiffness_n_mm2", 200e6 * wallScale);
  wall.set("stiffness_per_rigidity_1_mm3", 0);
  def.effects.push_back(wall);
  def.effects.push_back(EffectRegistry::global().use("self_contact"));
  def.obstacles.push_back(test::obstacleOf(test::icosphere(3e-3, 3, Vec3(2.5e-3, 0, 0)), 0.3));
  DeploymentDef d;
  d.coilLength = 0.06;
  d.coilBeams = 120;
  d.coilRest = makeHelix(d.coilLength, d.coilBeams, 0.005, 0.0008, true);
  d.coilMaterial = {7.5e9, shearModulusOf(7.5e9, 0.39), 21450};
  d.coilSection = circularSection(kWire, 0.39);
  d.tip.normal = Vec3(0, 0, 1);
  d.initialDeployed = 0.5e-3;
  d.maxPushSpeed = 0.05;
  d.maxPushForce = maxPushForce;
  def.device = d;
  const Model model = compileModel(def);
  State state = makeState(model);
  if (!command(model, state, {DeviceCommand::Kind::Push, 0.01, 0}).empty()) return NAN;
  for (int s = 0; s < 3000; ++s)
    if (!advance(model, state).ok()) return NAN;
  return state.stats.wallLoad.max;
}

// The sustained wall load at 0.7 s of the straight wire pushed at 10 mm/s
// to `past` m beyond touching the stop's skin (reached at about 0.28 s).
double stopLoad(double wallScale, double maxPushForce, double past) {
  const Model model = straightWire(maxPushForce, 5e-3, wallScale);
  State state = makeState(model);
  const double touch = 5e-3 - 2e-3 - (1 + kWallSkin) * kWire;  // push until the wire's end meets the skin
  if (!command(model, state, {DeviceCommand::Kind::Push, 0.01, touch + past}).empty()) return NAN;
  for (int s = 0; s < 700; ++s)
    if (!advance(model, state).ok()) return NAN;
  return state.stats.wallLoad.now;
}

TEST(Pusher, TheWallLoadOfAJammedPushConvergesAsTheWallStiffens) {
  // Penalty refinement 0.5, 1, 2, 4 times the registered wall. Control:
  // the same pushes with the limit at its upper bound (10 N, never reached
  // here) are stopped only by the penalty, and the load follows it (about
  // doubling per doubling); with the registered limit the pusher is the
  // compliance in series, and the load is the limit's (force balance).
  const double limit = kMaxPushForce.defaultValue * kMaxPushForce.toSI;
  const double unlimited = kMaxPushForce.max * kMaxPushForce.toSI;
  double last = NAN, lastControl = NAN;
  for (const double scale : {0.5, 1.0, 2.0, 4.0}) {
    const double load = stopLoad(scale, limit, 20e-6), control = stopLoad(scale, unlimited, 20e-6);
    ASSERT_TRUE(std::isfinite(load) && std::isfinite(control)) << "wall x " << scale;
    EXPECT_NEAR(load, limit, 0.01 * limit) << "wall x " << scale;
    if (std::isfinite(last)) {
      EXPECT_LT(std::abs(load - last), 0.1 * last) << "wall x " << scale;
      EXPECT_GT(control, 1.5 * lastControl) << "wall x " << scale << ": the control should follow the penalty";
    }
    last = load, lastControl = control;
  }
  // A curved coil jammed in a cavity at a grazing angle: its wall load is
  // not the limit (the wall's angle wedges it, about 3 times), but it does
  // not follow the penalty either.
  double jam = jammedPushLoad(0.5);
  ASSERT_TRUE(std::isfinite(jam));
  for (const double scale : {1.0, 2.0, 4.0}) {
    const double load = jammedPushLoad(scale);
    ASSERT_TRUE(std::isfinite(load)) << "wall x " << scale;
    EXPECT_LT(std::abs(load - jam), 0.1 * jam) << "wall x " << scale << ": " << load * 1e3 << " mN after "
                                               << jam * 1e3 << " mN";
    jam = load;
  }
}

}  // namespace
}  // namespace coilsim
