// Tests of the one failure type (src/physics/failure.cpp) as each part of
// the core reports it: every assertion compares what a failure names (rod,
// node or beam, quantity, value, limit, time) with the input the test itself
// put in, never with a number the code produced.
#include <gtest/gtest.h>

#include <cmath>
#include <optional>

#include "physics/failure.h"
#include "physics/integrator.h"
#include "physics/model.h"
#include "physics/run.h"
#include "support/helix_deployment.h"
#include "support/rod_models.h"

namespace coilsim::test {
namespace {

TEST(Failure, MessageNamesTheRodAndItsNodeOrBeam) {
  Failure f = badRod("coil", "speed 60 m/s exceeds 50 m/s (numerical blow-up)");
  EXPECT_EQ(f.message(), "rod 'coil': speed 60 m/s exceeds 50 m/s (numerical blow-up)");
  f.node = 3;
  EXPECT_EQ(f.where(), "rod 'coil' node 3");
  f.node = -1, f.beam = 2;
  EXPECT_EQ(f.message(), "rod 'coil' beam 2: speed 60 m/s exceeds 50 m/s (numerical blow-up)");
  EXPECT_EQ(badDefinition("effect 'drag'", "has 1 values for 2 parameters").message(),
            "effect 'drag': has 1 values for 2 parameters");
  EXPECT_EQ(badDefinition({}, "model has no rod").message(), "model has no rod");
}

TEST(Failure, DescribeSaysWhatKindOfFailureItWas) {
  Failure step = badRod("wire", "implicit matrix is not positive definite");
  step.kind = FailureKind::SolverFailure;
  step.time = 0.5;
  EXPECT_EQ(describe(step), "step refused at t = 0.500000 s: rod 'wire': implicit matrix is not positive definite");
  Failure statics = step;
  statics.kind = FailureKind::NotConverged;
  EXPECT_EQ(describe(statics), "static solve did not converge: rod 'wire': implicit matrix is not positive definite");
  Failure device;
  device.kind = FailureKind::DeviceRefusal;
  device.text = "the coil is fully deployed";
  EXPECT_EQ(describe(device), "refused: the coil is fully deployed");
  EXPECT_EQ(describe(badDefinition({}, "gravity is not finite")), "gravity is not finite");
}

TEST(Failure, CompileModelThrowsOneErrorNamingRodQuantityAndValue) {
  RodDef rod = clamped(straightRod(0.1, 4, steel(), circularSection(0.5e-3, kSteelPoisson)));
  rod.name = "wire";
  rod.material.youngModulus = -1;
  try {
    compileModel(modelOf({rod}));
    ADD_FAILURE() << "a negative Young's modulus was accepted";
  } catch (const PhysicsError& e) {
    const Failure& f = e.failure();
    EXPECT_EQ(f.kind, FailureKind::BadDefinition);
    EXPECT_EQ(f.rod, "wire");
    EXPECT_EQ(f.quantity, "Young's modulus");
    EXPECT_EQ(f.value, -1);
    EXPECT_EQ(std::string(e.what()), f.message());
    EXPECT_EQ(f.message(), "rod 'wire': Young's modulus must be a finite positive number, got -1.000000");
  }
  // Callers that catch std::invalid_argument still catch it.
  EXPECT_THROW(compileModel(modelOf({rod})), std::invalid_argument);
}

TEST(Failure, StaticSolveOfAFreeRodFailsNamingItAndLeavesTheState) {
  RodDef rod = straightRod(0.1, 4, steel(), circularSection(0.5e-3, kSteelPoisson));
  rod.name = "loose";
  const Model m = compileModel(modelOf({rod}, {"gravity"}, Vec3(0, 0, -9.81)));
  State s = makeState(m);
  const State before = s;
  const StaticReport rep = solveStatic(m, s);
  ASSERT_FALSE(rep.converged());
  EXPECT_EQ(rep.failure->kind, FailureKind::NotConverged);
  EXPECT_EQ(rep.failure->rod, "loose");
  EXPECT_EQ(rep.failure->quantity, "load factor");
  EXPECT_EQ(rep.failure->value, 0);  // refused before any load was applied
  EXPECT_EQ(s.rods[0].x, before.rods[0].x);
}

TEST(Failure, RefusedCommandNamesTheSpeedAndTheDevicesLimit) {
  HelixDeployment sc = makeHelixDeployment(40.0, 2.0);
  State s = sc.start;
  const double limit = 0.05;  // makeHelixDeployment's maxPushSpeed
  const std::optional<Failure> f = command(sc.model, s, {DeviceCommand::Kind::Push, 2 * limit, 0});
  ASSERT_TRUE(f);
  EXPECT_EQ(f->kind, FailureKind::DeviceRefusal);
  EXPECT_EQ(f->quantity, "push speed");
  EXPECT_EQ(f->value, 2 * limit);
  EXPECT_EQ(f->limit, limit);
  EXPECT_EQ(describe(*f).rfind("refused: push/pull speed must be in (0, ", 0), 0u) << describe(*f);
  EXPECT_EQ(s.device.motion.pushRate, 0) << "a refused command changes nothing";
  EXPECT_FALSE(command(sc.model, s, {DeviceCommand::Kind::Push, 0.5 * limit, 0}));
}

TEST(Failure, RefusedStepSaysWhenAndWhere) {
  RodDef rod = clamped(straightRod(0.1, 4, steel(), circularSection(0.5e-3, kSteelPoisson)));
  rod.name = "wire";
  rod.loads.push_back({4, Vec3(std::nan(""), 0, 0), Vec3::Zero()});
  ModelDef def = modelOf({rod});
  const Model m = compileModel(def);
  State s = makeState(m);
  s.time = 0.25;
  const StepReport rep = step(m, s);
  ASSERT_FALSE(rep.ok());
  EXPECT_EQ(rep.failure->kind, FailureKind::BlowUp);
  EXPECT_EQ(rep.failure->rod, "wire");
  EXPECT_EQ(rep.failure->time, 0.25);
  ASSERT_FALSE(s.warnings.empty());
  EXPECT_EQ(s.warnings.back(), describe(*rep.failure));
}

}  // namespace
}  // namespace coilsim::test
