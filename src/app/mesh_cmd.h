#pragma once
#include <string>
#include <vector>

namespace coilsim::app {
// `coilsim mesh FILE [--scale-to-mm S]`: prints the surface report (triangles,
// bounds mm, closed, oriented, components, volume mm^3, repairs). Exit 0 when
// the surface is usable as a wall (possibly after safe repairs), 2 when it is
// not or cannot be read.
int runMeshCommand(const std::vector<std::string>& args);
}  // namespace coilsim::app
