// runWindow: the interactive simulator. GLFW window, physics on a fixed time
// step decoupled from drawing (Session / RealTimeLoop), ImGui panel, camera
// on mouse, keys and gamepad.
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <chrono>
#include <cmath>
#include <cstdio>

#include "render/gl_loader.h"
#include "render/image.h"
#include "ui/frame.h"
#include "ui/glfw_window.h"
#include "ui/input.h"
#include "ui/layout_dump.h"
#include "ui/realtime.h"
#include "ui/viewer.h"

namespace coilsim::ui {
namespace {

bool writeWindowShot(int width, int height, const std::string& path) {
  render::Image image;
  std::string error;
  if (!render::Renderer::readWindowPixels(width, height, image)) {
    std::fprintf(stderr, "coilsim: could not read the window back for %s\n", path.c_str());
    return false;
  }
  if (!render::writePng(path, image, error)) {
    std::fprintf(stderr, "coilsim: %s\n", error.c_str());
    return false;
  }
  std::printf("coilsim: wrote %s (%dx%d)\n", path.c_str(), width, height);
  return true;
}

}  // namespace

int runWindow(Model& model, State& state, const ViewerOptions& options) {
  const auto mode = render::parseViewMode(options.view);
  if (!mode) {
    std::fprintf(stderr, "coilsim: unknown view '%s' (expected 3d, xray or biplane)\n", options.view.c_str());
    return 2;
  }
  render::BackendOptions bo;
  bo.width = options.width;
  bo.height = options.height;
  bo.vsync = options.vsync;
  bo.title = options.scenePath.empty() ? "coilsim" : "coilsim - " + options.scenePath;
  const auto win = GlfwWindow::open(bo);
  if (!win) return 1;
  GLFWwindow* window = win->handle();

  Session session(model, state, options.addDrawData);
  session.setTimeline(options.timeline);
  Views views(*mode);
  views.setXrayOnly(options.xrayOnly);
  session.setView(render::viewModeName(views.mode()));
  session.setXrayOnly(options.xrayOnly);
  session.setObserver(options.observer);
  session.setScript(options.script);
  PanelContext panel;
  panel.sceneName = options.scenePath;
  panel.readouts = options.readouts;
  panel.legend = options.legend;
  panel.effectsLocked = options.effectsLocked;
  std::optional<SetupChoices> setup = options.setup;
  if (setup) panel.setup = &*setup;
  // The view the user switched to (keys, panel, gamepad) goes to the session
  // (and its observer); a scripted switch comes back from it.
  auto userView = [&] { session.setView(render::viewModeName(views.mode())); };
  auto scriptView = [&] {
    if (const auto m = render::parseViewMode(session.view()); m && *m != views.mode()) views.setMode(*m);
  };
  panel.glInfo = render::glDescription();
  LayoutDump layout(LayoutDump::pathFromEnvironment());
  if (layout.enabled()) panel.layout = &layout;
  render::RenderSettings settings;
  settings.samples = options.samples >= 0 ? options.samples : (render::softwareRenderer() ? 0 : 4);

  // Our callbacks first: ImGui's GLFW backend chains to them.
  WindowInput input(window, session, views, panel);
  if (!win->attachImGui()) return 1;
  ImGuiLayer& imgui = win->imgui();
  FrameParts parts{win->renderer(), imgui, session, views, panel, settings, true};

  const bool scripted = options.runSeconds >= 0;
  session.setPlaying(scripted || !options.startPaused);
  if (scripted) session.setStopTime(options.runSeconds);
  const double wallLimit = scripted ? 60.0 + 20.0 * options.runSeconds : 0.0;
  const double start = wallSeconds();
  double last = start;
  std::string error;
  int exitCode = 0;
  bool closing = false;
  while (!closing) {
    glfwPollEvents();
    const double now = wallSeconds();
    const double dt = now - last;
    last = now;
    const int fbw = win->framebufferWidth(), fbh = win->framebufferHeight();
    input.update(dt, imgui.wantsMouse(), imgui.wantsKeyboard());
    userView();

    panel.lastAdvance = session.advance(dt, wallSeconds);
    scriptView();

    closing = glfwWindowShouldClose(window) || panel.closeRequested;
    if (scripted) {
      if (session.reachedStopTime()) {
        closing = true;
      } else if (!session.haltMessage().empty()) {
        std::fprintf(stderr, "coilsim: %s\n", session.haltMessage().c_str());
        closing = true;
        exitCode = 1;
      } else if (now - start > wallLimit) {
        std::fprintf(stderr, "coilsim: stopped after %.0f s of wall time at t = %.4f s of %.4f s\n", now - start,
                     session.state().time, options.runSeconds);
        closing = true;
        exitCode = 1;
      }
    }

    if (fbw <= 0 || fbh <= 0) {  // minimised: keep simulating, draw nothing
      glfwWaitEventsTimeout(0.05);
      continue;
    }
    const double drawStart = wallSeconds();
    int ww = 0, wh = 0;
    win->windowSize(ww, wh);
    layout.begin(float(ww), float(wh));
    if (!drawFrame(parts, fbw, fbh, dt, error)) {
      std::fprintf(stderr, "coilsim: %s\n", error.c_str());
      exitCode = 1;
      break;
    }
    if (!layout.write(error)) {
      std::fprintf(stderr, "coilsim: %s\n", error.c_str());
      layout = LayoutDump("");  // said once; the window goes on
      panel.layout = nullptr;
    }
    win->renderer().present(fbw, fbh);
    userView();
    if (setup && panel.setupRequested) {
      panel.setupRequested = false;
      // A next coil goes on playing in the same picture; another setup starts paused, framed anew.
      const bool follows = followsNow(*setup, session);
      if (applySetup(*setup, panel.setupCoil, panel.setupCatheter, session, panel) && !follows) {
        session.setPlaying(false);
        panel.fitRequested = true;
      }
    }
    panel.renderSeconds = wallSeconds() - drawStart;
    panel.frameSeconds = dt;
    if (input.screenshotRequested()) {
      writeWindowShot(fbw, fbh, input.nextScreenshotName());
    }
    if (closing && !options.windowScreenshotPath.empty() && !writeWindowShot(fbw, fbh, options.windowScreenshotPath))
      exitCode = 1;
    win->present();
  }
  model = session.model();
  state = session.state();
  if (session.observer()) session.observer()->closed(session.model(), session.state());
  return exitCode;
}

}  // namespace coilsim::ui
