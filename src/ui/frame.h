#pragma once
// One frame as the window and the off-screen path both draw it: the scene
// in the current view, then the panel and view labels on top.
#include <string>

#include "render/renderer.h"
#include "ui/imgui_layer.h"
#include "ui/panel.h"
#include "ui/session.h"
#include "ui/views.h"

namespace coilsim::ui {

struct FrameParts {
  render::Renderer& renderer;
  ImGuiLayer& imgui;
  Session& session;
  Views& views;
  PanelContext& panel;
  render::RenderSettings& settings;
  bool drawPanel = true;
};

// Draws into the renderer's frame (width x height pixels). `dt` is the real
// time since the last frame (for ImGui). Returns false with the reason in `error`.
bool drawFrame(FrameParts& parts, int width, int height, double dt, std::string& error);

// The same ImGui content without drawing it: ImGui sizes auto-fitting
// windows on their first frame, so a single off-screen frame runs this first.
void layoutPanelOnly(FrameParts& parts, int width, int height);

}  // namespace coilsim::ui
