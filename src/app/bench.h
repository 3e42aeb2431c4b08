#pragma once
#include <string>
#include <vector>

namespace coilsim {
// `coilsim bench [--json] [--quick]`: prints timing figures with ratios
// against baselines measured in the same run. Returns the exit code.
int runBench(const std::vector<std::string>& args);
}  // namespace coilsim
