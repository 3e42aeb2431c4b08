#pragma once
// `coilsim diagnose` (docs/validation.md): which physical effect is missing.
#include <string>
#include <vector>

namespace coilsim::app {

// coilsim diagnose FILE [--fit ...] --out DIR [--candidates a,b] [--spacing MM] [--no-plots] [--quiet]
// Fits young_modulus_gpa (plus --fit) in the baseline and with each candidate
// effect, writes DIR/diagnosis.json, DIR/diagnosis.md and the baseline's
// pictures. Returns 0, 1 if the baseline cannot be simulated or fitted, 2
// on a bad command line or measurement file.
int runDiagnose(const std::vector<std::string>& args);

}  // namespace coilsim::app
