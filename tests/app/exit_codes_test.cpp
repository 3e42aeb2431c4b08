// Tests of app/exit_codes.h against the exit codes `coilsim help run`
// promises (app/commands.cpp): 1 when the simulation failed (a step refused,
// a static solve not converged), 2 for bad input, which is what a definition
// physics refuses is.
#include <gtest/gtest.h>

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

}  // namespace
}  // namespace coilsim::app
