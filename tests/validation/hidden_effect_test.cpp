// The workbench on data with one hidden effect, made by coilsim's own model
// (a finer discretisation than the workbench fits with), a nominal E 25 %
// off, uneven sampling and 0.1 mm noise. Reference: the generator's truth.
#include <gtest/gtest.h>

#include <map>

#include "validation/diagnose.h"
#include "validation/generate.h"

namespace coilsim::validation {
namespace {

constexpr double kTrueE = 5.6e9, kNominalE = 7.0e9, kSigma = 0.1e-3;

Measurement skeleton() {
  Measurement m;
  m.name = "synthetic";
  m.coil.length = 0.080;
  m.coil.wireRadius = 0.15e-3;
  m.coil.massPerLength = 21450 * M_PI * 0.15e-3 * 0.15e-3;
  m.coil.rest.type = RestShapeDef::Type::Helix;
  m.coil.rest.loopDiameter = 8e-3;
  m.coil.rest.pitch = 5e-3;
  m.coil.youngModulus = kNominalE;
  m.coil.hasYoungModulus = true;
  m.coil.poissonRatio = 0.39;
  m.coil.hasPoissonRatio = true;
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

ModelParams truth(const Measurement& m) {
  ModelParams p = ModelParams::nominal(m);
  p.youngModulus = kTrueE;
  return p;
}

SimOptions coarse() { return {2e-3, 2e-3, 1e-3}; }

struct Outcome {
  Diagnosis d;
  std::vector<double> baseError;
};

Outcome run(const Measurement& m) {
  StageSimulator sim(m, coarse());
  Comparison cmp(m);
  Outcome o;
  o.d = diagnose(sim, cmp, ModelParams::nominal(m), {});
  for (const auto& s : o.d.baselineStages) o.baseError.push_back(s.metrics.stageError);
  return o;
}

void print(const std::string& what, const Outcome& o) {
  std::printf("%s: E %.3f +- %.3f GPa; base errors", what.c_str(), o.d.baseline.fitted[0].value / 1e9,
              o.d.baseline.fitted[0].sigma / 1e9);
  for (double e : o.baseError) std::printf(" %.4f", e);
  std::printf("\n  %s\n  %s\n", o.d.fingerprint.summary.c_str(), o.d.verdict.c_str());
  for (const auto& c : o.d.candidates) {
    std::printf("  %-20s screen %.3f explained %.3f sig %d refit %d %s |", c.effect.c_str(), c.screenedFraction,
                c.explainedFraction, c.significant, c.refitted, c.note.c_str());
    for (const auto& f : c.fit.fitted) std::printf(" %s=%.4g+-%.3g", f.name.c_str(), f.value / f.toSI, f.sigma / f.toSI);
    for (double e : c.stageErrorAfter) std::printf(" %.4f", e);
    std::printf("\n");
  }
}

TEST(HiddenEffect, Explore) {
  const Measurement sk = skeleton();
  GenerateOptions g;
  g.sigma = kSigma;
  {
    const Measurement m = generateMeasurement(sk, truth(sk), g);
    print("control", run(m));
  }
  {
    ModelParams t = truth(sk);
    t.effects.push_back(EffectRegistry::global().use("gravity_tilt"));
    t.effects.back().set("tilt_a_deg", 12 * M_PI / 180);
    t.effects.back().set("tilt_b_deg", -8 * M_PI / 180);
    print("gravity_tilt", run(generateMeasurement(sk, t, g)));
  }
  {
    ModelParams t = truth(sk);
    t.effects.push_back(EffectRegistry::global().use("catheter_compliance"));
    t.effects.back().set("bending_stiffness_n_mm2", 1e-6);
    print("catheter_compliance", run(generateMeasurement(sk, t, g)));
  }
  {
    Measurement d = sk;
    d.mediumDensity = 1000, d.mediumViscosity = 1.0;
    Stage st;
    st.name = "push";
    st.deployed = 0.05;
    st.pushHistory = {{0.0, 0.0, 0.0}, {1.0, 0.05, 0.0}};
    st.captureTime = 1.0;
    d.stages.push_back(st);
    ModelParams t = truth(d);
    t.effects.push_back(EffectRegistry::global().use("drag"));
    t.effects.back().set("viscosity_pa_s", 1.0);
    print("drag", run(generateMeasurement(d, t, g)));
  }
}

}  // namespace
}  // namespace coilsim::validation
