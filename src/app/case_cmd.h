#pragma once
// `coilsim case new SURFACE --out CASE.json [--sac-point x,y,z]`: a case made
// from a patient's surface (planning/case_maker.h), its morphology printed.
// `coilsim case edit CASE.json --neck-shift MM ... --out NEW.json`: the neck
// plane and the tip moved through planning::CaseEditor, the case saved; with
// --window the same editor by hand (app/case_window.h).
#include <string>
#include <vector>

namespace coilsim::app {

// Exit codes of app/exit_codes.h: 2 on bad input, an unusable surface or an
// unclear sac (the message says which and asks for --sac-point).
int runCaseCommand(const std::vector<std::string>& args);

}  // namespace coilsim::app
