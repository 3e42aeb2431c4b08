#pragma once
// Render performance for `coilsim bench`: frames per second of the 3D and
// X-ray views off-screen (OSMesa), and how a real-time frame divides between
// physics and drawing.
#include <functional>
#include <optional>
#include <string>

#include "physics/model.h"
#include "physics/state.h"
#include "render/renderer.h"
#include "ui/session.h"

namespace coilsim::ui {

struct RenderBenchOptions {
  int width = 1280, height = 720;  // pixels
  int frames = 30;                 // timed frames per measurement (after warmupFrames)
  int warmupFrames = 3;
  bool drawPanel = true;           // include the ImGui panel, as in the window
  int samples = -1;                // multisampling of the 3D view; <0: as the window picks it
  // Physics steps per frame in the stepping measurement; 0 asks for real
  // time at 60 frames per second: round(1 / (60 * model.timeStep)), at least 1.
  int stepsPerFrame = 0;
  DrawDataHook addDrawData;        // optional vessel meshes / markers, as in ViewerOptions
  // Optional: changes the renderer's settings after the window's choice
  // (a baseline drawn as the renderer drew before, a probe of one part).
  std::function<void(render::RenderSettings&)> adjustSettings;
  // Optional deployment; its timeline drives the stepping measurement (e.g.
  // a push from t = 0, so physics slides the coil as in use).
  std::vector<TimedCommand> timeline;
};

struct RenderBenchResult {
  double fps3d = 0, fpsXRay = 0, fpsBiplane = 0;  // drawn frames per second (GPU finished)
  double ms3d = 0, msXRay = 0, msBiplane = 0;     // milliseconds per frame
  // CPU milliseconds per frame of the whole process (every thread of a
  // software GL included): the work a frame takes, which other processes
  // on a shared machine do not inflate as they do the wall time above.
  double cpuMs3d = 0, cpuMsXRay = 0, cpuMsBiplane = 0;
  // Stepping measurement (3D view): each frame takes stepsPerFrame steps, then draws.
  int stepsPerFrame = 0;
  double physicsMsPerFrame = 0, renderMsPerFrame = 0;
  double physicsCpuMsPerFrame = 0;  // CPU time of the process while stepping (see cpuMs3d)
  double physicsShare = 0, renderShare = 0;  // fractions of the frame time, summing to 1
  long refusedSteps = 0;                     // steps refused (blow-ups) during the measurement
  std::string gl;                            // GL version / renderer measured
  int samples = 0;                           // multisampling used for the 3D view
};

// Runs the measurements on a copy of `state`. Returns false with the reason
// in `error` (no OSMesa GL 3.3 context, bad size).
bool benchRender(const Model& model, const State& state, const RenderBenchOptions& options, RenderBenchResult& result,
                 std::string& error);

}  // namespace coilsim::ui
