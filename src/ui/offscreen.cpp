// renderOffscreen: one frame through OSMesa, panel included, to a PNG.
#include <cstdio>

#include "render/backend.h"
#include "render/gl_loader.h"
#include "render/image.h"
#include "ui/frame.h"
#include "ui/layout_dump.h"
#include "ui/viewer.h"
#include "ui/offscreen_context.h"

namespace coilsim::ui {

bool renderOffscreen(const Model& model, const State& state, const ViewerOptions& options, std::string& error) {
  const auto mode = render::parseViewMode(options.view);
  if (!mode) {
    error = "unknown view '" + options.view + "' (expected 3d, xray or biplane)";
    return false;
  }
  const auto backend = offscreenContext(options.screenshotPath, options.width, options.height, error);
  if (!backend) return false;
  render::Renderer renderer;
  if (!renderer.init(error)) return false;
  ImGuiLayer imgui;
  if (!imgui.init(nullptr, error)) return false;

  Session session(model, state, options.addDrawData);
  session.setTimeline(options.timeline);
  Views views(*mode);
  PanelContext panel;
  panel.sceneName = options.scenePath;
  panel.readouts = options.readouts;
  panel.legend = options.legend;
  // The same sections as the window (the choice is shown, not offered).
  std::optional<SetupChoices> setup = options.setup;
  if (setup) panel.setup = &*setup;
  panel.interactive = false;
  panel.glInfo = render::glDescription();
  render::RenderSettings settings;
  settings.samples = options.samples >= 0 ? options.samples : 4;  // one frame: quality first
  FrameParts parts{renderer, imgui, session, views, panel, settings, options.drawPanel};

  if (session.showingOlderState())
    std::fprintf(stderr, "coilsim: the state to render is not healthy; drawing nothing in its place\n");
  // The layout of the frame written, as the window writes its own (tests compare the two).
  LayoutDump layout(LayoutDump::pathFromEnvironment());
  if (layout.enabled()) panel.layout = &layout;
  layoutPanelOnly(parts, options.width, options.height);
  layout.begin(float(options.width), float(options.height));
  if (!drawFrame(parts, options.width, options.height, 1.0 / 60.0, error) || !layout.write(error)) return false;
  render::Image image;
  return readBackFrame(renderer, image, error) && render::writePng(options.screenshotPath, image, error);
}

}  // namespace coilsim::ui
