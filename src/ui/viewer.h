#pragma once
// The graphical front end as the CLI sees it: an interactive window (GLFW)
// and an off-screen render to PNG (OSMesa), both drawing the same scene.
#include <string>

#include "physics/model.h"
#include "physics/state.h"

namespace coilsim::ui {

struct ViewerOptions {
  std::string scenePath;        // shown in the title and the panel
  std::string view = "3d";      // "3d", "xray" or "biplane"
  int width = 1280, height = 720;
  std::string screenshotPath;   // where renderOffscreen writes its PNG
  bool drawPanel = true;        // draw the ImGui panel into the image too
  double runSeconds = -1;       // window: close by itself after this much simulated time (<0: never)
  std::string windowScreenshotPath;  // window: PNG of the last frame when it closes (tests under Xvfb)
};

// Opens the window and runs the real-time loop until the user closes it (or
// runSeconds of simulated time have passed). Returns a process exit code;
// prints a clear message and returns non-zero if no display or GL 3.3 is available.
int runWindow(const Model& model, State& state, const ViewerOptions& options);

// Renders the current state once through OSMesa into options.screenshotPath.
// Returns false and sets `error` (naming the path or the GL problem) on failure.
bool renderOffscreen(const Model& model, const State& state, const ViewerOptions& options, std::string& error);

}  // namespace coilsim::ui
