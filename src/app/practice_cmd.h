#pragma once
// `coilsim practice`: play a practice case headless from a scripted timeline
// or by hand in the window (recording the session), or replay a recorded
// session; each writes the score sheet (docs/planning.md).
#include <string>
#include <vector>

namespace coilsim::app {

// coilsim practice CASE --coil NAME --input TIMELINE [--view V] [--views T:V,...] [--duration S] [--record SESSION] --out SCORE
// coilsim practice CASE --replay SESSION --out SCORE
// coilsim practice CASE --window [--coil NAME] [--view V] [--record SESSION] [--out SCORE]
//     [--input TIMELINE] [--views T:V,...] [--duration S] [--screenshot PNG]: by hand in the window
//     (or with scripted inputs, given as if typed), recorded and scored when the window closes.
// Returns 0, 1 if a step was refused, 2 on bad input.
int runPractice(const std::vector<std::string>& args);

}  // namespace coilsim::app
