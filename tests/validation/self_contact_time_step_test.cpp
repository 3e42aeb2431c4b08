// Time-step convergence of self_contact as the workbench switches it on
// (Diagnosable::held: frictionless, 5 N/mm) in a dynamic stage: a short
// coil whose loops land on one another (pitch = wire diameter, loops
// horizontal, gravity laying each on the one below), pushed out from 10 to
// 35 mm at 60 mm/s and captured 0.05 s after the push stops.
//
// Reference: the same stage without the contact. Richardson extrapolation
// over 1, 0.5 and 0.25 ms cannot serve: the rod's own dynamic stage is not
// in the asymptotic range at 1 ms (without any contact halving the step
// moves it by 0.027 then 0.023 mm, an observed order of 0.2; the release of
// each 2 mm beam at the catheter is a shock). What the contact must not do
// is add to that: halving the step may move the stage with the held
// contact by at most what it moves the stage without it, plus a tenth of
// the reference files' 0.05 mm point noise. The effect's defaults (50 N/mm,
// Coulomb 0.15 / 0.1) do not pass (0.25 mm: docs/validation.md, Limits),
// which is why the workbench holds other values.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "validation/diagnose.h"
#include "validation/simulate.h"

namespace coilsim::validation {
namespace {

constexpr double kWire = 0.1e-3, kPointSigma = 0.05e-3;

Measurement landingLoops() {
  Measurement m;
  m.name = "landing loops";
  m.coil.length = 0.040;
  m.coil.wireRadius = kWire;
  m.coil.density = 21450;  // platinum-tungsten, kg/m^3
  m.coil.rest.type = RestShapeDef::Type::Helix;
  m.coil.rest.loopDiameter = 8e-3;
  m.coil.rest.pitch = 2 * kWire;
  m.coil.youngModulus = 6.8e9;
  m.coil.poissonRatio = 0.39;
  m.tip.direction = Vec3::UnitX();
  m.tip.normal = Vec3::UnitY();
  Stage st;
  st.name = "push 60 mm/s";
  st.pushHistory = {{0.0, 0.010, 0.0}, {0.025 / 0.060, 0.035, 0.0}};
  st.deployed = 0.035;
  st.captureTime = 0.025 / 0.060 + 0.05;
  m.stages.push_back(st);
  return m;
}

// RMS node distance between the stage run at `h` and at h / 2, m.
double halvingChange(const Measurement& m, const ModelParams& p, double h) {
  std::vector<StageSim> r;
  for (const double step : {h, h / 2}) {
    SimOptions o;
    o.timeStep = step;
    StageSimulator sim(m, o);
    r.push_back(sim.run(p, false).front());
    EXPECT_TRUE(r.back().ok()) << r.back().message();
  }
  if (!r[0].ok() || !r[1].ok() || r[0].x.size() != r[1].x.size()) return INFINITY;
  double s = 0;
  for (size_t i = 0; i < r[0].x.size(); ++i) s += (r[0].x[i] - r[1].x[i]).squaredNorm();
  return std::sqrt(s / double(r[0].x.size()));
}

TEST(SelfContactTimeStep, HeldContactAddsNoTimeStepError) {
  const Measurement m = landingLoops();
  const ModelParams off = ModelParams::nominal(m);
  ModelParams held = off, defaults = off;
  held.effects.push_back(EffectRegistry::global().use("self_contact"));
  for (const auto& [param, value] : candidateFor("self_contact", m).held) held.effects.back().set(param, value);
  defaults.effects.push_back(EffectRegistry::global().use("self_contact"));
  for (const double h : {1e-3, 0.5e-3}) {
    const double dOff = halvingChange(m, off, h), dHeld = halvingChange(m, held, h);
    std::printf("  step %.2f ms halved: stage moves %.4f mm without contact, %.4f mm with the held contact, "
                "%.4f mm with the effect's defaults\n",
                h * 1e3, dOff * 1e3, dHeld * 1e3, halvingChange(m, defaults, h) * 1e3);
    EXPECT_LE(dHeld, dOff + 0.1 * kPointSigma) << "step " << h;
  }
}

}  // namespace
}  // namespace coilsim::validation
