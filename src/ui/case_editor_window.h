#pragma once
// The case editor window (`coilsim case edit CASE.json --window`,
// docs/planning.md): the vessel surface, the sac piece highlighted, the neck
// plane as a disc with its normal and the catheter tip; the user moves the
// neck plane (shift + drag, arrow keys, ctrl + click on the surface), places
// the tip (click on the surface, or drag it), reads the morphology live and saves.
//
// The ui layer knows nothing of cases: the app (src/app/case_window.cpp)
// fills these plain structs and hands every edit over as a callback to
// planning::CaseEditor, which keeps the editing logic.
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "physics/draw_data.h"

namespace coilsim::ui {

// What the window shows of the case after each edit.
struct CaseEditorView {
  DrawData scene;                                          // m, as the renderer draws
  std::vector<std::pair<std::string, std::string>> rows;   // the morphology: name, value with its unit
  Vec3 neckNormal = Vec3::UnitZ();                         // the first view looks across it
  Vec3 tip = Vec3::Zero();                                 // m, the catheter tip: a drag from it moves it
  bool unsaved = false;                                    // edits since the last save
};

// Every edit returns "" when made, else why it was refused (nothing changed).
struct CaseEditorHooks {
  std::string title;            // the case file (window title, panel header)
  std::string savePath;         // where Save writes
  bool saveOverwrites = false;  // savePath is the case being edited: Save asks first
  std::function<CaseEditorView()> view;
  std::function<std::string(double mm)> moveNeck;                   // along its normal, + toward the dome
  std::function<std::string(const Vec3& axis, double radians)> tiltNeck;
  // A click in the 3D view: the ray under the cursor, origin and direction in m.
  std::function<std::string(const Vec3& origin, const Vec3& direction)> placeTip;   // mid-lumen under the cursor
  std::function<std::string(const Vec3& origin, const Vec3& direction)> placeNeck;  // through the surface point hit
  std::function<std::string()> aimTip;  // the tip pointing at the neck's centre
  std::function<std::string()> save;    // writes savePath
};

// The controls, in the panel's help and docs/planning.md.
inline constexpr double kNeckDragMmPerPixel = 0.05;  // shift + vertical drag, up toward the dome
inline constexpr double kNeckKeyStepMm = 0.1;        // Up / Down
inline constexpr double kNeckPageStepMm = 1.0;       // Page Up / Page Down
inline constexpr double kTiltKeyStepDeg = 1.0;       // I / K (about the view's horizontal), J / L (vertical)
inline constexpr double kTipGrabPixels = 10.0;       // a drag starting this close to the tip moves the tip

struct CaseEditorWindowOptions {
  int width = 1280, height = 800;
  // Off-screen: the picture. Window: the last frame, written when it closes.
  std::string screenshotPath;
};

// Opens the window; returns 0 when closed by the user, 1 with a message when
// there is no display or GL 3.3 or a picture could not be written. Prints a
// line with the 3D view's place and camera when it opens (for scripts that
// click into it), each refusal to stderr and each save to stdout.
int runCaseEditorWindow(const CaseEditorHooks& hooks, const CaseEditorWindowOptions& options);

// One frame of the same window off-screen (OSMesa) into
// options.screenshotPath. Returns false with the reason in `error`.
bool renderCaseEditorOffscreen(const CaseEditorHooks& hooks, const CaseEditorWindowOptions& options,
                               std::string& error);

}  // namespace coilsim::ui
