#pragma once
// Practice sessions: a trainee drives one coil of a case (push, pull, twist,
// detach, retract, and the view they look through), every input is recorded
// with the step it took effect at, and the session ends with a score sheet.
// Replaying the recording runs the same steps with the same inputs, so it
// reproduces the score sheet bit for bit.
//
// The scoring and the recording live in SessionScorer (session_scorer.h),
// which the window (coilsim practice --window) drives from its own stepping;
// a PracticeSession steps headless: command() and setView(), then step();
// finish() and recording() at the end. Commands and views take effect at
// the next step().
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "physics/run.h"
#include "physics/deployment.h"
#include "physics/model.h"
#include "physics/state.h"
#include "planning/auto_deploy.h"
#include "planning/case_file.h"
#include "planning/metrics.h"
#include "planning/session_scorer.h"

namespace coilsim::planning {

class PracticeSession {
 public:
  // Builds the model for the case's coil `coilName` (one of case.coils).
  // Whether there are wall forces says `contacts`, by default the contact layer (hasWallForces).
  // Throws io::InputError naming the case file if the coil is not in its set
  // or the scene cannot be compiled.
  PracticeSession(const PracticeCase& practiceCase, const std::string& coilName, const WallForceCheck& contacts = {});

  // Starts a device command at the next step; returns "" or why the device refuses it
  // (a refused command is not recorded as a command; the score sheet lists it).
  std::string command(const DeviceCommand& c);
  // The same for a command read from a recording, applied exactly as read.
  std::string replayCommand(const DeviceCommand& c);
  // "3d", "xray" or "biplane"; counts towards fluoroscopy time from the next step.
  void setView(const std::string& view);
  // Advances one time step; false once a step was refused (then nothing more happens).
  bool step();
  // Ends the session: final metrics, goal check.
  ScoreSheet finish();

  const Model& model() const { return model_; }
  const State& state() const { return state_; }
  const Deployment& deployment() const { return *model_.device; }
  const DeviceState& deploymentState() const { return state_.device; }
  long steps() const { return steps_; }
  const std::string& view() const { return scorer_->view(); }  // the view looked through now
  double time() const { return double(steps_) * model_.timeStep; }
  const ScoreSheet& runningScore() const { return scorer_->running(); }

  // The recording (SessionScorer::recording) ending now.
  nlohmann::ordered_json recording() const;

 private:
  Model model_;
  State state_;
  long steps_ = 0;
  std::optional<SessionScorer> scorer_;
  void note(const std::string& message);  // built once the deployment is known
};

// A recorded session, read back.
struct SessionRecording {
  std::string caseLabel, coil;
  double end = 0;  // s
  std::vector<TimedCommand> timeline;
  std::vector<std::pair<double, std::string>> views;
};
SessionRecording loadSession(const std::string& path);
SessionRecording parseSession(const nlohmann::json& document, const std::string& file);

// Plays `timeline` and `views` (inputs at their times) for `end` seconds on a
// fresh session and returns its score sheet. Used for replay and for
// scripted practice; identical inputs give identical sheets. `keepGoing`,
// when given, is asked after each step (a front end's progress and Ctrl-C):
// false ends the session there, scored as it stands.
ScoreSheet playSession(const PracticeCase& practiceCase, const std::string& coil,
                       const std::vector<TimedCommand>& timeline,
                       const std::vector<std::pair<double, std::string>>& views, double end,
                       nlohmann::ordered_json* recordingOut = nullptr, const WallForceCheck& contacts = {},
                       const std::function<void(const PracticeSession&)>& atEnd = {},
                       const std::function<bool(const PracticeSession&)>& keepGoing = {});

}  // namespace coilsim::planning
