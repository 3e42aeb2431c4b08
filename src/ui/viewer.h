#pragma once
// The graphical front end as the CLI sees it: an interactive window (GLFW)
// and an off-screen render to PNG (OSMesa), both drawing the same scene.
#include <functional>
#include <optional>
#include <string>

#include "physics/draw_data.h"
#include "physics/model.h"
#include "physics/state.h"
#include "ui/readouts.h"
#include "ui/scene_legend.h"
#include "ui/session.h"
#include "ui/setup.h"

namespace coilsim::ui {

struct ViewerOptions {
  std::string scenePath;        // shown in the title and the panel
  std::string view = "3d";      // "3d", "xray" or "biplane"
  int width = 1280, height = 720;
  std::string screenshotPath;   // where renderOffscreen writes its PNG
  bool drawPanel = true;        // draw the ImGui panel into the image too
  double runSeconds = -1;       // window: close by itself after this much simulated time (<0: never)
  std::string windowScreenshotPath;  // window: PNG of the last frame when it closes (tests under Xvfb)
  bool startPaused = false;     // window: open paused (ignored when runSeconds >= 0)
  bool vsync = true;            // window: wait for the display between frames
  int samples = -1;             // multisampling of the 3D view: 0 off, <0 automatic (4; in the
                                // window 0 on software GL, where it would cost 3x the frame)
  // Optional: adds to the draw data what the core does not fill (vessel
  // meshes, contact or validation markers), called whenever the state changes.
  std::function<void(const Model&, const State&, DrawData&)> addDrawData;
  // Device commands at their times, played as `coilsim run --headless`
  // plays them, besides the panel, keys and gamepad (model with a device only).
  std::vector<TimedCommand> timeline;
  // Optional live read-outs in the panel (planning: packing, protrusion, wall-force warnings).
  ReadoutHook readouts;
  // Window: coil and catheter choice in the panel, built by the app.
  std::optional<SetupChoices> setup;
  // Window: who records the user's inputs and the steps (practice), told when the window closes.
  std::shared_ptr<RunObserver> observer;
  // Window: user inputs given at their times as if typed (tests under Xvfb).
  std::vector<ScriptedInput> script;
  // What the picture's colours are (coil, sac wall, neck plane), in the
  // scene's lower left corner; empty: none.
  std::vector<LegendEntry> legend;
  bool xrayOnly = false;        // window: no 3D view (practice in the X-ray views only)
  std::string effectsLocked;    // window: why the effect switches are fixed (practice: the case's physics)
};

// Opens the window and runs the real-time loop until the user closes it (or
// runSeconds of simulated time have passed); `model` and `state` are then
// the run as it closed (a coil or catheter chosen in the panel replaces the
// model). Returns a process exit code; prints a clear message and returns
// non-zero, changing nothing, if no display or GL 3.3 is available.
int runWindow(Model& model, State& state, const ViewerOptions& options);

// Renders the current state once through OSMesa into options.screenshotPath.
// Returns false and sets `error` (naming the path or the GL problem) on failure.
bool renderOffscreen(const Model& model, const State& state, const ViewerOptions& options, std::string& error);

}  // namespace coilsim::ui
