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
#include "planning/placed_coils.h"
#include "planning/session_scorer.h"

namespace coilsim::planning {

// The coils of one session, one after the other through the case's
// catheter, as in a real coiling: once the running coil has detached the
// next one goes in, and the detached ones stay in the sac as rods
// (placed_coils.h) that the next one touches. Each coil has a model of its
// own (the deployment's rods, then the placed coils'); the session's clock
// and records in the State (time, statistics, warnings) go on across them.
class PracticeCoilChain {
 public:
  // The case's coil `first` going in with nothing placed yet. Throws
  // io::InputError naming the case file if the coil is not in its set or
  // the scene cannot be compiled.
  PracticeCoilChain(const PracticeCase& practiceCase, const std::string& first);

  const Model& model() const { return model_; }
  // The running coil's start: its deployment at the initial length, the placed coils at rest.
  const State& start() const { return start_; }
  const std::string& coil() const { return coils_.back(); }
  const std::vector<std::string>& coils() const { return coils_; }  // every coil so far, in order
  size_t placed() const { return placed_.size(); }

  // Why `next` cannot go in after the state `now` of the running coil (it
  // has not detached; `next` is not in the case's set), or "".
  std::string whyNot(const State& now, const std::string& next) const;
  // Goes on with `next`: the running coil, as `now` left it, joins the
  // placed ones. Returns the state the next coil starts from. Throws
  // io::InputError saying whyNot, changing nothing.
  State next(const State& now, const std::string& next);

 private:
  void build(const std::string& coil, const State* before);

  const PracticeCase* case_;
  std::vector<std::string> coils_;
  std::vector<PlacedCoil> placed_;
  ModelDef def_;  // of the running coil, as compiled
  size_t firstPlaced_ = 0;
  Model model_;
  State start_;
};

// The coils of a session: the first, then each next one at its session time
// (a replay) or, without a time, as soon as the one before has detached (a
// scripted session: --coil a+b+c).
struct NextCoil {
  std::string coil;
  std::optional<double> time;  // s
};
struct SessionCoils {
  std::string first;
  std::vector<NextCoil> next;
  SessionCoils(std::string coil, std::vector<NextCoil> after = {}) : first(std::move(coil)), next(std::move(after)) {}
  SessionCoils(const char* coil) : first(coil) {}
};
// "a+b+c" -> a, then b and c each once the one before has detached.
SessionCoils parseCoilSequence(const std::string& text);
// Throws io::InputError naming the case file and the first coil of `coils`
// not in the case's set.
void checkCoils(const PracticeCase& practiceCase, const SessionCoils& coils);

class PracticeSession {
 public:
  // Builds the model for the case's coil `coilName` (one of case.coils).
  // Whether there are wall forces says `contacts`, by default the contact layer (hasWallForces).
  // Throws io::InputError naming the case file if the coil is not in its set
  // or the scene cannot be compiled.
  PracticeSession(const PracticeCase& practiceCase, const std::string& coilName, const WallForceCheck& contacts = {});

  // The next coil of the case's set goes in through the same catheter from
  // the next step, the detached ones kept in the sac (PracticeCoilChain).
  // Returns "" or why not (the running coil has not detached, no such
  // coil): then nothing changes, and the score sheet lists it.
  std::string nextCoil(const std::string& coilName);

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

  const Model& model() const { return coils_.model(); }
  const State& state() const { return state_; }
  const Deployment& deployment() const { return *model().device; }
  const DeviceState& deploymentState() const { return state_.device; }
  long steps() const { return steps_; }
  const std::string& view() const { return scorer_->view(); }  // the view looked through now
  double time() const { return double(steps_) * model().timeStep; }
  const PracticeCoilChain& coils() const { return coils_; }
  const ScoreSheet& runningScore() const { return scorer_->running(); }

  // The recording (SessionScorer::recording) ending now.
  nlohmann::ordered_json recording() const;

 private:
  PracticeCoilChain coils_;
  State state_;
  long steps_ = 0;
  std::optional<SessionScorer> scorer_;
  void note(const std::string& message);  // built once the deployment is known
};

// A recorded session, read back.
struct SessionRecording {
  std::string caseLabel, coil;
  std::vector<NextCoil> nextCoils;  // each with its time
  double end = 0;  // s
  std::vector<TimedCommand> timeline;
  std::vector<std::pair<double, std::string>> views;
};
SessionRecording loadSession(const std::string& path);
SessionRecording parseSession(const nlohmann::json& document, const std::string& file);

// Plays `timeline` and `views` (inputs at their times) for `end` seconds on a
// fresh session of `coils` and returns its score sheet (a next coil that
// cannot go in is noted in it and dropped). Used for replay and for
// scripted practice; identical inputs give identical sheets. `keepGoing`,
// when given, is asked after each step (a front end's progress and Ctrl-C):
// false ends the session there, scored as it stands.
ScoreSheet playSession(const PracticeCase& practiceCase, const SessionCoils& coils,
                       const std::vector<TimedCommand>& timeline,
                       const std::vector<std::pair<double, std::string>>& views, double end,
                       nlohmann::ordered_json* recordingOut = nullptr, const WallForceCheck& contacts = {},
                       const std::function<void(const PracticeSession&)>& atEnd = {},
                       const std::function<bool(const PracticeSession&)>& keepGoing = {});

}  // namespace coilsim::planning
