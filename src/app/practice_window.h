#pragma once
// `coilsim practice --window`: a case practised by hand in the window (or
// with scripted inputs typed into it), every input and view switch recorded,
// the score kept from the window's own steps (planning::SessionScorer behind
// a ui::RunObserver), the session file and score sheet written on close.
#ifdef COILSIM_HAVE_UI
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "app/exit_codes.h"
#include "physics/run.h"
#include "planning/case_file.h"
#include "planning/practice.h"
#include "ui/viewer.h"

namespace coilsim::app {

// Where a window session's recording and score sheet go when it closes.
struct WindowOutputs {
  std::string record, out;
  int exitCode = kExitOk;
};

// The window (or an off-screen picture) of a practice session's model and
// state, with the live read-outs: packing, protrusion and wall-force warnings.
ui::ViewerOptions practiceViewer(const planning::PracticeCase& pc, const planning::PracticeSession& session,
                                 const std::string& view);

// Opens the case in the window with `coil` (empty: the set's first), starting
// in `view` (xray or biplane: X-ray views only); `script` and `views` are
// typed in at their times; `duration` > 0 closes it after that much
// simulated time, `screenshot` gets the last frame. Returns the window's
// exit code, or outputs->exitCode (1 when a step was refused).
int practiseInWindow(const planning::PracticeCase& pc, std::string coil, const std::string& view,
                     const std::vector<TimedCommand>& script, const std::vector<std::pair<double, std::string>>& views,
                     double duration, const std::string& screenshot, std::shared_ptr<WindowOutputs> outputs);

}  // namespace coilsim::app
#endif
