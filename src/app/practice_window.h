#pragma once
// `coilsim practice --window`: a case practised by hand in the window (or
// with scripted inputs typed into it), every input and view switch recorded,
// the score kept from the window's own steps (planning::SessionScorer behind
// a ui::RunObserver), the session file and score sheet written on close.
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "app/exit_codes.h"
#include "physics/run.h"
#include "planning/case_file.h"
#include "planning/practice.h"

namespace coilsim::app {

// The window's size, or the picture's (--size WxH), in pixels.
struct PictureSize {
  int width = 1280, height = 720;
};

// Where a window session's recording and score sheet go when it closes.
struct WindowOutputs {
  std::string record, out;
  int exitCode = kExitOk;
};

// The last frame of a scripted session off-screen, in its current view, with
// the live read-outs (packing, protrusion, wall-force warnings), written to
// `path` at `size`. False with `error` set if it cannot (no OpenGL context,
// built without graphics).
bool practicePicture(const planning::PracticeCase& pc, const planning::PracticeSession& session,
                     const std::string& path, PictureSize size, std::string& error);

// Opens the case in the window with `coil` (empty: the set's first), starting
// in `view` (xray or biplane: X-ray views only); `script` and `views` are
// typed in at their times; `duration` > 0 closes it after that much
// simulated time, `screenshot` gets the last frame; the window opens at
// `size`. Returns the window's
// exit code, or outputs->exitCode (1 when a step was refused); without
// graphics, kExitUsage after saying so on stderr.
int practiseInWindow(const planning::PracticeCase& pc, std::string coil, const std::string& view,
                     const std::vector<TimedCommand>& script, const std::vector<std::pair<double, std::string>>& views,
                     double duration, const std::string& screenshot, PictureSize size,
                     std::shared_ptr<WindowOutputs> outputs);

}  // namespace coilsim::app
