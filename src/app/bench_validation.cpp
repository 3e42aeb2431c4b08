// Timings of the validation workbench for `coilsim bench` (bench_validation.h).
#include "app/bench_validation.h"

#include <chrono>
#include <cstdio>

#include "io/units.h"
#include "validation/diagnose.h"
#include "validation/generate.h"

namespace coilsim {
namespace {

using namespace validation;

double secondsSince(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// A 3-stage measurement like the shared control file (120 mm helical coil,
// 8 mm loops, 5 mm pitch, wire radius 0.15 mm, stages at 30, 60, 100 mm,
// 0.1 mm noise, nominal E 25 % high), made here so the bench needs no data files.
Measurement benchMeasurement(bool hidden) {
  Measurement m;
  m.name = "bench";
  m.coil.length = 0.120;
  m.coil.wireRadius = 0.15e-3;
  m.coil.density = 21450;
  m.coil.rest.type = RestShapeDef::Type::Helix;
  m.coil.rest.loopDiameter = 8e-3;
  m.coil.rest.pitch = 5e-3;
  m.coil.youngModulus = 7.0e9;
  m.coil.poissonRatio = 0.39;
  m.tip.direction = Vec3::UnitX();
  m.tip.normal = Vec3::UnitZ();
  for (double l : {0.030, 0.060, 0.100}) {
    Stage s;
    s.name = std::to_string(int(units::mToMm(l))) + " mm";
    s.deployed = l;
    m.stages.push_back(s);
  }
  ModelParams truth = ModelParams::nominal(m);
  truth.coil.youngModulus = 5.6e9;
  // Two hidden effects make diagnose run its forward selection (a second
  // round of refits, the free fit of the selected model) as on a file
  // where something is missing: a compliant tube and a tilted bench.
  if (hidden) {
    truth.effects.push_back(EffectRegistry::global().use("catheter_compliance"));
    truth.effects.back().set("bending_stiffness_n_mm2", 8e-6);
    truth.effects.back().set("segment_length_mm", 12e-3);
    truth.effects.push_back(EffectRegistry::global().use("gravity_tilt"));
    truth.effects.back().set("tilt_a_deg", units::degToRad(-4.0));
    truth.effects.back().set("tilt_b_deg", units::degToRad(2.0));
  }
  GenerateOptions g;
  g.sim = {2e-3, 2e-3, 1e-3};
  return generateMeasurement(m, truth, g);
}

}  // namespace

void benchValidationFigures(const std::function<void(const std::string&, double)>& set, bool quick, bool json) {
  if (!json) std::fprintf(stderr, "bench: validation workbench (identify E, diagnose 5 candidates)...\n");
  const Measurement m = benchMeasurement(false);
  StageSimulator sim(m);  // the workbench's default discretisation (2 mm beams)
  const Comparison cmp(m);
  auto t0 = std::chrono::steady_clock::now();
  const int runs = quick ? 1 : 3;
  for (int k = 0; k < runs; ++k) sim.run(ModelParams::nominal(m), false);
  const double one = secondsSince(t0) / runs;
  FitOptions fo;
  fo.params = {youngModulusFit()};
  t0 = std::chrono::steady_clock::now();
  const FitResult f = identify(sim, cmp, ModelParams::nominal(m), fo);
  const double fit = secondsSince(t0);
  double diag = 0;
  if (!quick) {
    t0 = std::chrono::steady_clock::now();
    const Diagnosis d = diagnose(sim, cmp, ModelParams::nominal(m), {});
    diag = secondsSince(t0);
    if (!d.ok) std::fprintf(stderr, "bench: diagnosis failed: %s\n", d.message.c_str());
  }
  double diagHidden = 0;
  size_t found = 0;
  if (!quick) {
    const Measurement mh = benchMeasurement(true);
    StageSimulator simH(mh);
    const Comparison cmpH(mh);
    t0 = std::chrono::steady_clock::now();
    const Diagnosis d = diagnose(simH, cmpH, ModelParams::nominal(mh), {});
    diagHidden = secondsSince(t0);
    found = d.selected.size();
    if (!d.ok) std::fprintf(stderr, "bench: diagnosis with hidden effects failed: %s\n", d.message.c_str());
  }
  if (!f.ok) std::fprintf(stderr, "bench: identification failed: %s\n", f.message.c_str());
  set("validate_one_run_s", one);
  set("validate_identify_e_s", fit);
  set("validate_identify_e_over_one_run", fit / one);
  if (!quick) {
    set("validate_diagnose_5_s", diag);
    set("validate_diagnose_5_over_one_run", diag / one);
    set("validate_diagnose_2_hidden_s", diagHidden);
  }
  if (json) return;
  std::printf("validation workbench, 3-stage helix (120 mm coil, %d beams):\n", sim.beams());
  std::printf("  one simulation of the 3 stages (push from zero): %.3f s\n", one);
  std::printf("  identification of E: %.2f s = %.0f simulations (target < 10 s), %d evaluations\n", fit, fit / one, f.evaluations);
  if (!quick) {
    std::printf("  diagnosis of 5 candidates: %.2f s = %.0f simulations (target < 60 s)\n", diag, diag / one);
    std::printf("  the same with a tube and a tilt hidden (%zu of 2 selected): %.2f s (target < 60 s)\n", found,
                diagHidden);
  }
}

}  // namespace coilsim
