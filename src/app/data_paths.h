#pragma once
// Where coilsim's shipped data are (coil catalogue, scenes, phantoms,
// timelines, example measurements), so an installed program does not
// depend on the source tree it was built from.
#include <string>

namespace coilsim::app {

// The data directory, first of:
// 1. $COILSIM_DATA_DIR when set and not empty (not checked: a wrong one
//    fails loudly at the first file read, naming the path);
// 2. <directory of the executable>/../share/coilsim, when it holds
//    assets/coils (an installed program: <prefix>/bin/coilsim);
// 3. the source tree this binary was built from (a build-tree binary).
std::string dataDirectory();

// Points the default coil catalogue (planning::defaultCatalogue) at
// dataDirectory(); the command line does this once before a command runs.
void useDataDirectory();

}  // namespace coilsim::app
