// identify's stop request (the panel's Stop button): the fit ends at the
// evaluation that asks, says "stopped" and reports no values; and its
// uncertainties for a parameter the data cannot see.
#include <gtest/gtest.h>

#include "validation/generate.h"
#include "validation/identify.h"

namespace coilsim::validation {
namespace {

Measurement straightCantilever() {
  Measurement m;
  m.name = "straight";
  m.coil.length = 0.03;
  m.coil.wireRadius = 0.1e-3;
  m.coil.density = 21450;
  m.coil.youngModulus = 7e9;
  m.tip.direction = Vec3::UnitX();
  m.tip.normal = Vec3::UnitZ();
  Stage s;
  s.name = "l = 30 mm";
  s.deployed = 0.03;
  m.stages.push_back(s);
  return m;
}

// The cantilever measured with E = 5 GPa (nominal 7), 0.02 mm noise.
Measurement measuredCantilever() {
  const Measurement sk = straightCantilever();
  ModelParams truth = ModelParams::nominal(sk);
  truth.coil.youngModulus = 5e9;
  GenerateOptions g;
  g.sigma = 0.02e-3;
  return generateMeasurement(sk, truth, g);
}

TEST(Identify, StopRequestEndsTheFitAtOnce) {
  const Measurement m = measuredCantilever();
  StageSimulator sim(m, {2e-3, 2e-3, 1e-3});
  Comparison cmp(m);
  FitOptions o;
  o.params = {"young_modulus_gpa"};
  int asked = 0;
  o.stop = [&] { return ++asked > 3; };
  const FitResult r = identify(sim, cmp, ModelParams::nominal(m), o);
  EXPECT_FALSE(r.ok);
  EXPECT_EQ(r.message, "stopped");
  EXPECT_EQ(r.evaluations, 3);
  EXPECT_EQ(r.history.size(), 3u);
  EXPECT_TRUE(r.fitted.empty());
  // Without the request the same fit runs to its end and finds E.
  o.stop = nullptr;
  const FitResult full = identify(sim, cmp, ModelParams::nominal(m), o);
  ASSERT_TRUE(full.ok) << full.message;
  EXPECT_GT(full.evaluations, 3);
  EXPECT_NEAR(full.fitted[0].value, 5e9, 0.05 * 5e9);
}

// Drag acts only while the coil moves: a static stage does not see the
// viscosity at all (its Jacobian column is zero). Its uncertainty is then
// infinite, not the pseudo-inverse's zero, while E keeps a finite one.
TEST(Identify, AParameterTheDataDoNotSeeIsNotIdentifiable) {
  const Measurement m = measuredCantilever();
  StageSimulator sim(m, {2e-3, 2e-3, 1e-3});
  Comparison cmp(m);
  ModelParams start = ModelParams::nominal(m);
  start.effects.push_back(effectFromFile("drag", m));
  FitOptions o;
  o.params = {"young_modulus_gpa", "drag.viscosity_pa_s"};
  const FitResult r = identify(sim, cmp, start, o);
  ASSERT_TRUE(r.ok) << r.message;
  ASSERT_EQ(r.fitted.size(), 2u);
  EXPECT_TRUE(r.fitted[0].identifiable);
  EXPECT_GT(r.fitted[0].sigma, 0);
  EXPECT_LT(r.fitted[0].sigma, 0.05 * 5e9);
  EXPECT_FALSE(r.fitted[1].identifiable);
  EXPECT_EQ(r.fitted[1].sigma, INFINITY);
}

}  // namespace
}  // namespace coilsim::validation
