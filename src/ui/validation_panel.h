#pragma once
// The validation workbench in a window (`coilsim validate FILE --window`,
// docs/validation.md): the per-stage table before and after, one toggle per
// registered effect, a Fit button that runs the fit in a background thread
// while the RMS residual along the optimiser's evaluations is plotted live,
// the error along the arc length of each stage, and the 3D coil coloured by
// its error beside the measured centre line.
//
// The ui layer knows nothing of measurements or identification: the app
// fills these plain structs and hands the fit over as a callback.
#include <functional>
#include <string>
#include <vector>

#include "physics/draw_data.h"
#include "ui/validation_charts.h"

namespace coilsim::ui {

struct ValidationStageRow {
  std::string name;
  double deployedMm = 0;
  bool ok = false;
  std::string message;  // why not ok
  double stageError = 0, nodeErrorMean = 0, nodeErrorSd = 0, meanDisplacementMm = 0, meanDistanceMm = 0;
  std::vector<float> arcMm, errorMm;  // (nodes) |x_sim - x_meas| along the arc length
  float noiseFloorMm = 0;             // sqrt(3) point_sigma
};

// One evaluated model: its stages, its fitted values, and per stage the
// scene (the coil coloured by error and the measured centre line).
struct ValidationView {
  bool ok = true;
  std::string message;                // why the fit failed (shown in the panel)
  std::vector<std::string> effects;   // names on
  std::vector<ValidationStageRow> stages;
  std::vector<std::string> fitted;    // one line each: "young_modulus = 5.61 +- 0.02 GPa"
  std::vector<float> history;         // RMS residual per coordinate (mm) after each evaluation
  std::vector<DrawData> scenes;       // (stages)
};

// Called after each evaluation of the optimiser: its index and the RMS residual in mm.
using FitProgress = std::function<void(int evaluation, double rmsMm)>;

struct ValidationHooks {
  std::string title;                        // the measurement (window title, panel header)
  std::vector<std::string> effects;         // the registered effects offered as toggles
  std::vector<std::string> descriptions;    // (effects) tooltips
  std::vector<std::string> initiallyOn;     // toggles on at the start
  ValidationView before;                    // the base model at the file's nominal values
  ValidationView after;                     // what "after" shows until the first fit (no stages: nothing yet)
  // Fits with these effects on. Runs on a background thread (it must not
  // touch the caller's simulators); calls `progress` after each evaluation
  // and should end soon (ok = false) once `stopRequested` returns true (the
  // Stop button, the window closing).
  std::function<ValidationView(const std::vector<std::string>& effectsOn, const FitProgress& progress,
                               const std::function<bool()>& stopRequested)>
      fit;
  int maxEvaluations = 120;                 // for the progress bar
  ErrorColourScale errorScale;              // how the scenes colour the coil by error (its legend)
};

struct ValidationWindowOptions {
  int width = 1280, height = 720;  // fits a 1280x720 screen, as the run and practice windows do
  // Scripted runs (tests, pictures): effects toggled as by a click on the
  // first frame, Fit pressed once, and the frame written to
  // `screenshotPath` once the fit is over (the window then closes).
  std::vector<std::string> toggle;
  bool autoFit = false;
  std::string screenshotPath;
  double wallLimitSeconds = 600;  // a scripted window gives up after this long
};

// Opens the window; returns a process exit code (non-zero with a message
// when there is no display or GL 3.3, when a scripted fit fails or times out).
// With COILSIM_LAYOUT_DUMP set, each frame writes where the panel's controls
// are (ui/layout_dump.h), as the run and practice windows do; so does the
// off-screen picture.
int runValidationWindow(const ValidationHooks& hooks, const ValidationWindowOptions& options);

// The same panel off-screen (OSMesa): the scripted toggles and fit run to
// the end first, then one frame goes to options.screenshotPath. Returns
// false with the reason in `error`.
bool renderValidationOffscreen(const ValidationHooks& hooks, const ValidationWindowOptions& options, std::string& error);

}  // namespace coilsim::ui
