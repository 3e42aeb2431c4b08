#pragma once
#include <string>
#include <vector>

namespace coilsim::app {
// `coilsim phantom --type sidewall|curved|bifurcation --sac-mm D ... --out FILE.stl`:
// writes a parametric aneurysm phantom as binary STL (mm) and its sidecar
// FILE.phantom.json (sac, neck plane). Exit 0, or 2 on bad arguments.
int runPhantomCommand(const std::vector<std::string>& args);
}  // namespace coilsim::app
