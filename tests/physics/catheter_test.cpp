// The flexible, pre-shaped catheter and the composite coil-inside-catheter
// model (physics/catheter.h, deployment.h). References: hollow-circle
// section formulas, the exact geometry of circular arcs, the moment balance
// of two coaxial beams forced onto one centre line (k = (EI_1 k_1 + EI_2 k_2)
// / (EI_1 + EI_2)), the closed form of the paper's normalised quaternion sum
// for coaxial rotations, the axial compliance L / (EA_1 + EA_2) of two
// coaxial bars, and conservation of the coil's length and mass.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "support/coil_spec.h"
#include "support/refusal.h"
#include "physics/catheter.h"
#include "physics/deployment.h"
#include "physics/run.h"
#include "physics/integrator.h"

namespace coilsim {
namespace {

constexpr double kDeg = M_PI / 180;

// The test catheter: OD 0.6 / ID 0.42 mm polymer (E 0.3 GPa), 2 mm held,
// 10 mm free, 0.5 mm beams; a 90 deg tip of radius 4 mm (6.28 mm of arc).
CatheterDef testCatheter(CatheterShape::Type type, double angle, CompositeWeighting rule) {
  CatheterDef c;
  c.flexible = true;
  c.material = {0.3e9, shearModulusOf(0.3e9, 0.4), 1100};
  c.outerRadius = 0.3e-3;
  c.innerRadius = 0.21e-3;
  c.shape = {type, angle, 0.004};
  c.heldLength = 0.002;
  c.freeLength = 0.010;
  c.beams = 24;
  c.weighting = rule;
  return c;
}

struct Rig {
  Model model;
  Deployment dep;
  State state;
};

// A 30 mm coil (wire radius 0.15 mm) that fills the 12 mm catheter when
// nothing of it is out. `rest` straight unless a helix diameter is given.
Rig makeRig(const CatheterDef& cath, double coilYoung, double deployed, double helixDiameter = 0,
            std::vector<EffectUse> effects = {}) {
  ModelDef def;
  def.gravity = Vec3::Zero();
  def.damping.massCoeff = 60.0;
  def.timeStep = 1e-3;
  def.effects = std::move(effects);
  DeploymentDef d;
  d.coil = test::wireSpec(0.03, helixDiameter > 0 ? test::helixRest(helixDiameter, 0.0005) : RestShapeDef{}, coilYoung, 0.39, 21450,
                    0.15e-3);
  d.coilBeams = 60;
  d.tip.position = Vec3(0.001, 0.002, 0.003);
  d.tip.direction = Vec3(0, 1, 0);
  d.tip.normal = Vec3(0, 0, 1);
  d.catheter = cath;
  d.initialDeployed = deployed;
  Rig r;
  def.device = d;
  r.model = compileModel(def);
  r.dep = *r.model.device;
  r.state = makeState(r.model);
  resetDevice(r.model, r.state, deployed, 0.0);
  return r;
}

void run(Rig& r, const std::vector<TimedCommand>& commands, double seconds) {
  const TimelineRun t = runTimeline(r.model, r.state, commands, seconds);
  ASSERT_TRUE(t.ok()) << t.failure->message();
}

double bendingStiffness(const Material& m, const Section& s) { return m.youngModulus * s.iy; }

TEST(CatheterTest, TubeSectionMatchesTheHollowCircleFormulas) {
  const Section t = tubeSection(0.3e-3, 0.21e-3, 0.4);
  EXPECT_NEAR(t.area, M_PI * (0.09e-6 - 0.0441e-6), 1e-18);
  EXPECT_NEAR(t.iy, M_PI / 64 * (std::pow(0.6e-3, 4) - std::pow(0.42e-3, 4)), 1e-24);
  EXPECT_DOUBLE_EQ(t.torsion, 2 * t.iy);
  const Section solid = tubeSection(0.3e-3, 0.0, 0.4), circle = circularSection(0.3e-3, 0.4);
  EXPECT_DOUBLE_EQ(solid.shearFactor, circle.shearFactor);
  // Thin-walled limit of Cowper's factor: 2 (1 + nu) / (4 + 3 nu).
  EXPECT_NEAR(tubeSection(1.0, 0.9999, 0.3).shearFactor, 2 * 1.3 / 4.9, 1e-4);
}

TEST(CatheterTest, PreShapedRestCurvesEndWhereTheArcsPutThem) {
  const double S = 0.012, R = 0.004;
  // 90 deg: a straight stretch of S - R pi/2, then a quarter circle bending to +y.
  const RestCurve a = makeCatheterRest({CatheterShape::Type::Angled, 90 * kDeg, R}, S, 24);
  const double straight = S - R * M_PI / 2;
  EXPECT_NEAR((a.points.back() - Vec3(straight + R, R, 0)).norm(), 0, 1e-15);
  EXPECT_NEAR((a.frames.back() * Vec3::UnitX() - Vec3::UnitY()).norm(), 0, 1e-15);
  // Nodes are equally spaced in arc length: chords 2 R sin(ds / 2R) in the arc.
  const double ds = S / 24;
  EXPECT_NEAR((a.points[24] - a.points[23]).norm(), 2 * R * std::sin(ds / (2 * R)), 1e-15);
  EXPECT_NEAR((a.points[1] - a.points[0]).norm(), ds, 1e-15);
  // S: two opposite 45 deg bends: the tip is parallel to the base, offset by 2 R (1 - cos 45).
  const RestCurve s = makeCatheterRest({CatheterShape::Type::S, 45 * kDeg, R}, S, 24);
  EXPECT_NEAR((s.frames.back() * Vec3::UnitX() - Vec3::UnitX()).norm(), 0, 1e-14);
  EXPECT_NEAR(s.points.back().y(), 2 * R * (1 - std::cos(M_PI / 4)), 1e-15);
  // J: a half turn comes back along -x, 2 R to the side.
  const RestCurve j = makeCatheterRest({CatheterShape::Type::J, 180 * kDeg, R}, 0.02, 40);
  EXPECT_NEAR((j.frames.back() * Vec3::UnitX() + Vec3::UnitX()).norm(), 0, 1e-14);
  EXPECT_NEAR(j.points.back().y(), 2 * R, 1e-15);
  EXPECT_THROW(makeCatheterRest({CatheterShape::Type::J, 180 * kDeg, R}, 0.01, 20), std::invalid_argument);
}

TEST(CatheterTest, BlendedRestRotationsMatchTheirClosedForms) {
  // Two coaxial rest rotations a1, a2 with weights w1, w2:
  //  moment balance (EI):   phi = (w1 a1 + w2 a2) / (w1 + w2)
  //  paper (normalised sum): tan(phi / 2) = (w1 sin(a1/2) + w2 sin(a2/2)) / (w1 cos(a1/2) + w2 cos(a2/2))
  const Vec3 axis = Vec3(1, 2, -0.5).normalized();
  const double a1 = 0.7, a2 = -0.3, w1 = 2.0, w2 = 5.0;
  const Quat q1(Eigen::AngleAxisd(a1, axis)), q2(Eigen::AngleAxisd(a2, axis));
  const Vec3 ei = quatLog(blendRestRotation(q1, q2, w1, w2, CompositeWeighting::BendingStiffness));
  const Vec3 e = quatLog(blendRestRotation(q1, q2, w1, w2, CompositeWeighting::YoungModulus));
  const double balance = (w1 * a1 + w2 * a2) / (w1 + w2);
  const double paper = 2 * std::atan2(w1 * std::sin(a1 / 2) + w2 * std::sin(a2 / 2),
                                      w1 * std::cos(a1 / 2) + w2 * std::cos(a2 / 2));
  EXPECT_NEAR((ei - balance * axis).norm(), 0, 1e-14);
  EXPECT_NEAR((e - paper * axis).norm(), 0, 1e-14);
  EXPECT_GT(std::abs(balance - paper), 1e-3) << "the two rules must differ for this test to tell them apart";
}

// The coil pulled into a soft 90 deg tip straightens it. At rest with no
// load the composite chain takes its blended rest shape, so the tip angle is
// the sum of the blended element rotations: with the EI rule exactly
// 90 deg EI_c / (EI_c + EI_k) (moment balance of two coaxial beams); with
// the paper's E rule the per-element closed form above, summed.
double straightenedTipAngle(CompositeWeighting rule, double& expected, double& restAngle) {
  const CatheterDef cath = testCatheter(CatheterShape::Type::Angled, 90 * kDeg, rule);
  Rig r = makeRig(cath, 7.5e9, 0.03);  // coil fully out: the catheter empty and at its rest shape
  restAngle = catheterTip(r.model, r.state).angle;
  // Pull 25 mm back in (the catheter fills: 12 mm), then let it settle.
  run(r, {{0, {DeviceCommand::Kind::Pull, 0.025, 0.025}}}, 2.5);
  EXPECT_NEAR(r.state.device.deployed, 0.005, 1e-12);
  const Section sc = r.dep.catheterSection, sk = r.dep.section;
  const double wc = rule == CompositeWeighting::BendingStiffness ? bendingStiffness(cath.material, sc)
                                                                 : cath.material.youngModulus;
  const double wk = rule == CompositeWeighting::BendingStiffness ? bendingStiffness(r.dep.material, sk)
                                                                 : r.dep.material.youngModulus;
  // Catheter element angles from the arc's geometry: curvature 1/R over the
  // part of each element within the arc [S - R pi/2, S].
  const double S = 0.012, R = 0.004, arcStart = S - R * M_PI / 2, ds = S / 24;
  expected = 0;
  for (int e = 0; e < 24; ++e) {
    const double a = std::max(0.0, std::min((e + 1) * ds, S) - std::max(e * ds, arcStart)) / R;
    expected += rule == CompositeWeighting::BendingStiffness
                    ? wc * a / (wc + wk)
                    : 2 * std::atan2(wc * std::sin(a / 2), wc * std::cos(a / 2) + wk);
  }
  return catheterTip(r.model, r.state).angle;
}

TEST(CatheterTest, StiffCoilStraightensASoftNinetyDegreeTipAsMomentBalancePredicts) {
  double expected = 0, rest = 0;
  const double angle = straightenedTipAngle(CompositeWeighting::BendingStiffness, expected, rest);
  std::printf("[ measured ] 90 deg tip with the coil inside (EI rule): %.4f deg, moment balance %.4f deg\n",
              angle / kDeg, expected / kDeg);
  EXPECT_NEAR(rest, 90 * kDeg, 1e-9) << "the empty catheter must keep its 90 deg shape";
  EXPECT_LT(expected, 45 * kDeg) << "the platinum coil is the stiffer: it must straighten the tip past halfway";
  EXPECT_NEAR(angle, expected, 1e-4 * expected);
}

TEST(CatheterTest, PapersYoungModulusWeightingMatchesItsClosedForm) {
  double expected = 0, rest = 0;
  const double angle = straightenedTipAngle(CompositeWeighting::YoungModulus, expected, rest);
  std::printf("[ measured ] 90 deg tip with the coil inside (E rule): %.4f deg, closed form %.4f deg\n",
              angle / kDeg, expected / kDeg);
  EXPECT_NEAR(angle, expected, 1e-4 * expected);
}

TEST(CatheterTest, CompositeShapeOfASoftCoilFollowsTheCatheterCentreLine) {
  // A soft helical coil (4 mm loops) fills a 90 deg catheter. Per element the
  // blended rotation differs from the catheter's by w_k |theta_k - theta_c|
  // with w_k = EI_k / (EI_c + EI_k): over the free length S_f the centre line
  // moves by at most w_k (kappa_k + kappa_c) S_f^2.
  const CatheterDef cath = testCatheter(CatheterShape::Type::Angled, 90 * kDeg, CompositeWeighting::BendingStiffness);
  auto deviation = [&](double coilYoung, double& bound) {
    Rig r = makeRig(cath, coilYoung, 0.0, 0.004);
    run(r, {}, 0.3);
    const RodModel& rm = r.model.rods[r.dep.catheterRod];  // the catheter's own rest centre line
    double worst = 0;
    for (int i = 0; i <= r.dep.tipNode; ++i)
      worst = std::max(worst, (r.state.rods[r.dep.chainRod].x[i] - rm.restPoints[i]).norm());
    const double ec = bendingStiffness(cath.material, r.dep.catheterSection);
    const double ek = bendingStiffness(r.dep.material, r.dep.section);
    bound = ek / (ec + ek) * (1 / 0.002 + 1 / 0.004) * 0.01 * 0.01;
    return worst;
  };
  double softBound = 0, stiffBound = 0;
  const double soft = deviation(1.5e6, softBound), stiff = deviation(7.5e9, stiffBound);
  std::printf("[ measured ] composite vs catheter centre line: soft coil %.3g m (bound %.3g), stiff coil %.3g m\n",
              soft, softBound, stiff);
  EXPECT_LT(soft, softBound);
  EXPECT_LT(softBound, 1e-4) << "a soft coil must leave the catheter's shape within 0.1 mm";
  EXPECT_GT(stiff, 10 * softBound) << "a stiff helix must move it, or the test cannot tell";
}

// Pushes the coil's distal tip back along -direction with a constant force.
class TipResistance final : public Effect {
 public:
  explicit TipResistance(Vec3 f) : f_(f) {}
  std::string_view name() const override { return "tip_resistance"; }
  std::string_view description() const override { return "test: a force on the last node of the coil"; }
  void apply(const EffectContext& c, std::span<const double>, RodForces& out) const override {
    if (c.rod.name == "coil") out.force[c.state.activeNodes - 1].head<3>() += c.loadFactor * f_;
  }

 private:
  Vec3 f_;
};

TEST(CatheterTest, ResistanceAtTheTipKicksTheCatheterBackByItsAxialCompliance) {
  // A straight catheter full of straight coil, 5 mm out; a force F opposes the
  // push at the coil's tip. It reaches the catheter through the partial beam;
  // the free catheter (composite throughout) shortens by F L_free / (EA_c + EA_k).
  const CatheterDef cath = testCatheter(CatheterShape::Type::Straight, 0, CompositeWeighting::BendingStiffness);
  const double F = 0.05;
  const TipResistance resist(-F * Vec3(0, 1, 0));
  Rig r = makeRig(cath, 7.5e9, 0.005, 0, {EffectUse{&resist, {}, true}});
  run(r, {}, 1.0);
  const double ea = cath.material.youngModulus * r.dep.catheterSection.area + r.dep.material.youngModulus * r.dep.section.area;
  const double expected = F * cath.freeLength / ea;
  const double kick = catheterTip(r.model, r.state).kickback;
  std::printf("[ measured ] kickback %.4g m, axial compliance predicts %.4g m\n", kick, expected);
  EXPECT_NEAR(kick, expected, 0.01 * expected);
}

TEST(CatheterTest, CoilLengthAndMassAreConservedThroughDeployRetractDeployInAFlexibleCatheter) {
  const CatheterDef cath = testCatheter(CatheterShape::Type::Angled, 90 * kDeg, CompositeWeighting::BendingStiffness);
  Rig r = makeRig(cath, 7.5e9, 0.0, 0.004);
  const double L = 0.03, mass = r.dep.material.density * r.dep.section.area * L;
  double worstL = 0, worstM = 0;
  using K = DeviceCommand::Kind;
  const std::vector<std::pair<double, DeviceCommand>> phases = {
      {1.0, {K::Push, 0.02, 0.02}}, {0.8, {K::Pull, 0.02, 0.015}}, {1.3, {K::Push, 0.02, 0.025}}};
  for (const auto& [seconds, cmd] : phases) {
    ASSERT_EQ(coilsim::test::refusal(command(r.model, r.state, cmd)), "");
    for (int s = 0; s < int(std::lround(seconds / 1e-3)); ++s) {
      ASSERT_TRUE(advance(r.model, r.state).ok()) << "t = " << r.state.time;
      worstL = std::max(worstL, std::abs(representedCoilLength(r.model, r.state) / L - 1));
      worstM = std::max(worstM, std::abs(representedCoilMass(r.model, r.state) / mass - 1));
    }
  }
  EXPECT_NEAR(r.state.device.deployed, L, 1e-12);
  std::printf("[ measured ] flexible catheter: worst length error %.3g, mass error %.3g\n", worstL, worstM);
  EXPECT_LT(worstL, 1e-12);
  EXPECT_LT(worstM, 1e-12);
  // Fully out, the coil is rest helix material again: its centre line is as long as its rest.
  const RodState& c = r.state.rods[r.dep.chainRod];
  double polygon = 0, rest = 0;
  for (int e = r.dep.tipNode; e + 1 < c.activeNodes; ++e)
    polygon += (c.x[e + 1] - c.x[e]).norm(), rest += c.beams[e].length;
  EXPECT_NEAR(polygon / rest, 1.0, 1e-4);
}

TEST(CatheterTest, BadCatheterDefinitionsAreRefused) {
  ModelDef def;
  DeploymentDef d;
  d.coil = test::wireSpec(0.03, RestShapeDef{}, 7.5e9, 0.39, 21450, 0.15e-3);
  d.coilBeams = 30;
  d.tip.normal = Vec3(0, 0, 1);
  d.catheter = testCatheter(CatheterShape::Type::J, 180 * kDeg, CompositeWeighting::BendingStiffness);
  EXPECT_THROW(addDeployment(d, def), std::invalid_argument) << "a J of 12.6 mm arc in 10 mm of free catheter";
  d.catheter = testCatheter(CatheterShape::Type::Straight, 0, CompositeWeighting::BendingStiffness);
  d.catheter.innerRadius = d.catheter.outerRadius;
  EXPECT_THROW(addDeployment(d, def), std::invalid_argument) << "a tube with no wall";
}

}  // namespace
}  // namespace coilsim
