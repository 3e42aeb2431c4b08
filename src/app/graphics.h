#pragma once
// What the command files ask of the window and the off-screen renderer,
// beyond the window commands' own headers (bench_render.h,
// practice_window.h, validate_window.h, validate_plots.h' savePng). CMake
// compiles the graphics files (graphics_ui.cpp, bench_render.cpp,
// practice_window.cpp, validate_window.cpp, window_setup.cpp, sac_drawing.cpp,
// case_window.cpp) when the ui
// layer is built, and graphics_none.cpp in their place when it is not:
// there each function says "built without graphics" and returns the
// failure its contract names. Command files hold no #ifdef.
#include <memory>
#include <string>
#include <vector>

#include "app/run_scene.h"
#include "io/scene.h"
#include "physics/device.h"
#include "physics/model.h"
#include "physics/state.h"
#include "physics/triangle_mesh.h"
#include "planning/case_editor.h"
#include "planning/sac_geometry.h"

namespace coilsim::app {

// True when this binary has the ui layer (window and off-screen rendering).
bool haveUi();

// `coilsim run`'s window on `model` and `state` (static scenes solved
// before): the timeline played as the headless run plays it, live
// read-outs when an obstacle is a phantom with its sac, the panel's coil
// and catheter choice (which may replace `model`). Returns the window's
// exit code; without graphics, kExitUsage after saying so on stderr.
int runSceneWindow(Model& model, State& state, const io::SceneSpec& spec, const RunOptions& options,
                   const std::vector<TimedCommand>& timeline);

// `coilsim run --screenshot`: the last frame off-screen, in options.view
// at options.width x height. False with `error` set if it cannot (no
// OpenGL context, unwritable file, built without graphics).
// It shows the panel's sections as the window does (read-outs when an
// obstacle is a phantom with its sac, the coil and catheter).
bool sceneScreenshot(const Model& model, const State& state, const io::SceneSpec& spec, const RunOptions& options,
                     std::string& error);

// A plan's picture of one run: the 3D view without the panel, titled
// `title`, with the `sac` mesh drawn unless an obstacle of the model is
// that mesh, its neck plane and a legend. False with `error` set if it
// cannot (as above).
bool planPicture(const Model& model, const State& state, const std::string& title, int width, int height,
                 const planning::Sac& sac, const std::string& path, std::string& error);

// `coilsim case edit --window` (the case editor window on `editor`, saving
// to `savePath`) or `--screenshot` (one frame of it off-screen). Returns the
// exit code, or -1 when the command goes on (a screenshot taken, the case
// still to be written).
int caseEditorGraphics(planning::CaseEditor& editor, const std::string& caseFile, const std::string& savePath,
                       bool window, const std::string& screenshot);

}  // namespace coilsim::app
