#pragma once
// `coilsim run`: load a scene, simulate it (window, or off-screen with a
// summary, a result file and a screenshot), and say how it went.
#include <optional>
#include <string>

#include "app/exit_codes.h"

namespace coilsim::app {

struct RunOptions {
  std::string scene;
  bool headless = false;
  std::string out;                  // result file, empty: none
  std::string input;                // input timeline (coilsim-timeline/1), empty: none
  std::optional<double> durationS;  // overrides the scene's duration_s
  std::optional<long> steps;        // overrides it by a step count
  std::string screenshot;           // PNG path, empty: none
  std::optional<std::string> view;  // "3d", "xray", "biplane"
  std::optional<int> width, height;
};

// True when DISPLAY or WAYLAND_DISPLAY is set.
bool haveDisplay();

// Runs one scene; prints errors (naming the file and JSON path) on stderr
// and returns one of the exit codes above. Never throws.
int runScene(const RunOptions& options);

}  // namespace coilsim::app
