#pragma once
// The ImGui control panel, the same in the window and in off-screen
// screenshots: simulation controls and read-outs, view switch, effect
// switches with their parameters, and the place for deployment controls.
#include <string>
#include <vector>

#include "render/renderer.h"
#include "ui/readouts.h"
#include "ui/session.h"
#include "ui/setup.h"
#include "ui/views.h"

namespace coilsim::ui {

// The device controls' settings, in the panel's units (shared with the
// keys and the gamepad, which push at the same speed).
struct DeviceControls {
  double pushSpeedMmS = 2.0;     // mm/s, push and pull (hold P / O)
  double twistRateDegS = 180.0;  // deg/s, twist (hold Q / E)
  double twistStepDeg = 15.0;    // deg per wheel notch with Ctrl
  double retractSpeedMmS = 1.0;  // mm/s, catheter retraction
  bool confirmDetach = false;    // the detach confirmation is open
};

// Colours and markers drawn on request (the moment colouring itself lives
// in the Session, which owns the draw data).
struct Overlays {
  bool colourByMoment = false;
  double momentScaleNmm = 0;  // N mm shown fully red; 0: the largest in the picture
  bool contacts = true;       // contact points and force arrows (3D view)
};

// What the panel shows besides the session, and what it asks for.
struct PanelContext {
  std::string sceneName;        // shown in the title
  bool interactive = true;      // false off-screen: a snapshot, no frame timing
  double frameSeconds = 0;      // wall time of the last frame (window)
  double renderSeconds = 0;     // of which drawing
  FrameAdvance lastAdvance;     // what the real-time loop did this frame
  std::string glInfo;           // GL version and renderer
  int sidebarWidth = 360;       // pixels, the panel's column at the left
  DeviceControls device;
  Overlays overlays;
  ReadoutHook readouts;         // optional live read-outs (planning), a section of their own
  const SetupChoices* setup = nullptr;  // optional coil and catheter choice (window)
  SetupStatus setupStatus;
  std::string effectsLocked;    // non-empty: why the effect switches cannot change (practice)
  // Requests, handled by the caller after the frame.
  bool fitRequested = false;
  bool closeRequested = false;
  bool setupRequested = false;  // a choice made in the combos: setupCoil, setupCatheter
  int setupCoil = -1, setupCatheter = -1;
};

void drawPanel(Session& session, Views& views, PanelContext& context);

// Labels in the corner of each projection ("AP", "LAT", C-arm angles).
void drawViewLabels(const std::vector<render::ViewportInfo>& viewports, int frameHeight, const Views& views);

// The deployment section (push, pull, twist, detach), see deployment_panel.cpp.
void drawDeploymentControls(Session& session, PanelContext& context);

}  // namespace coilsim::ui
