// Coil deployment through a rigid straight catheter (physics/deployment.h,
// controller.h). References: the helix's analytic curvature and torsion
// (coil-measurement/1: kappa = R/(R^2+c^2), tau = +-c/(R^2+c^2), c = p/2pi),
// the static equilibrium of the same deployed length computed by the static
// solver (an independent path: Newton on a clamped rod, no sliding), rigid
// rotation about the catheter axis, and conservation of length and mass.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstring>

#include "support/coil_spec.h"
#include "support/refusal.h"
#include "physics/deployment.h"
#include "physics/failure.h"
#include "physics/run.h"
#include "physics/integrator.h"

namespace coilsim {
namespace {

constexpr double kLength = 0.03, kLoop = 0.004, kPitch = 0.001;
constexpr int kBeams = 60;  // h = 0.5 mm, as the bench coil with 300 beams

struct Bench {
  Model model;
  Deployment dep;
  State state;
};

Bench makeBench(bool gravity, double alpha = 20.0, double initial = 0.0, double young = 7.5e9) {
  ModelDef def;
  def.gravity = gravity ? Vec3(0, 0, -9.81) : Vec3::Zero();
  if (gravity) def.effects.push_back(EffectRegistry::global().use("gravity"));
  def.damping.massCoeff = alpha;
  def.timeStep = 1e-3;
  DeploymentDef d;
  d.coil = test::wireSpec(kLength, test::helixRest(kLoop, kPitch), young, 0.39, 21450, 0.15e-3);
  d.coilBeams = kBeams;
  d.tip.position = Vec3(0.001, 0.002, 0.003);
  d.tip.direction = Vec3(1, 0, 0);
  d.tip.normal = Vec3(0, 0, 1);
  d.initialDeployed = initial;
  Bench b;
  def.device = d;
  b.model = compileModel(def);
  b.dep = *b.model.device;
  b.state = makeState(b.model);
  resetDevice(b.model, b.state, initial, 0.0);
  return b;
}

void run(Bench& b, const std::vector<TimedCommand>& commands, double seconds) {
  const TimelineRun r = runTimeline(b.model, b.state, commands, seconds);
  ASSERT_TRUE(r.ok()) << r.failure->message();
}

TimedCommand push(double t, double speed, double distance) {
  return {t, {DeviceCommand::Kind::Push, speed, distance}};
}

// Curvature and signed torsion at node i from four consecutive points
// (discrete Frenet: turning angle per length, binormal turning angle).
void curvatureTorsion(const std::vector<Vec3>& x, int i, double& kappa, double& tau) {
  const Vec3 e0 = x[i] - x[i - 1], e1 = x[i + 1] - x[i], e2 = x[i + 2] - x[i + 1];
  const Vec3 b0 = e0.cross(e1).normalized(), b1 = e1.cross(e2).normalized();
  const double ds = e1.norm();
  kappa = 2 * std::sin(0.5 * std::acos(std::clamp(e0.normalized().dot(e1.normalized()), -1.0, 1.0))) / ds;
  const double turn = std::atan2(b0.cross(b1).dot(e1.normalized()), b0.dot(b1));
  tau = turn / ds;
}

TEST(DeploymentTest, SlowPushInFreeSpaceRecoversTheRestHelix) {
  Bench b = makeBench(false);
  run(b, {push(0, 0.01, kLength)}, kLength / 0.01 + 0.5);
  ASSERT_DOUBLE_EQ(b.state.device.deployed, kLength);
  const RodState& c = b.state.rods[b.dep.chainRod];
  ASSERT_EQ(c.activeNodes, kBeams + 1);
  const double R = kLoop / 2, cc = kPitch / (2 * M_PI);
  const double kappa0 = R / (R * R + cc * cc), tau0 = cc / (R * R + cc * cc);
  // Discrete curvature of a polygon inscribed in a helix differs from the
  // smooth one by O((kappa h)^2) ~ 1.3 %; torsion likewise.
  double worstK = 0, worstT = 0;
  for (int i = 2; i + 2 < c.activeNodes; ++i) {
    double k, t;
    curvatureTorsion(c.x, i, k, t);
    worstK = std::max(worstK, std::abs(k / kappa0 - 1));
    worstT = std::max(worstT, std::abs(t / tau0 - 1));
  }
  std::printf("[ measured ] helix after push: curvature error %.3g, torsion error %.3g\n", worstK, worstT);
  EXPECT_LT(worstK, 0.02) << "loop curvature after deployment";
  EXPECT_LT(worstT, 0.05) << "torsion (positive: right-handed) after deployment";
}

TEST(DeploymentTest, DeployedUnderGravityMatchesTheStaticSolveOfTheSameLength) {
  // A soft coil (a wound spring's effective modulus) so that it sags visibly.
  Bench b = makeBench(true, 30.0, 0.0, 0.02e9);
  const double l = 0.01;  // 20 beams out: the partial beam is then exactly h
  run(b, {push(0, 0.01, l)}, l / 0.01 + 1.5);
  const RodState& c = b.state.rods[b.dep.chainRod];
  const int out = c.activeNodes - 1;
  ASSERT_EQ(out, int(std::lround(l / (kLength / kBeams))));
  // Reference: a clamped helix of length l at the tip, solved statically.
  ModelDef ref;
  ref.gravity = Vec3(0, 0, -9.81);
  ref.effects.push_back(EffectRegistry::global().use("gravity"));
  RodDef r;
  r.length = l;
  r.beams = out;
  r.rest = makeHelix(l, out, kLoop, kPitch, true);
  r.placement = b.dep.tip;
  r.material = b.dep.material;
  r.section = b.dep.section;
  r.constraints.push_back({0, kAllDofs});
  ref.rods.push_back(r);
  const Model rm = compileModel(ref);
  State rs = makeState(rm);
  ASSERT_TRUE(solveStatic(rm, rs).converged());
  double worst = 0, sag = 0;
  for (int i = 0; i <= out; ++i) {
    worst = std::max(worst, (c.x[i] - rs.rods[0].x[i]).norm());
    sag = std::max(sag, (rs.rods[0].x[i] - rm.rods[0].restPoints[i]).norm());
  }
  ASSERT_GT(sag, 1e-4) << "gravity must bend the coil measurably for this test to mean anything";
  std::printf("[ measured ] deployed vs static: worst %.3g m, sag %.3g m\n", worst, sag);
  EXPECT_LT(worst, 0.01 * sag) << "deployed shape vs static solve (sag " << sag << " m)";
}

TEST(DeploymentTest, TwistByNinetyDegreesTurnsTheLoopAboutTheCatheterAxis) {
  Bench b = makeBench(false, 20.0, 0.008);
  run(b, {}, 0.2);
  const std::vector<Vec3> before = b.state.rods[b.dep.chainRod].x;
  const int n = b.state.rods[b.dep.chainRod].activeNodes;
  run(b, {{0, {DeviceCommand::Kind::Twist, M_PI, M_PI / 2}}}, 1.5);
  EXPECT_NEAR(b.state.device.twist, M_PI / 2, 1e-12);
  const Quat turn(Eigen::AngleAxisd(M_PI / 2, b.dep.tip.direction.normalized()));
  double worst = 0, reach = 0;
  for (int i = 0; i < n; ++i) {
    const Vec3 expected = b.dep.tip.position + turn * (before[i] - b.dep.tip.position);
    worst = std::max(worst, (b.state.rods[b.dep.chainRod].x[i] - expected).norm());
    reach = std::max(reach, (before[i] - b.dep.tip.position).norm());
  }
  std::printf("[ measured ] twist 90 deg: worst %.3g m of reach %.3g m\n", worst, reach);
  EXPECT_LT(worst, 1e-3 * reach);
}

TEST(DeploymentTest, LengthAndMassAreConservedThroughDeployRetractDeploy) {
  Bench b = makeBench(true, 20.0);
  const double L = kLength, mass = b.dep.material.density * b.dep.section.area * L;
  double worstL = 0, worstM = 0;
  DeviceCommand pull{DeviceCommand::Kind::Pull, 0.02, 0.02};
  std::vector<std::pair<double, DeviceCommand>> phases = {
      {0.02 / 0.02, {DeviceCommand::Kind::Push, 0.02, 0.02}}, {1.0, pull}, {1.5, {DeviceCommand::Kind::Push, 0.02, 0.03}}};
  for (auto& [seconds, cmd] : phases) {
    ASSERT_EQ(coilsim::test::refusal(command(b.model, b.state, cmd)), "");
    for (int s = 0; s < int(seconds / 1e-3); ++s) {
      ASSERT_TRUE(advance(b.model, b.state).ok());
      worstL = std::max(worstL, std::abs(representedCoilLength(b.model, b.state) / L - 1));
      worstM = std::max(worstM, std::abs(representedCoilMass(b.model, b.state) / mass - 1));
    }
  }
  EXPECT_NEAR(b.state.device.deployed, L, 1e-12);
  EXPECT_LT(worstL, 1e-12);
  EXPECT_LT(worstM, 1e-12);
  // The simulated centre line is as long as the rest one (axial strain only).
  const RodState& c = b.state.rods[b.dep.chainRod];
  double polygon = 0, rest = 0;
  for (int e = 0; e + 1 < c.activeNodes; ++e) polygon += (c.x[e + 1] - c.x[e]).norm(), rest += c.beams[e].length;
  EXPECT_NEAR(polygon / rest, 1.0, 1e-4);
}

TEST(DeploymentTest, DetachedCoilAtRestDoesNotDrift) {
  Bench b = makeBench(false, 20.0, kLength);
  run(b, {}, 0.3);
  ASSERT_EQ(coilsim::test::refusal(command(b.model, b.state, {DeviceCommand::Kind::Detach, 0, 0})), "");
  run(b, {}, 0.001);
  ASSERT_TRUE(b.state.device.detached);
  const RodState& f = b.state.rods[b.dep.freeRod];
  ASSERT_TRUE(f.active);
  const std::vector<Vec3> start = f.x;
  run(b, {}, 1.0);
  double drift = 0;
  for (int i = 0; i < f.activeNodes; ++i) drift = std::max(drift, (f.x[i] - start[i]).norm());
  std::printf("[ measured ] detached coil drift in 1 s: %.3g m\n", drift);
  EXPECT_LT(drift, 1e-7) << "a released coil at rest must stay where it is";
}

TEST(DeploymentTest, InvalidCommandsAreRefusedWithAReasonAndChangeNothing) {
  Bench b = makeBench(false, 20.0, 0.01);
  using K = DeviceCommand::Kind;
  EXPECT_NE(coilsim::test::refusal(command(b.model, b.state, {K::Push, 0.01, 0.05})), "") << "push beyond the coil's end";
  EXPECT_NE(coilsim::test::refusal(command(b.model, b.state, {K::Push, 10.0, 0})), "") << "push faster than a hand";
  EXPECT_NE(coilsim::test::refusal(command(b.model, b.state, {K::Push, std::nan(""), 0})), "") << "NaN speed";
  EXPECT_NE(coilsim::test::refusal(command(b.model, b.state, {K::Detach, 0, 0})), "") << "detach before the coil is out";
  EXPECT_NE(coilsim::test::refusal(command(b.model, b.state, {K::Pull, 0.01, 0.02})), "") << "pull more than is out";
  EXPECT_FALSE(b.state.device.motion.moving());
  Bench d = makeBench(false, 20.0, kLength);
  ASSERT_EQ(coilsim::test::refusal(command(d.model, d.state, {K::Detach, 0, 0})), "");
  run(d, {}, 0.001);
  EXPECT_NE(coilsim::test::refusal(command(d.model, d.state, {K::Pull, 0.01, 0.001})), "") << "pull after detach";
  EXPECT_NE(coilsim::test::refusal(command(d.model, d.state, {K::Twist, 1.0, 0.1})), "") << "twist after detach";
}


// detach() itself (what a pending detach runs) refuses as command() does: a
// DeviceRefusal with the deployed length against the coil's, and nothing
// changes; once detached, a second detach is refused too. Reference: the
// lengths the benches were built with.
TEST(DeploymentTest, DetachRefusesACoilNotFullyOutAndASecondDetach) {
  Bench b = makeBench(false, 20.0, 0.01);
  const State before = b.state;
  const std::optional<Failure> early = detach(b.model, b.state);
  ASSERT_TRUE(early);
  EXPECT_EQ(early->kind, FailureKind::DeviceRefusal);
  EXPECT_DOUBLE_EQ(early->value, 0.01);
  EXPECT_DOUBLE_EQ(early->limit, kLength);
  EXPECT_EQ(describe(*early).rfind("refused: ", 0), 0u) << describe(*early);
  EXPECT_FALSE(b.state.device.detached);
  EXPECT_EQ(b.state.rods[size_t(b.dep.freeRod)].active, before.rods[size_t(b.dep.freeRod)].active);
  EXPECT_EQ(b.state.rods[size_t(b.dep.chainRod)].activeNodes, before.rods[size_t(b.dep.chainRod)].activeNodes);
  Bench d = makeBench(false, 20.0, kLength);
  ASSERT_EQ(detach(d.model, d.state), std::nullopt);
  EXPECT_TRUE(d.state.device.detached);
  const std::optional<Failure> again = detach(d.model, d.state);
  ASSERT_TRUE(again);
  EXPECT_EQ(again->kind, FailureKind::DeviceRefusal);
}
// The coil's RodSpec is sampled by compileModel: a rest shape that cannot be
// built (a polyline of one point) is refused naming the deployment.
TEST(DeploymentTest, ACoilRestShapeThatCannotBeBuiltNamesTheDeployment) {
  ModelDef def;
  DeploymentDef d;
  d.coilName = "probe";
  RestShapeDef dot;
  dot.type = RestShapeDef::Type::Polyline;
  dot.points = {Vec3::Zero()};
  d.coil = test::wireSpec(kLength, dot, 7.5e9, 0.39, 21450, 0.15e-3);
  d.coilBeams = kBeams;
  d.tip.normal = Vec3(0, 0, 1);
  def.device = d;
  try {
    compileModel(def);
    ADD_FAILURE() << "a one-point polyline was accepted";
  } catch (const PhysicsError& e) {
    EXPECT_EQ(e.failure().kind, FailureKind::BadDefinition);
    EXPECT_EQ(e.failure().where(), "deployment of 'probe'");
    EXPECT_NE(e.failure().text.find("rest shape"), std::string::npos) << e.what();
  }
}

TEST(DeploymentTest, ReachingTheCoilsEndIsSaidOnceEvenWhileTheCatheterIsRetracted) {
  Bench b = makeBench(false, 20.0, kLength - 0.002);
  using K = DeviceCommand::Kind;
  const TimelineRun r = runTimeline(b.model, b.state,
                                    {push(0, 0.01, 0), {0.3, {K::Retract, 0.005, 0.001}}}, 0.6);
  ASSERT_TRUE(r.ok());
  int said = 0;
  for (const std::string& line : r.log) said += line.find("fully deployed") != std::string::npos;
  EXPECT_EQ(said, 1) << "one limit reached, one message (the retraction keeps pressing on it every step)";
  EXPECT_DOUBLE_EQ(b.state.device.deployed, kLength);
}

TEST(DeploymentTest, ReplayingATimelineIsBitForBit) {
  auto once = [] {
    Bench b = makeBench(true, 5.0);
    run(b, {push(0, 0.02, 0.015), {0.3, {DeviceCommand::Kind::Twist, 2.0, 0.5}}, {0.6, {DeviceCommand::Kind::Pull, 0.01, 0.003}}}, 1.2);
    return b.state.rods[b.dep.chainRod];
  };
  const RodState a = once(), c = once();
  ASSERT_EQ(a.activeNodes, c.activeNodes);
  EXPECT_EQ(std::memcmp(a.x.data(), c.x.data(), sizeof(Vec3) * a.x.size()), 0);
  EXPECT_EQ(std::memcmp(a.q.data(), c.q.data(), sizeof(Quat) * a.q.size()), 0);
}

}  // namespace
}  // namespace coilsim
