#pragma once
// `coilsim practice`: play a practice case headless from a scripted timeline
// (recording the session), or replay a recorded session; both write the
// score sheet (docs/planning.md).
#include <string>
#include <vector>

namespace coilsim::app {

// coilsim practice CASE --coil NAME --input TIMELINE [--view V] [--duration S] [--record SESSION] --out SCORE
// coilsim practice CASE --replay SESSION --out SCORE
// Returns 0, 1 if a step was refused, 2 on bad input.
int runPractice(const std::vector<std::string>& args);

}  // namespace coilsim::app
