#include "ui/render_bench.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <ctime>

#include "io/units.h"
#include "render/backend.h"
#include "render/gl_loader.h"
#include "ui/frame.h"

namespace coilsim::ui {
namespace {

double seconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

// CPU seconds of every thread of the process.
double processSeconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

}  // namespace

bool benchRender(const Model& model, const State& state, const RenderBenchOptions& o, RenderBenchResult& result,
                 std::string& error) {
  result = {};
  if (o.frames <= 0) {
    error = "the render benchmark needs at least one frame";
    return false;
  }
  render::BackendOptions bo;
  bo.width = o.width;
  bo.height = o.height;
  auto backend = render::createBackend("osmesa", bo, error);
  if (!backend) return false;
  render::Renderer renderer;
  if (!renderer.init(error)) return false;
  ImGuiLayer imgui;
  if (!imgui.init(nullptr, error)) return false;
  result.gl = render::glDescription();

  Session session(model, state, o.addDrawData);
  session.setTimeline(o.timeline);
  Views views;
  PanelContext panel;
  panel.interactive = false;
  render::RenderSettings settings;
  settings.samples = o.samples >= 0 ? o.samples : (render::softwareRenderer() ? 0 : 4);
  if (o.adjustSettings) o.adjustSettings(settings);
  result.samples = settings.samples;
  FrameParts parts{renderer, imgui, session, views, panel, settings, o.drawPanel};

  // Frames of one view, timed until the GPU has finished each.
  auto timeView = [&](render::ViewMode mode, double& fps, double& ms, double& cpuMs) {
    views.setMode(mode);
    for (int i = 0; i < o.warmupFrames + o.frames; ++i) {
      if (i == o.warmupFrames) renderer.finish();
      const double t0 = seconds(), c0 = processSeconds();
      if (!drawFrame(parts, o.width, o.height, 1.0 / 60.0, error)) return false;
      renderer.finish();
      if (i >= o.warmupFrames) {
        ms += units::sToMs(seconds() - t0);
        cpuMs += units::sToMs(processSeconds() - c0);
      }
    }
    ms /= o.frames;
    cpuMs /= o.frames;
    fps = 1e3 / ms;
    return true;
  };
  if (!timeView(render::ViewMode::Shaded, result.fps3d, result.ms3d, result.cpuMs3d)) return false;
  if (!timeView(render::ViewMode::XRay, result.fpsXRay, result.msXRay, result.cpuMsXRay)) return false;
  if (!timeView(render::ViewMode::Biplane, result.fpsBiplane, result.msBiplane, result.cpuMsBiplane)) return false;

  // Stepping and drawing, as the window does at 60 frames per second.
  views.setMode(render::ViewMode::Shaded);
  result.stepsPerFrame =
      o.stepsPerFrame > 0 ? o.stepsPerFrame : std::max(1, int(std::lround(1.0 / (60.0 * model.timeStep))));
  double physics = 0, drawing = 0, physicsCpu = 0;
  for (int i = 0; i < o.frames; ++i) {
    const double t0 = seconds(), c0 = processSeconds();
    // A refused step leaves the state as it was; the attempts still count.
    result.refusedSteps += session.stepMany(result.stepsPerFrame);
    const double t1 = seconds();
    physicsCpu += processSeconds() - c0;
    session.refreshDrawData();
    if (!drawFrame(parts, o.width, o.height, 1.0 / 60.0, error)) return false;
    renderer.finish();
    physics += t1 - t0;
    drawing += seconds() - t1;
  }
  result.physicsMsPerFrame = units::sToMs(physics) / o.frames;
  result.renderMsPerFrame = units::sToMs(drawing) / o.frames;
  result.physicsCpuMsPerFrame = units::sToMs(physicsCpu) / o.frames;
  const double total = physics + drawing;
  result.physicsShare = total > 0 ? physics / total : 0;
  result.renderShare = total > 0 ? drawing / total : 0;
  return true;
}

}  // namespace coilsim::ui
