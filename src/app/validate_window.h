#pragma once
// `coilsim validate FILE --window` and `--screenshot PNG`: the workbench as
// an ImGui panel (ui/validation_panel.h), fed from the validation layer.
#include <string>
#include <vector>

#include "app/validate_cmd.h"

namespace coilsim::app {

struct WindowArgs {
  bool window = false;              // --window
  std::string screenshot;           // --screenshot PNG (off-screen without --window)
  std::vector<std::string> toggle;  // --toggle a,b: scripted clicks on the effect toggles
  bool autoFit = false;             // --auto-fit: Fit pressed once
  int width = 1280, height = 720;   // --size WxH of the window or the picture
};

// Opens the panel (or renders it off-screen) on the measurement `a.file`.
// Returns a process exit code; says why on stderr when the build has no
// graphics or there is no display.
int runValidateWindow(const WorkbenchArgs& a, const WindowArgs& w);

}  // namespace coilsim::app
