// The workbench on data it did not make: the coil-measurement/1 files of
// tests/data/reference, written by the independent Cosserat rod of
// tests/reference (no code shared with src/), each with hidden effects and a
// nominal E 15-30 % off. References, all from that rod: the scenario's true
// E and hidden effects (refrod::referenceScenarios), and the error its own
// true model reaches on each file, computed here by running the rod with
// the true physics and putting its noise-free centre lines through the same
// comparison as coilsim's simulations.
//
// For every file with a hidden effect: forward selection names it first
// (both, in order, in the file with two), significantly; the final model's
// stage errors are within 1.5x of the true model's; E within 5 % or 3 sigma.
// Controls: nothing significant. Buoyancy, which a static file cannot
// separate from E, is found by the joint fit of the coil in water and in air.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cmath>
#include <map>
#include <optional>

#include "experiment.h"
#include "io/measurement.h"
#include "validation/diagnose.h"
#include "validation/joint.h"

namespace coilsim::validation {
namespace {

const std::string kDir = COILSIM_SOURCE_DIR "/tests/data/reference/";

const refrod::Scenario& scenario(const std::string& name) {
  static const std::vector<refrod::Scenario> all = refrod::referenceScenarios();
  for (const refrod::Scenario& s : all)
    if (s.name == name) return s;
  throw std::runtime_error("no reference scenario " + name);
}

// The stage errors the true model reaches on the file: the reference rod's
// noise-free centre lines compared like a simulation.
// `adequacyOut`, `nodesOut`: the true model's adequacy and node count per stage.
std::vector<double> trueModelErrors(const std::string& name, const Comparison& cmp, Adequacy* adequacyOut = nullptr,
                                    std::vector<size_t>* nodesOut = nullptr) {
  const std::vector<refrod::StageResult> truth = refrod::runExperiment(scenario(name));
  std::vector<StageSim> sims;
  for (const refrod::StageResult& r : truth) {
    StageSim s;
    s.x = r.nodesM;
    s.s = r.nodeS;
    sims.push_back(s);
  }
  std::vector<double> e;
  const auto cs = cmp.compare(sims);
  for (const StageComparison& c : cs) e.push_back(c.metrics.stageError);
  const Adequacy a = adequacy(cmp, cs);
  std::printf("  true model adequacy:");
  for (const auto& s : a.stages) std::printf(" %.2f/%.2f", s.reducedChi2, s.critical);
  std::printf("\n");
  if (adequacyOut) *adequacyOut = a;
  if (nodesOut)
    for (const StageComparison& c : cs) nodesOut->push_back(c.sim.size());
  return e;
}

struct Run {
  Measurement m;
  std::unique_ptr<StageSimulator> sim;
  std::unique_ptr<Comparison> cmp;
  Diagnosis d;
};

// `predict` false skips the prediction check's extra fit (the slow files:
// contacts, a dynamic stage), which the other files exercise.
std::unique_ptr<Run> diagnoseFile(const std::string& name, bool predict = true) {
  auto r = std::make_unique<Run>();
  r->m = io::readMeasurement(kDir + name + ".json");
  r->sim = std::make_unique<StageSimulator>(r->m);
  r->cmp = std::make_unique<Comparison>(r->m);
  DiagnoseOptions o;
  o.refitTop = 2;
  o.predict = predict;
  r->d = diagnose(*r->sim, *r->cmp, ModelParams::nominal(r->m), o);
  return r;
}

void print(const std::string& name, const Diagnosis& d, const std::vector<double>& trueErrors) {
  std::printf("%s: E %.4g +- %.3g GPa (regularised %.4g); %s\n", name.c_str(), d.baseline.fitted[0].value / 1e9,
              d.baseline.fitted[0].sigma / 1e9, d.regularisedBaseline.fitted[0].value / 1e9, d.verdict.c_str());
  for (const auto& c : d.candidates)
    std::printf("  %-20s screen %.3f explained %.3f sig %d %s\n", c.effect.c_str(), c.screenedFraction,
                c.explainedFraction, c.significant, c.note.c_str());
  for (const auto& s : d.selected) {
    std::printf("  selected %s (%.3f):", s.effect.c_str(), s.explainedFraction);
    for (const auto& f : s.result.fit.fitted) std::printf(" %s=%.4g+-%.3g", f.name.c_str(), f.value / f.toSI, f.sigma / f.toSI);
    std::printf("\n");
  }
  std::printf("  stage errors: base");
  for (const auto& s : d.baselineStages) std::printf(" %.4f", s.metrics.stageError);
  std::printf("; final");
  for (const auto& s : d.finalStages) std::printf(" %.4f", s.metrics.stageError);
  std::printf("; true model");
  for (double e : trueErrors) std::printf(" %.4f", e);
  std::printf("\n  adequacy:");
  for (const auto& s : d.adequacy.stages) std::printf(" %.2f/%.2f", s.reducedChi2, s.critical);
  std::printf(" %s\n  prediction: %s\n", d.adequacy.explained ? "explained" : "missing", d.prediction.message.c_str());
}

// The checks of the issue for a file whose hidden effects are `expected`,
// in order; forward selection may name nothing outside `hidden`. E must
// come within 5 % or `eSigmas` sigma of the truth.
// The 99.9 % bound of a reduced chi-square over `nodes` nodes were their 3
// coordinates independent terms with the noise floor's variance: the
// chi-square of n such terms is n +- sqrt(2n), so chi2 / n is 1 +- sqrt(2 / n).
double derivedChi2Bound(size_t nodes) { return 1 + 3.09 * std::sqrt(2 / (3.0 * double(nodes))); }

// `boundStage`: a stage whose reduced chi-square (final model and the
// reference's true model) must also stay under derivedChi2Bound.
void checkHidden(const std::string& name, const std::vector<std::string>& expected,
                 const std::vector<std::string>& hidden = {}, bool predict = true, double eSigmas = 3,
                 std::optional<size_t> boundStage = std::nullopt) {
  const auto r = diagnoseFile(name, predict);
  const Diagnosis& d = r->d;
  ASSERT_TRUE(d.ok) << d.message;
  Adequacy trueAdequacy;
  std::vector<size_t> trueNodes;
  const std::vector<double> truth = trueModelErrors(name, *r->cmp, &trueAdequacy, &trueNodes);
  if (boundStage) {
    const size_t k = *boundStage;
    ASSERT_LT(k, d.finalStages.size());
    const double bound = derivedChi2Bound(d.finalStages[k].sim.size());
    ASSERT_LT(k, trueNodes.size());
    const double trueBound = derivedChi2Bound(trueNodes[k]);
    std::printf("  stage %zu chi2_red: final %.2f (derived bound %.2f, bootstrap %.2f), true model %.2f (%.2f)\n", k,
                d.adequacy.stages[k].reducedChi2, bound, d.adequacy.stages[k].critical,
                trueAdequacy.stages[k].reducedChi2, trueBound);
    EXPECT_LE(d.adequacy.stages[k].reducedChi2, bound) << name << " stage " << k;
    EXPECT_LE(trueAdequacy.stages[k].reducedChi2, trueBound) << name << " stage " << k << ", true model";
  }
  print(name, d, truth);
  ASSERT_GE(d.selected.size(), expected.size()) << d.verdict;
  for (size_t k = 0; k < expected.size(); ++k) {
    EXPECT_EQ(d.selected[k].effect, expected[k]) << "step " << k << ": " << d.verdict;
    EXPECT_TRUE(d.selected[k].result.significant);
  }
  for (size_t k = expected.size(); k < d.selected.size(); ++k)
    EXPECT_NE(std::find(hidden.begin(), hidden.end(), d.selected[k].effect), hidden.end())
        << d.selected[k].effect << " was not hidden: " << d.verdict;
  EXPECT_TRUE(d.adequacy.explained) << d.adequacy.verdict;
  if (predict) {
    EXPECT_TRUE(d.prediction.done) << d.prediction.message;
  }
  ASSERT_EQ(d.finalStages.size(), truth.size());
  for (size_t k = 0; k < truth.size(); ++k)
    EXPECT_LE(d.finalStages[k].metrics.stageError, 1.5 * truth[k]) << name << " stage " << k;
  const FittedValue& E = d.selected.back().result.fit.fitted[0];
  ASSERT_EQ(E.name, "young_modulus_gpa");  // the scene key, diagnosis's default
  const double trueE = scenario(name).trueYoungGpa * 1e9;
  EXPECT_LE(std::abs(E.value - trueE), std::max(0.05 * trueE, eSigmas * E.sigma))
      << name << ": E " << E.value / 1e9 << " +- " << E.sigma / 1e9 << " GPa, true " << trueE / 1e9;
}

void checkControl(const std::string& name) {
  const auto r = diagnoseFile(name);
  const Diagnosis& d = r->d;
  ASSERT_TRUE(d.ok) << d.message;
  const std::vector<double> truth = trueModelErrors(name, *r->cmp);
  print(name, d, truth);
  EXPECT_TRUE(d.selected.empty()) << d.verdict;
  for (const auto& c : d.candidates) EXPECT_FALSE(c.significant) << c.effect;
  EXPECT_TRUE(d.implausible.empty()) << d.priorVerdict;
  EXPECT_TRUE(d.adequacy.explained) << d.adequacy.verdict;
  for (size_t k = 0; k < truth.size(); ++k)
    EXPECT_LE(d.baselineStages[k].metrics.stageError, 1.5 * truth[k]) << name << " stage " << k;
  const FittedValue& E = d.baseline.fitted[0];
  const double trueE = scenario(name).trueYoungGpa * 1e9;
  EXPECT_LE(std::abs(E.value - trueE), std::max(0.05 * trueE, 3 * E.sigma)) << name << ": E " << E.value / 1e9;
}

TEST(ReferenceFiles, Control1) { checkControl("control-1"); }
TEST(ReferenceFiles, Control2) { checkControl("control-2"); }
TEST(ReferenceFiles, TiltedBench) { checkHidden("tilted-bench", {"gravity_tilt"}); }
TEST(ReferenceFiles, CatheterTip) { checkHidden("catheter-tip", {"catheter_compliance"}); }
// The free E takes 3.9x its nominal to hold the loops up: the prior check
// flags it, and against the regularised baseline self_contact comes first.
TEST(ReferenceFiles, SelfContactStatic) {
  checkHidden("self-contact-static", {"self_contact"}, {}, false);
}
// Both, in order: the tube first, then the 4.5 deg tilt on top of it (on
// the 0.1 mm wire the tilt's sideways sag stays above the noise once the
// tube is in the model; docs/validation.md, "Two effects at once").
TEST(ReferenceFiles, TwoEffects) { checkHidden("two-effects", {"catheter_compliance", "gravity_tilt"}); }
// Drag and the 6 % upthrust of the glycerol-like medium: drag is found;
// the upthrust is a weight change E absorbs in one file.
TEST(ReferenceFiles, Drag) { checkHidden("drag", {"drag"}, {"buoyancy"}, false); }
// Loops landing on one another in a push captured 0.05 s after it stops,
// in water: self_contact first and significant (the workbench's contact
// held frictionless at 5 N/mm, Diagnosable::held), every stage within 1.5x
// of the true model; water's upthrust and drag may follow. The dynamic
// stage lands in stackings that change with E, so E comes from the static
// stages (validation/fit_staged.h): within 2 sigma of the true value.
//
// Its chi-square: the dynamic stage's 3 n node coordinates, were they
// independent with the noise floor's variance, give a reduced chi-square of
// 1 +- sqrt(2 / 3n) (chi-square of 3n terms: 3n +- sqrt(6n)), 99.9 % bound
// 1 + 3.09 sqrt(2 / 3n). The final model and the reference's own true model
// must both stay under it.
TEST(ReferenceFiles, SelfContactDynamic) {
  checkHidden("self-contact-dynamic", {"self_contact"}, {"buoyancy", "drag"}, false, 2, 2);
}

// Water alone: buoyancy is a 4.7 % weight change that E absorbs exactly in
// static stages, so the single file cannot name it. With the same coil in
// air, one E cannot fit both files; buoyancy at each file's declared medium
// removes the difference, and the joint E is the true one.
TEST(ReferenceFiles, BuoyancyWaterAndAir) {
  const auto water = diagnoseFile("buoyancy-water");
  ASSERT_TRUE(water->d.ok);
  for (const auto& c : water->d.candidates) {
    if (c.effect == "buoyancy") {
      EXPECT_NE(c.note.find("indistinguishable"), std::string::npos) << c.note;
    }
  }
  Measurement air = io::readMeasurement(kDir + "buoyancy-air.json");
  StageSimulator airSim(air);
  const Comparison airCmp(air);
  ModelParams a = ModelParams::nominal(air);
  const JointDiagnosis j = diagnoseJoint({{water->sim.get(), water->cmp.get(), ModelParams::nominal(water->m)},
                                          {&airSim, &airCmp, a}},
                                         {"young_modulus_gpa"}, {});
  ASSERT_TRUE(j.ok) << j.message;
  std::printf("joint: %s\n", j.verdict.c_str());
  ASSERT_FALSE(j.spread.empty());
  EXPECT_TRUE(j.spread[0].mustDiffer) << j.verdict;
  ASSERT_FALSE(j.effects.empty());
  EXPECT_EQ(j.effects.front().effect, "buoyancy");
  EXPECT_TRUE(j.effects.front().removesSpread);
  const double trueE = scenario("buoyancy-water").trueYoungGpa * 1e9;
  const FittedValue& E = j.effects.front().fit.fitted[0];
  EXPECT_LE(std::abs(E.value - trueE), std::max(0.05 * trueE, 3 * E.sigma)) << "joint E " << E.value / 1e9;
}

// The candidate itself, not the search: catheter_compliance set to the
// reference's true tube (free length, composite EI = tube + coil, tube
// mass, polymer Poisson ratio) with the true E reaches within 1.5x of the
// error of the reference's own true model on catheter-tip.
TEST(ReferenceFiles, CatheterComplianceAtTheTrueTube) {
  const std::string name = "catheter-tip";
  const Measurement m = io::readMeasurement(kDir + name + ".json");
  StageSimulator sim(m);
  const Comparison cmp(m);
  const refrod::Scenario& sc = scenario(name);
  ModelParams p = ModelParams::nominal(m);
  p.coil.youngModulus = sc.trueYoungGpa * 1e9;
  const double ro = sc.tube.outerDiameterMm / 2e3, ri = sc.tube.innerDiameterMm / 2e3;
  const double tubeEI = sc.tube.youngGpa * 1e9 * M_PI * (std::pow(ro, 4) - std::pow(ri, 4)) / 4;
  const double coilEI = p.coil.youngModulus * M_PI * std::pow(m.coil.wireRadius, 4) / 4;
  p.effects.push_back(EffectRegistry::global().use("catheter_compliance"));
  EffectUse& c = p.effects.back();
  c.set("segment_length_mm", sc.tube.lengthMm * 1e-3);
  c.set("bending_stiffness_n_mm2", tubeEI + coilEI);
  c.set("tube_mass_per_length_g_m", sc.tube.densityGcm3 * 1e3 * M_PI * (ro * ro - ri * ri));
  c.set("poisson_ratio", sc.tube.poisson);
  const std::vector<StageComparison> s = cmp.compare(sim.run(p, false));
  const std::vector<double> truth = trueModelErrors(name, cmp);
  for (size_t k = 0; k < truth.size(); ++k) {
    std::printf("  stage %zu: %.4f (true model %.4f)\n", k, s[k].metrics.stageError, truth[k]);
    EXPECT_LE(s[k].metrics.stageError, 1.5 * truth[k]) << "stage " << k;
  }
}

}  // namespace
}  // namespace coilsim::validation
