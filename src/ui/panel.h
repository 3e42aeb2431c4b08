#pragma once
// The ImGui control panel, the same in the window and in off-screen
// screenshots: simulation controls and read-outs, view switch, effect
// switches with their parameters, and the place for deployment controls.
#include <string>
#include <vector>

#include "render/renderer.h"
#include "ui/layout_dump.h"
#include "ui/readouts.h"
#include "ui/scene_legend.h"
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
  bool confirmDetach = false;    // the detach confirmation is open (a modal over the scene)
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
  std::vector<LegendEntry> legend;  // the scene's legend (drawn with or without the panel)
  bool helpOpen = false;        // the help overlay (F1 or ?) is shown
  LayoutDump* layout = nullptr; // optional: where the controls were drawn (tests under Xvfb)
  // Requests, handled by the caller after the frame.
  bool fitRequested = false;
  bool closeRequested = false;
  bool setupRequested = false;  // a choice made in the combos: setupCoil, setupCatheter
  int setupCoil = -1, setupCatheter = -1;
};

// The panel fits any window from 1280x720 up: the device controls (and
// play, step, reset) stay at the top, never scrolled away; every other
// section collapses and scrolls below them; below 900 pixels of height
// (the compact clinical layout) the simulation figures and effect switches
// start closed. Then the detach confirmation and the help overlay, when open.
void drawPanel(Session& session, Views& views, PanelContext& context);

// Labels in the corner of each projection ("AP", "LAT", C-arm angles).
void drawViewLabels(const std::vector<render::ViewportInfo>& viewports, int frameHeight, const Views& views);

// The deployment controls (push, pull, twist, detach), see deployment_panel.cpp.
void drawDeploymentControls(Session& session, PanelContext& context);
// The device's messages (refusals, limits reached), newest first.
void drawDeviceMessages(const Session& session);

// D or the Detach button: opens the confirmation, unless the controller
// would refuse the detach now (then the refusal is noted at once and
// nothing asks). Returns true if it asks.
bool requestDetach(Session& session, DeviceControls& controls);
// D or Enter in the confirmation, or its button: detaches and closes it.
void confirmDetach(Session& session, DeviceControls& controls);
// The confirmation itself, a modal centred over the scene area (never over
// the panel's buttons), answered by mouse or by the keys above.
void drawDetachConfirmation(Session& session, PanelContext& context);

}  // namespace coilsim::ui
