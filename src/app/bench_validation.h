#pragma once
// The validation part of `coilsim bench` (issue 5's Performance section):
// identification of E on a 3-stage measurement (target under 10 s) and a
// full diagnosis of the 5 candidate effects (target under 60 s), each also
// as a multiple of one simulation of the 3 stages measured in the same run.
#include <functional>
#include <string>

namespace coilsim {

// Reports validate_identify_e_s, validate_diagnose_5_s, validate_one_run_s and
// the ratios through `set`; prints a short table on stdout unless `json`.
void benchValidationFigures(const std::function<void(const std::string&, double)>& set, bool quick, bool json);

}  // namespace coilsim
