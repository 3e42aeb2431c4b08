// The wall load (physics/contact/wall_load.h): the sustained figure filters
// penalty spikes by its stated window, per node; a cantilever pressed on a
// wall reads the force of beam theory, converging as the penalty stiffness
// grows; and a coil settled in a sac reads a load that a stiffer wall does
// not change (Richardson in 1 / k).
#include "physics/contact/wall_load.h"

#include <gtest/gtest.h>

#include <cmath>

#include "physics/contact/detect.h"
#include "physics/deployment.h"
#include "physics/integrator.h"
#include "physics/rest_shape.h"
#include "physics/run.h"
#include "support/coil_spec.h"
#include "support/meshes.h"
#include "support/refusal.h"
#include "support/rod_models.h"

namespace coilsim {
namespace {

TEST(WallLoad, ASpikeEveryOtherStepIsNotALoadAndTheWindowIsStatedInSeconds) {
  // 1 N every other step over a steady 2 mN (a light node chattering): the
  // sustained load is the 2 mN, the peak the spike.
  WallLoad w;
  for (int s = 0; s <= 20; ++s) addWallLoad(w, s % 2 ? 1.0 : 2e-3, 1e-3, 1e-3 * s);
  EXPECT_DOUBLE_EQ(w.now, 2e-3);
  EXPECT_DOUBLE_EQ(w.max, 2e-3);
  EXPECT_DOUBLE_EQ(w.peak, 1.0);
  // A load counts once it has lasted the window, 5 ms, whatever the step.
  for (const double h : {1e-3, 2.5e-4}) {
    WallLoad v;
    const int steps = int(std::lround(kWallLoadWindow / h));
    EXPECT_EQ(wallLoadSteps(h), steps);
    for (int s = 0; s < steps - 1; ++s) addWallLoad(v, 0.05, h, h * s);
    EXPECT_EQ(v.now, 0.0) << "h = " << h;
    addWallLoad(v, 0.05, h, h * steps);
    EXPECT_EQ(v.now, 0.05) << "h = " << h;
  }
  // Nothing until a whole window was stepped; a State that starts again has none.
  EXPECT_EQ(State{}.stats.wallLoad.max, 0.0);
}

TEST(WallLoad, SpikesMovingFromNodeToNodeAreNotALoad) {
  // Node 0 holds 2 mN at every step; each step one of nodes 1-4 in turn
  // takes a 1 N spike (a coil chattering on the wall, each node for one
  // step). Held by one node for the window: 2 mN. Each step's largest node
  // force is 1 N at every step, which is what the window must not count.
  WallLoad w;
  double forces[5];
  for (int s = 0; s <= 20; ++s) {
    for (double& f : forces) f = 0;
    forces[0] = 2e-3;
    forces[1 + s % 4] = 1.0;
    addWallLoad(w, forces, 1e-3, 1e-3 * s);
  }
  EXPECT_DOUBLE_EQ(w.now, 2e-3);
  EXPECT_DOUBLE_EQ(w.max, 2e-3);
  EXPECT_DOUBLE_EQ(w.peak, 1.0);
  // One node holding 0.1 N for the window is a load, wherever the others are.
  for (int s = 0; s < wallLoadSteps(1e-3); ++s) {
    for (double& f : forces) f = 0;
    forces[3] = 0.1;
    forces[s % 2 ? 1 : 4] = 0.5;
    addWallLoad(w, forces, 1e-3, 0.021 + 1e-3 * s);
  }
  EXPECT_DOUBLE_EQ(w.now, 0.1);
}

// A platinum cantilever (L = 10 mm, r = 0.15 mm, 20 beams, clamped at x = 0)
// is moved rigidly onto a flat frictionless wall tilted by alpha, so that
// only its tip node touches, until the wall's contact surface (the skin,
// kWallSkin r outside the wire) overlaps the tip by d along the wall normal;
// then it settles.
struct PressedCantilever {
  double load = 0;      // N, the sustained wall load after settling
  double fastest = 0;   // m/s, fastest node at the end
  double kBeam = 0;     // N/m, beam theory's tip stiffness along the wall normal
  double kNode = 0;     // N/m, the penalty on the tip node (k per length times half a segment)
};

constexpr double kLength = 0.01, kRadius = 0.15e-3, kOverlap = 0.1e-3, kTilt = 0.3;  // tan(alpha)
constexpr int kBeams = 20;

// rigid: the wall holds the tip by a constraint (the stiffness then only sets friction, off here).
PressedCantilever pressCantilever(double stiffness_n_mm2, bool rigid = false) {
  RodDef rod = test::clamped(
      test::straightRod(kLength, kBeams, test::platinum(), circularSection(kRadius, test::kPlatinumPoisson)));
  ModelDef def = test::modelOf({rod});
  def.damping.massCoeff = 100;
  EffectUse wall = EffectRegistry::global().use("wall_contact");
  wall.set("stiffness_n_mm2", stiffness_n_mm2 * 1e6);
  wall.set("stiffness_per_rigidity_1_mm3", 0);  // the penalty exactly as given
  wall.set("friction_static", 0);
  wall.set("friction_dynamic", 0);
  wall.set("rigid", rigid ? 1.0 : 0.0);
  def.effects.push_back(wall);
  // The wall rises along +x with slope kTilt; the rod lives above it.
  const double alpha = std::atan(kTilt);
  const Vec3 up(-std::sin(alpha), 0, std::cos(alpha));  // the wall's normal into the free side
  const Vec3 tip(kLength, 0, 0);
  const double gap = 0.1e-3;  // clear before the clamp moves
  const Vec3 foot = tip - ((1 + kWallSkin) * kRadius + gap) * up;
  def.obstacles.push_back(test::obstacleOf(test::plane(foot, -up, 2e-3, 8), 0.0));
  Model model = compileModel(def);
  State state = makeState(model);
  // The clamp moves along -up by gap + overlap at 10 mm/s, then holds.
  const double speed = 0.01, travel = gap + kOverlap;
  const long moving = std::lround(travel / speed / model.timeStep);
  model.rods[0].constraints[0].velocity = -speed * up;
  PressedCantilever out;
  for (long s = 0; s < 400; ++s) {
    if (s == moving) model.rods[0].constraints[0].velocity = Vec3::Zero();
    EXPECT_TRUE(step(model, state).ok()) << "step " << s;
  }
  for (const Vec3& v : state.rods[0].v) out.fastest = std::max(out.fastest, v.norm());
  out.load = state.stats.wallLoad.now;
  const double ei = test::platinum().youngModulus * M_PI * std::pow(kRadius, 4) / 4;
  // Tip force F along the normal: its transverse part F cos(alpha) bends the
  // cantilever by F cos L^3 / 3EI, which moves the tip along the normal by
  // that times cos (the axial part shortens it by 1e-7 of that).
  out.kBeam = 3 * ei / (std::pow(kLength, 3) * std::pow(std::cos(alpha), 2));
  out.kNode = stiffness_n_mm2 * 1e6 * (kLength / kBeams) / 2;
  return out;
}

// Beam and penalty in series: the tip takes the overlap d as F / kBeam + F / kNode.
double seriesForce(const PressedCantilever& p) { return kOverlap / (1 / p.kBeam + 1 / p.kNode); }

TEST(WallLoad, ACantileverPressedOnAWallReadsBeamTheorysForceAndConvergesAsThePenaltyStiffens) {
  // A Richardson-style sequence: penalties from about the beam's own tip
  // stiffness (9.8 N/m) up, each twice the last, and the default wall. The
  // load follows beam and penalty in series (so the penalty's law is the
  // one stated), and tends to beam theory's.
  const double ks[] = {0.04, 0.08, 0.16, 0.32};  // N/mm2 (tip node 10-80 N/m)
  double loads[4];
  for (int i = 0; i < 4; ++i) {
    const PressedCantilever p = pressCantilever(ks[i]);
    loads[i] = p.load;
    std::printf("[ measured ] k %.2f N/mm2: wall load %.4f mN, beam and penalty in series %.4f mN, fastest node %.2g m/s\n",
                ks[i], p.load * 1e3, seriesForce(p) * 1e3, p.fastest);
    EXPECT_LT(p.fastest, 1e-5) << "not settled";
    EXPECT_NEAR(p.load, seriesForce(p), 0.02 * seriesForce(p)) << "k = " << ks[i];
  }
  // Monotone convergence: each doubling changes the load less than the last.
  for (int i = 0; i + 2 < 4; ++i) EXPECT_LT(loads[i + 2] - loads[i + 1], loads[i + 1] - loads[i]) << "k " << ks[i];
  // Richardson extrapolation: in series, 1 / F is linear in 1 / k, so
  // 2 / F(2k) - 1 / F(k) is 1 / F at an infinitely stiff wall: beam theory's
  // F = 3 EI d / (L^3 cos^2 alpha).
  const PressedCantilever stiff = pressCantilever(ks[3]);
  const double limit = kOverlap * stiff.kBeam;
  const double extrapolated = 1 / (2 / loads[3] - 1 / loads[2]);
  EXPECT_NEAR(extrapolated, limit, 0.02 * limit);
  // At the registered wall (200 N/mm2) the load is beam theory's, and doubling the wall changes it by far less than 10 %.
  const double f200 = pressCantilever(200).load, f400 = pressCantilever(400).load;
  std::printf("[ measured ] default wall: %.4f mN, twice as stiff %.4f mN, beam theory %.4f mN\n", f200 * 1e3,
              f400 * 1e3, limit * 1e3);
  EXPECT_NEAR(f200, limit, 0.02 * limit);
  EXPECT_LT(std::abs(f400 - f200), 0.1 * f400);
  // The wall held by a constraint has no penalty in series: beam theory's force outright.
  const PressedCantilever held = pressCantilever(200, true);
  std::printf("[ measured ] constraint: %.4f mN, fastest node %.2g m/s\n", held.load * 1e3, held.fastest);
  EXPECT_LT(held.fastest, 1e-5) << "not settled";
  EXPECT_NEAR(held.load, limit, 0.01 * limit);
}

// A clinician's scene: a soft helical coil (the default scene's: 0.012-inch
// wound platinum, B = 0.00294 N mm^2, 7 mm loops) pushed out of a catheter
// into a closed 7 mm sac, the pusher stopped, settled. Its 7 mm loops are
// larger than the sac its centre line can reach, so they press outward: a
// wall load the coil's elasticity carries.
struct SettledSac {
  Model model;
  State settled;
};

// The sac, the coil and its catheter, at time step h; the wall a penalty or (rigid) constraints.
Model sacModel(double h, bool rigid = false) {
  ModelDef def;
  def.gravity = Vec3(0, 0, -9.81);
  def.effects.push_back(EffectRegistry::global().use("gravity"));
  def.effects.push_back(EffectRegistry::global().use("wall_contact"));
  def.effects.back().set("rigid", rigid ? 1.0 : 0.0);
  def.effects.push_back(EffectRegistry::global().use("self_contact"));
  def.damping.massCoeff = 20;  // settles sooner; damping does not move an equilibrium
  def.timeStep = h;
  def.obstacles.push_back(test::obstacleOf(test::icosphere(3.5e-3, 4)));  // 5120 triangles
  DeploymentDef d;
  d.coil = test::wireSpec(0.03, test::helixRest(7e-3, 0.3048e-3), 168e9, 0.38, 21450, 0);
  d.coil.explicitSection = {3.1837e-8, 1.74887e-20, 1.74887e-20, 5.74399e-20, 0, 0.1524e-3};
  d.coilBeams = 60;  // 0.5 mm, as the scenes
  d.tip.position = Vec3(0, 0, -2.5e-3);
  d.tip.direction = Vec3(0, 0, 1);
  d.tip.normal = Vec3(1, 0, 0);
  d.catheterDrawLength = 0.5e-3;
  def.device = d;
  return compileModel(def);
}

// Pushes `pushed` m at `speed` m/s, then `after` s with the pusher at rest.
State pushIntoSac(const Model& model, double pushed, double speed, double after) {
  State state = makeState(model);
  resetDevice(model, state, 0.0, 0.0);
  EXPECT_EQ(test::refusal(command(model, state, {DeviceCommand::Kind::Push, speed, pushed})), "");
  const long steps = std::lround((pushed / speed + after) / model.timeStep);
  for (long s = 0; s < steps; ++s) {
    const StepReport r = advance(model, state);
    EXPECT_TRUE(r.ok()) << "step " << s << ": " << (r.ok() ? "" : describe(*r.failure));
    if (!r.ok()) break;
  }
  EXPECT_FALSE(state.device.motion.moving());
  return state;
}

SettledSac settleInSac(double pushed, double speed) {
  SettledSac out{sacModel(1e-3), State{}};
  out.settled = pushIntoSac(out.model, pushed, speed, 3.5);
  return out;
}

double fastestNode(const State& state) {
  double v = 0;
  for (const RodState& r : state.rods)
    for (int i = 0; r.active && i < r.activeNodes; ++i) v = std::max(v, r.v[i].norm());
  return v;
}

TEST(WallLoad, ACoilSettledInASacReadsALoadThatAStifferWallDoesNotChange) {
  // From the one settled State, the wall at 1, 2 and 4 times its registered
  // penalty for 0.2 s more. (Separate deployments at each penalty end in
  // different coil shapes, a chaotic deployment's; docs/contact.md.)
  SettledSac sac = settleInSac(0.02, 0.01);
  EffectUse* wall = findEffect(sac.model, "wall_contact");
  ASSERT_NE(wall, nullptr);
  const double k = wall->value("stiffness_n_mm2"), perRigidity = wall->value("stiffness_per_rigidity_1_mm3");
  double loads[3];
  for (int i = 0; i < 3; ++i) {
    wall->set("stiffness_n_mm2", k * (1 << i));
    wall->set("stiffness_per_rigidity_1_mm3", perRigidity * (1 << i));
    State state = sac.settled;
    for (int s = 0; s < 200; ++s) ASSERT_TRUE(advance(sac.model, state).ok()) << "k x" << (1 << i) << " step " << s;
    loads[i] = state.stats.wallLoad.now;
    std::printf("[ measured ] wall x%d: sustained load %.4f mN (largest while pushed %.3f mN), fastest node %.3g mm/s\n",
                1 << i, loads[i] * 1e3, state.stats.wallLoad.max * 1e3, fastestNode(state) * 1e3);
    EXPECT_LT(fastestNode(state), 1e-3) << "not settled: the load would be a transient's";
  }
  // The coil must press: more than a node's weight (0.5 mm of wire, 3.4 uN).
  EXPECT_GT(loads[0], 1e-5);
  // The penalty's error is first order in 1 / k (a load carried by the
  // wire's elasticity, the penalty's compliance in series): Richardson from
  // k and 2k gives the limit, and 4k must lie where that predicts.
  const double limit = 2 * loads[1] - loads[0];
  std::printf("[ measured ] Richardson limit %.4f mN\n", limit * 1e3);
  EXPECT_LT(std::abs(loads[1] - loads[0]), 0.1 * limit) << "the issue's criterion: doubling the wall changes the load by less than 10 %";
  EXPECT_NEAR(loads[2], limit + 0.5 * (loads[1] - limit), 0.01 * limit);
}

TEST(WallLoad, APushIntoASacReadsALargestLoadThatConvergesAsTheStepShrinks) {
  // A clinician's push: the soft coil driven 12 mm into the closed 7 mm sac
  // at 10 mm/s (displacement controlled: the pusher's advance is
  // prescribed, as in timelines/push-*.json), its loops striking the wall
  // and pressing on one another, then 0.1 s at rest. The wall holds each
  // node by a constraint, which has no stiffness to refine: the step is
  // (1, 0.5, 0.25 ms). Reference: Richardson's extrapolation of the three,
  // with the order they show; halving the step must change the largest
  // sustained load by less than 10 % of that limit.
  const double steps[3] = {1e-3, 0.5e-3, 0.25e-3};
  double loads[3];
  for (int i = 0; i < 3; ++i) {
    const State state = pushIntoSac(sacModel(steps[i], true), 0.012, 0.01, 0.1);
    loads[i] = state.stats.wallLoad.max;
    std::printf("[ measured ] h %.2f ms: largest sustained wall load %.4f mN at t = %.3f s, peak %.3f mN\n",
                steps[i] * 1e3, loads[i] * 1e3, state.stats.wallLoad.timeOfMax, state.stats.wallLoad.peak * 1e3);
  }
  EXPECT_GT(loads[2], 1e-5) << "the coil must press on the wall (more than a node's weight)";
  const double d1 = loads[0] - loads[1], d2 = loads[1] - loads[2];
  // The observed order p from the ratio of successive differences (2^p); a
  // ratio below 1 means no convergence, and Richardson does not apply.
  const double ratio = std::abs(d2) > 0 ? d1 / d2 : INFINITY;
  const double limit = std::isfinite(ratio) && ratio > 1 ? loads[2] + d2 / (ratio - 1) : loads[2];
  std::printf("[ measured ] differences %.4f, %.4f mN (ratio %.2f); Richardson limit %.4f mN\n", d1 * 1e3, d2 * 1e3,
              ratio, limit * 1e3);
  EXPECT_LT(std::abs(d2), 0.1 * limit) << "halving the step from 0.5 to 0.25 ms";
  EXPECT_LT(std::abs(d1), 0.1 * limit) << "halving the step from 1 to 0.5 ms";
  EXPECT_LT(std::abs(loads[2] - limit), 0.1 * limit);
}

}  // namespace
}  // namespace coilsim
