#pragma once
// `coilsim plan` and `coilsim plan-merge` (docs/planning.md).
#include <string>
#include <vector>

namespace coilsim::app {

// coilsim plan SCENE|CASE --coils a,b,c --out DIR [--jobs N] [--sac FILE] ...
// Returns 0, 1 if a candidate's simulation failed, 2 on bad input.
int runPlan(const std::vector<std::string>& args);

// coilsim plan-merge DIR... --out DIR: merges DIR/plan.json files.
int runPlanMerge(const std::vector<std::string>& args);

}  // namespace coilsim::app
