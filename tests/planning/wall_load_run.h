#pragma once
// One short run of the plan's automatic operator in the wide-neck sphere
// case, the run whose wall load the front ends must all report alike
// (session_scorer_test.cpp; session_scorer_window_test.cpp with the ui
// layer). Computed once per test binary, on first use.
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
    r.plan = autoDeploy(r.model, r.planState, o, wallContactForces);
    return r;
  }();
  return run;
}

}  // namespace coilsim::planning
