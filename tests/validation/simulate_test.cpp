// What a stage simulation reports (validation/simulate.h): a stage that
// cannot be simulated carries the Failure physics gave, and the comparison
// carries it on. References: a coil with a negative Young's modulus, which
// no rod can have (physics refuses it as a bad definition naming the
// quantity), against the same coil with its real modulus, which simulates.
#include "validation/simulate.h"

#include <gtest/gtest.h>

#include "validation/compare.h"

namespace coilsim::validation {
namespace {

Measurement shortHelix() {
  Measurement m;
  m.name = "short helix";
  m.coil.length = 0.020;
  m.coil.wireRadius = 0.1e-3;
  m.coil.density = 21450;
  m.coil.rest.type = RestShapeDef::Type::Helix;
  m.coil.rest.loopDiameter = 6e-3;
  m.coil.rest.pitch = 4e-3;
  m.coil.youngModulus = 6e9;
  m.coil.poissonRatio = 0.39;
  m.tip.direction = Vec3::UnitX();
  m.tip.normal = Vec3::UnitZ();
  Stage s;
  s.name = "8 mm";
  s.deployed = 0.008;
  // A measured centre line along the exit direction (only compare() reads it).
  for (int i = 0; i <= 8; ++i) s.centerline.push_back(Vec3(1e-3 * i, 0, 0));
  s.pointSigma = 0.05e-3;
  m.stages.push_back(s);
  return m;
}

TEST(StageSimulator, AModelPhysicsRefusesIsEveryStagesFailure) {
  const Measurement m = shortHelix();
  StageSimulator sim(m);
  ModelParams bad = ModelParams::nominal(m);
  bad.coil.youngModulus = -1e9;
  const std::vector<StageSim> runs = sim.run(bad);
  ASSERT_EQ(runs.size(), 1u);
  ASSERT_FALSE(runs[0].ok());
  EXPECT_EQ(runs[0].failure->kind, FailureKind::BadDefinition);
  EXPECT_EQ(runs[0].failure->quantity, "Young's modulus") << runs[0].message();
  EXPECT_EQ(runs[0].failure->value, -1e9);
  EXPECT_EQ(runs[0].message(), describe(*runs[0].failure));
  const std::vector<StageComparison> compared = Comparison(m).compare(runs);
  ASSERT_FALSE(compared[0].ok());
  EXPECT_EQ(compared[0].message(), runs[0].message());

  const std::vector<StageSim> good = sim.run(ModelParams::nominal(m));
  ASSERT_TRUE(good[0].ok()) << good[0].message();
  EXPECT_EQ(good[0].message(), "");
  EXPECT_FALSE(good[0].x.empty());
}

}  // namespace
}  // namespace coilsim::validation
