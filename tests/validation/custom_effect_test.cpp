// A physical effect defined only in this test (a steady sideways flow),
// registered by name exactly as the README's "Adding a physical effect"
// shows, hidden in synthetic data: with it switched on and fitted the error
// falls to the control level and its magnitude is recovered; diagnose,
// given it as a candidate, ranks it first. Reference: the generator's truth.
#include <gtest/gtest.h>

#include "physics/model.h"
#include "physics/state.h"
#include "validation/diagnose.h"
#include "validation/generate.h"

namespace coilsim {
namespace {

// The whole new effect: a name, its parameters with units and bounds, its force.
constexpr ParamSpec kSideFlowParams[] = {
    {"force_mn_per_m", "mN/m", "drag of a steady sideways flow per length of coil", 1.0, 0.0, 1000.0, 1e-3},
};

class SideFlow final : public Effect {
 public:
  std::string_view name() const override { return "test_side_flow"; }
  std::string_view description() const override { return "steady sideways flow (+y) pushing the coil"; }
  std::span<const ParamSpec> params() const override { return kSideFlowParams; }
  void apply(const EffectContext& c, std::span<const double> p, RodForces& out) const override {
    for (int i = 0; i < c.state.activeNodes; ++i)
      out.force[i].head<3>() += c.loadFactor * p[0] * c.state.nodes[i].length * Vec3::UnitY();
  }
};

}  // namespace

namespace validation {
namespace {

constexpr double kE = 5.6e9, kWire = 0.1e-3, kSigma = 0.05e-3, kTrueForce = 1.5e-3;  // N/m

Measurement skeleton() {
  Measurement m;
  m.name = "side flow";
  m.coil.length = 0.080;
  m.coil.wireRadius = kWire;
  m.coil.density = 21450;  // weight 6.6 mN/m: the flow is 23 % of it
  m.coil.rest.type = RestShapeDef::Type::Helix;
  m.coil.rest.loopDiameter = 8e-3;
  m.coil.rest.pitch = 5e-3;
  m.coil.youngModulus = 1.2 * kE;
  m.coil.poissonRatio = 0.39;
  m.tip.direction = Vec3::UnitX();
  m.tip.normal = Vec3::UnitZ();
  for (double l : {0.025, 0.050, 0.075}) {
    Stage s;
    s.name = "l = " + std::to_string(int(l * 1e3)) + " mm";
    s.deployed = l;
    m.stages.push_back(s);
  }
  return m;
}

std::vector<double> stageErrors(StageSimulator& sim, const Comparison& cmp, const ModelParams& p) {
  std::vector<double> e;
  for (const auto& s : cmp.compare(sim.run(p, true))) e.push_back(s.metrics.stageError);
  return e;
}

TEST(CustomEffect, RegisteredInTheTestMakesTheErrorFall) {
  // The one registration line.
  if (!EffectRegistry::global().find("test_side_flow")) EffectRegistry::global().add(std::make_unique<SideFlow>());

  const Measurement sk = skeleton();
  ModelParams truth = ModelParams::nominal(sk);
  truth.coil.youngModulus = kE;
  GenerateOptions g;
  g.sigma = kSigma;
  const Measurement control = generateMeasurement(sk, truth, g);
  truth.effects.push_back(EffectRegistry::global().use("test_side_flow"));
  truth.effects.back().set("force_mn_per_m", kTrueForce);
  const Measurement m = generateMeasurement(sk, truth, g);
  const SimOptions coarse{2e-3, 2e-3, 1e-3};

  // The control's level: the base model with E fitted on data without the flow.
  StageSimulator csim(control, coarse);
  Comparison ccmp(control);
  FitOptions fe;
  fe.params = {"young_modulus_gpa"};
  const FitResult cf = identify(csim, ccmp, ModelParams::nominal(control), fe);
  ASSERT_TRUE(cf.ok) << cf.message;
  const std::vector<double> controlErr = stageErrors(csim, ccmp, cf.params);

  StageSimulator sim(m, coarse);
  Comparison cmp(m);
  const FitResult base = identify(sim, cmp, ModelParams::nominal(m), fe);
  ASSERT_TRUE(base.ok) << base.message;
  const std::vector<double> before = stageErrors(sim, cmp, base.params);

  ModelParams start = base.params;
  start.effects.push_back(EffectRegistry::global().use("test_side_flow"));
  start.effects.back().set("force_mn_per_m", 0.0);
  FitOptions fw;
  fw.params = {"young_modulus_gpa", "test_side_flow.force_mn_per_m"};
  const FitResult with = identify(sim, cmp, start, fw);
  ASSERT_TRUE(with.ok) << with.message;
  const std::vector<double> after = stageErrors(sim, cmp, with.params);

  for (size_t k = 0; k < before.size(); ++k) {
    std::printf("%s: control %.4f, base %.4f, with the flow %.4f\n", m.stages[k].name.c_str(), controlErr[k], before[k], after[k]);
    EXPECT_LE(after[k], 1.5 * controlErr[k]);
  }
  double worst = 0;
  for (size_t k = 0; k < before.size(); ++k) worst = std::max(worst, before[k] / after[k]);
  EXPECT_GT(worst, 2.0) << "the error should fall clearly once the flow is on";
  const FittedValue& f = with.fitted[1];
  std::printf("force %.4g +- %.2g mN/m (truth %.4g)\n", f.value * 1e3, f.sigma * 1e3, kTrueForce * 1e3);
  EXPECT_LE(std::abs(f.value - kTrueForce), 3.0 * f.sigma);

  // Diagnose, given the new effect as a candidate beside a built-in one, ranks it first.
  DiagnoseOptions o;
  o.candidates = {candidateFor("test_side_flow", m), candidateFor("catheter_compliance", m)};
  o.refitTop = 1;
  const Diagnosis d = diagnose(sim, cmp, ModelParams::nominal(m), o);
  ASSERT_TRUE(d.ok) << d.message;
  EXPECT_EQ(d.candidates.front().effect, "test_side_flow") << d.verdict;
  EXPECT_TRUE(d.candidates.front().significant) << d.verdict;
}

}  // namespace
}  // namespace validation
}  // namespace coilsim
