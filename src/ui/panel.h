#pragma once
// The ImGui control panel, the same in the window and in off-screen
// screenshots: simulation controls and read-outs, view switch, effect
// switches with their parameters, and the place for deployment controls.
#include <string>
#include <vector>

#include "render/renderer.h"
#include "ui/session.h"
#include "ui/views.h"

namespace coilsim::ui {

// What the panel shows besides the session, and what it asks for.
struct PanelContext {
  std::string sceneName;        // shown in the title
  bool interactive = true;      // false off-screen: a snapshot, no frame timing
  double frameSeconds = 0;      // wall time of the last frame (window)
  double renderSeconds = 0;     // of which drawing
  FrameAdvance lastAdvance;     // what the real-time loop did this frame
  std::string glInfo;           // GL version and renderer
  int sidebarWidth = 360;       // pixels, the panel's column at the left
  // Requests, handled by the caller after the frame.
  bool fitRequested = false;
  bool closeRequested = false;
};

void drawPanel(Session& session, Views& views, PanelContext& context);

// Labels in the corner of each projection ("AP", "LAT", C-arm angles).
void drawViewLabels(const std::vector<render::ViewportInfo>& viewports, int frameHeight, const Views& views);

// The deployment section (push, pull, twist, detach), see deployment_panel.cpp.
void drawDeploymentControls(Session& session);

}  // namespace coilsim::ui
