// stageJitter on a response that is smooth by construction: static stages
// of an open helix (no contact), reached by continuation. Reference: a
// smooth response cancels in the second difference to order d^2. Linear
// sag goes as 1/E, and 1/E over E exp(-d, 0, d) has the second difference
// (e^d - 2 + e^-d) / E = d^2 (1 + d^2 / 12) / E; so each node's second
// difference is about d^2 times its sag, and the sag is twice the node's
// move when E doubles. The jitter must stay within d^2 times that move (a
// factor 2 for the rod's geometric nonlinearity), whatever the centres.
#include <gtest/gtest.h>

#include <cmath>

#include "validation/compare.h"
#include "validation/fit_jitter.h"
#include "validation/generate.h"
#include "validation/params.h"

namespace coilsim::validation {
namespace {

Measurement openHelix() {
  Measurement m;
  m.name = "open helix";
  m.coil.length = 0.060;
  m.coil.wireRadius = 0.1e-3;
  m.coil.density = 21450;  // platinum-tungsten, kg/m^3
  m.coil.rest.type = RestShapeDef::Type::Helix;
  m.coil.rest.loopDiameter = 8e-3;
  m.coil.rest.pitch = 5e-3;
  m.coil.youngModulus = 6e9;
  m.coil.poissonRatio = 0.39;
  m.tip.direction = Vec3::UnitX();
  m.tip.normal = Vec3::UnitZ();
  for (double l : {0.030, 0.055}) {
    Stage s;
    s.name = "l = " + std::to_string(int(l * 1e3)) + " mm";
    s.deployed = l;
    m.stages.push_back(s);
  }
  GenerateOptions g;
  g.sigma = 0.05e-3;
  g.sim = {2e-3, 2e-3, 1e-3};
  return generateMeasurement(m, ModelParams::nominal(m), g);
}

TEST(FitJitter, SmoothStaticStagesStayWithinTheSecondOrderBound) {
  const Measurement m = openHelix();
  StageSimulator sim(m);
  const Comparison cmp(m);
  const ModelParams p = ModelParams::nominal(m);
  JitterOptions o;
  const std::vector<double> j = stageJitter(sim, cmp, p, youngModulusFit(), o);
  // The largest node move when E doubles from the largest centre (the most compliant state is at the smallest).
  ModelParams soft = p, stiff = p;
  soft.coil.youngModulus = p.coil.youngModulus * o.centres.front();
  stiff.coil.youngModulus = 2 * soft.coil.youngModulus;
  const std::vector<StageSim> a = sim.run(soft, false), b = sim.run(stiff, false);
  ASSERT_EQ(j.size(), m.stages.size());
  for (size_t k = 0; k < j.size(); ++k) {
    ASSERT_TRUE(a[k].ok() && b[k].ok()) << a[k].message() << b[k].message();
    double move = 0;
    for (size_t i = 0; i < a[k].x.size(); ++i) move = std::max(move, (a[k].x[i] - b[k].x[i]).norm());
    const double bound = 2 * o.step * o.step * 2 * move;
    std::printf("  stage %zu: jitter %.3g um, bound %.3g um (sag move %.3f mm)\n", k, j[k] * 1e6, bound * 1e6, move * 1e3);
    EXPECT_GT(move, 0.05e-3);  // the stage moves with E by more than a point sigma: the bound is not vacuous
    EXPECT_LE(j[k], bound) << "stage " << k;
  }
}

}  // namespace
}  // namespace coilsim::validation
