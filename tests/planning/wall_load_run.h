#pragma once
// One short run of the plan's automatic operator in the wide-neck sphere
// case, the run whose wall load the front ends must all report alike
// (session_scorer_test.cpp; session_scorer_window_test.cpp with the ui
// layer). Computed once per test binary, on first use.
#include <gtest/gtest.h>

#include <string>

#include "planning/auto_deploy.h"
#include "planning/practice.h"

namespace coilsim::planning {

inline const std::string kWideNeckCase = std::string(COILSIM_SOURCE_DIR) + "/scenes/cases/sphere-7mm-wide-neck.json";

struct WallLoadRun {
  PracticeCase practiceCase;
  std::string coil;
  Model model;       // the practice model the plan ran on
  State startState;  // the practice session's start
  State planState;   // after the plan
  AutoDeployResult plan;
};

inline const WallLoadRun& wallLoadRun() {
  static const WallLoadRun run = [] {
    WallLoadRun r;
    r.practiceCase = loadCase(kWideNeckCase);
    r.coil = "finishing-2x20";  // short, so each front end's run of it stays a small test
    // The plan's operator on the practice model (the same contacts: addRunContacts).
    const PracticeSession start(r.practiceCase, r.coil);
    r.model = start.model();
    r.startState = start.state();
    r.planState = start.state();
    AutoDeployOptions o;
    o.pushSpeed = 20e-3;  // the case's fastest push, to load the wall within a short test
    o.settle = 0.1;
    r.plan = autoDeploy(r.model, r.planState, o, hasWallForces);
    return r;
  }();
  return run;
}

// Whether the run is worth comparing: the plan ran, and its coil pressed on
// the wall (a load of zero everywhere would prove nothing).
inline ::testing::AssertionResult loadedTheWall(const WallLoadRun& run) {
  if (!run.plan.ok) return ::testing::AssertionFailure() << "the plan failed: " << run.plan.error;
  if (!run.plan.wallForcesAvailable) return ::testing::AssertionFailure() << "the plan reports no wall forces";
  if (!(run.plan.wall.max > 0.0)) return ::testing::AssertionFailure() << "the coil never pressed on the wall";
  return ::testing::AssertionSuccess();
}

// The tests on the run: each starts only when the run is worth comparing.
class WallLoadFigure : public ::testing::Test {
 protected:
  void SetUp() override { ASSERT_TRUE(loadedTheWall(run)); }
  const WallLoadRun& run = wallLoadRun();
  const AutoDeployResult& plan = run.plan;
};

}  // namespace coilsim::planning
