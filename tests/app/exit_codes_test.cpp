// Tests of app/exit_codes.h against the exit codes `coilsim help run`
// promises (app/commands.cpp): 1 when the simulation failed (a step refused,
// a static solve not converged), 2 for bad input, which is what a definition
// physics refuses is.
#include <gtest/gtest.h>

#include <optional>

#include "app/exit_codes.h"
#include "physics/failure.h"

namespace coilsim::app {
namespace {

TEST(ExitCodes, ABadDefinitionIsBadInputAndAFailedRunAFailedSimulation) {
  Failure f;
  f.kind = FailureKind::BadDefinition;
  EXPECT_EQ(exitCodeOf(f), 2);
  for (const FailureKind k : {FailureKind::BlowUp, FailureKind::SolverFailure, FailureKind::MissedContact,
                              FailureKind::NotConverged, FailureKind::DeviceRefusal}) {
    f.kind = k;
    EXPECT_EQ(exitCodeOf(f), 1) << int(k);
  }
}

// A failed fit or diagnosis exits as its physics cause says, and without
// one (the optimiser gave up) as a failed simulation.
TEST(ExitCodes, AFailedCommandTakesItsCausesCodeOrOne) {
  Failure f;
  f.kind = FailureKind::BadDefinition;
  EXPECT_EQ(exitCodeOf(std::optional<Failure>(f)), 2);
  f.kind = FailureKind::NotConverged;
  EXPECT_EQ(exitCodeOf(std::optional<Failure>(f)), 1);
  EXPECT_EQ(exitCodeOf(std::optional<Failure>()), 1);
}

}  // namespace
}  // namespace coilsim::app
