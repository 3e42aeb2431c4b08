#pragma once
// Practice sessions: a trainee drives one coil of a case (push, pull, twist,
// detach, retract, and the view they look through), every input is recorded
// with the step it took effect at, and the session ends with a score sheet.
// Replaying the recording runs the same steps with the same inputs, so it
// reproduces the score sheet bit for bit.
//
// For the window (ui): construct a PracticeSession from a loaded case, call
// command() and setView() from input handlers, step() once per simulation
// step, read model()/state() to draw, and score() / recording() at the end.
// Commands and views take effect at the next step().
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "physics/controller.h"
#include "physics/deployment.h"
#include "physics/model.h"
#include "physics/state.h"
#include "planning/auto_deploy.h"
#include "planning/case_file.h"
#include "planning/metrics.h"

namespace coilsim::planning {

inline constexpr const char* kSessionFormat = "coilsim-session/1";

struct ScoreSheet {
  std::string caseName, coil;
  double time = 0;                 // s of simulated procedure
  double coilLengthPlaced = 0;     // m of coil outside the catheter at the end
  double packingDensity = 0;
  double neckCoverage = 0;
  int occlusion = 3;
  int protrusionEvents = 0;        // times the coil started protruding (sampled every 0.1 s)
  bool protrudingAtEnd = false;
  bool wallForcesAvailable = false;
  double maxWallForce = 0;         // N, largest wall load lasting 5 steps (WallForceStats)
  double timeAboveSafety = 0;      // s with some wall force above the goal's threshold
  double maxTipForce = 0;          // N, force of the coil on the catheter tip felt with the pusher at rest
  int repositionings = 0;          // pulls of the coil back into the catheter
  double fluoroscopyTime = 0;      // s spent in the X-ray (xray or biplane) view
  bool detached = false;
  bool detachInSac = false;        // the catheter tip (detachment zone) was inside the sac at detach
  bool goalMet = false;
  bool ok = true;                  // false: a step was refused
  std::string error;
};

// The score sheet as JSON ("coilsim-score/1"), in edge units (mm, mN, s).
nlohmann::ordered_json scoreJson(const ScoreSheet& s);

class PracticeSession {
 public:
  // Builds the model for the case's coil `coilName` (one of case.coils).
  // Wall forces come from `contacts`, by default the contact layer's (wallContactForces).
  // Throws io::InputError naming the case file if the coil is not in its set
  // or the scene cannot be compiled.
  PracticeSession(const PracticeCase& practiceCase, const std::string& coilName, const ContactForceSource& contacts = {});

  // Starts a device command at the next step; returns "" or why the device refuses it
  // (a refused command is not recorded).
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
  const Deployment& deployment() const { return deployment_; }
  const DeploymentState& deploymentState() const { return ds_; }
  long steps() const { return steps_; }
  const std::string& view() const { return view_; }  // the view looked through now
  double time() const { return double(steps_) * model_.timeStep; }
  const ScoreSheet& runningScore() const { return score_; }

  // The recording: {"format": "coilsim-session/1", "case", "coil", "end_s",
  // "timeline": <coilsim-timeline/1 document>, "views": [{"t_s", "view"}]}.
  nlohmann::ordered_json recording() const;

 private:
  void sample();
  const PracticeCase& case_;
  ContactForceSource contacts_;
  std::string coil_;
  Model model_;
  State state_;
  Deployment deployment_;
  DeploymentState ds_;
  DeploymentController controller_;
  Sac sac_;
  double sacVolume_ = 0;
  NeckGrid neck_;
  long steps_ = 0;
  long fluoroSteps_ = 0;  // steps spent in an X-ray view
  std::string view_ = "3d";
  bool protruding_ = false;
  ScoreSheet score_;
  std::vector<std::vector<double>> forces_;
  WallForceStats wall_;
  FeltTipForce felt_;
  std::vector<nlohmann::ordered_json> recorded_;  // accepted commands as the timeline file holds them
  std::vector<std::pair<double, std::string>> views_;
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
// scripted practice; identical inputs give identical sheets.
ScoreSheet playSession(const PracticeCase& practiceCase, const std::string& coil,
                       const std::vector<TimedCommand>& timeline,
                       const std::vector<std::pair<double, std::string>>& views, double end,
                       nlohmann::ordered_json* recordingOut = nullptr, const ContactForceSource& contacts = {},
                       const std::function<void(const PracticeSession&)>& atEnd = {});

}  // namespace coilsim::planning
