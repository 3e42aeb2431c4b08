#pragma once
// The score sheet and the recording of a practice session, kept step by step
// from whoever steps the physics: PracticeSession (scripted and replayed
// sessions) and the window (coilsim practice --window --record). Both call
// the same hooks in the same order around each step, so a window session and
// the replay of its recording give the same sheet.
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "physics/run.h"
#include "physics/deployment.h"
#include "physics/model.h"
#include "physics/state.h"
#include "planning/case_file.h"
#include "planning/contact_forces.h"
#include "planning/metrics.h"

namespace coilsim::planning {

inline constexpr const char* kSessionFormat = "coilsim-session/1";

// One coil of a session with several: when it went in and how it was left.
struct CoilOutcome {
  std::string coil;
  double from = 0;          // s of session time it went in at
  double lengthPlaced = 0;  // m of it outside the catheter when it was left (or at the end)
  bool detached = false, detachInSac = false;
};

struct ScoreSheet {
  std::string caseName, coil;      // coil: the coils' names joined by " + "
  double time = 0;                 // s of simulated procedure
  double coilLengthPlaced = 0;     // m of coil outside the catheter at the end
  double packingDensity = 0;
  double neckCoverage = 0;
  int occlusion = 3;
  int protrusionEvents = 0;        // times the coil started protruding (sampled every 0.1 s)
  bool protrudingAtEnd = false;
  bool wallForcesAvailable = false;
  double maxWallForce = 0;         // N, largest sustained wall load (physics/contact/wall_load.h: lasting 5 ms)
  double timeAboveSafety = 0;      // s with some wall force above the goal's threshold
  // Deepest the wire went past the wall's skin at any step's contact
  // detection, in m and in wire radii (State::stats, since the session's start).
  double maxWallPenetration = 0, maxWallPenetrationOfRadius = 0;
  double maxTipForce = 0;          // N, force of the coil on the catheter tip felt with the pusher at rest
  int repositionings = 0;          // pulls of the coil back into the catheter
  double fluoroscopyTime = 0;      // s spent in the X-ray (xray or biplane) view
  bool detached = false;
  // At detach the catheter tip (the detachment zone) was inside the sac and
  // no coil protruded through the neck (a coil detached half in the parent
  // vessel is not detached in the sac, wherever the tip was).
  bool detachInSac = false;
  Goal goal;                       // what was judged
  bool goalMet = false;
  std::vector<std::string> goalMissed;  // why not, one line per part of the goal missed
  bool ok = true;                  // false: a step was refused
  std::string error;
  // Device commands refused and device limits reached ("t = 0.000 s: refused:
  // the coil is not fully out ..."), in time order: nothing a trainee did is dropped unsaid.
  std::vector<std::string> deviceMessages;
  // Every coil of the session, in order (packing, neck coverage, protrusion
  // and the wall figures above are of all of them together; coil length,
  // detached and detach in sac sum or require every coil).
  std::vector<CoilOutcome> coils;
};

// The score sheet as JSON ("coilsim-score/1"), in edge units (mm, mN, s,
// packing and neck coverage in percent), with the goal it judged.
nlohmann::ordered_json scoreJson(const ScoreSheet& s);

// One command as a timeline file holds it ({"t_s", "push": {...}}), edge units.
nlohmann::ordered_json commandJson(const TimedCommand& t);
// The command as a replay will read it back from that JSON (through the
// file's units), so a live session runs exactly the numbers its replay runs.
DeviceCommand asRecorded(const DeviceCommand& c);

// True for the views that count as fluoroscopy time: "xray" and "biplane".
bool fluoroscopic(const std::string& view);

class SessionScorer {
 public:
  // Scores `coil` of `practiceCase` deployed by `dep` with time step `dt` (s);
  // whether there are wall forces says `contacts` (empty: the contact layer's hasWallForces).
  SessionScorer(const PracticeCase& practiceCase, const std::string& coil, const Deployment& dep, double dt,
                const WallForceCheck& contacts = {});

  // Inputs, at the session time `t` (steps x dt) they take effect from.
  // `recorded` is what the file gets (commandJson of the command as given).
  void commandAccepted(double t, const nlohmann::ordered_json& recorded, const DeviceCommand& applied);
  void viewChanged(double t, const std::string& view);
  // The next coil goes in at session time `t` through `dep`; `left` is the
  // state the running coil was left in (detached).
  void coilChanged(double t, const std::string& coil, const Deployment& dep, const State& left);
  // A refused command or a device limit reached, at the session time so far
  // (the score sheet's device_messages).
  void deviceMessage(const std::string& message);

  // Around every advance (the device moves, then the physics steps), with
  // the step's report. A refused step ends the scoring (nothing later
  // counts; the sheet's error names the session time and the Failure).
  void beforeStep(const State& state);
  void afterStep(const Model& model, const State& state, const StepReport& report);

  // The sheet at the end (final metrics, goal check).
  ScoreSheet finish(const Model& model, const State& state) const;
  // The recording: {"format": "coilsim-session/1", "case", "coil", "end_s",
  // "timeline": <coilsim-timeline/1 document>, "views": [{"t_s", "view"}]},
  // and "next_coils": [{"t_s", "coil"}] after "coil" when there were several.
  nlohmann::ordered_json recording(double end) const;

  const ScoreSheet& running() const { return score_; }
  const std::string& view() const { return view_; }
  double time() const { return double(steps_) * dt_; }  // s, steps scored so far
  bool scoring() const { return score_.ok; }

 private:
  SacMetrics measure(const Model& model, const State& state) const;

  const PracticeCase& case_;
  WallForceCheck contacts_;
  std::string coil_;               // the running coil
  std::vector<CoilOutcome> left_;  // the coils before it
  double coilFrom_ = 0;            // s, when the running coil went in
  bool coilDetached_ = false, coilInSac_ = false;
  Deployment dep_;
  double dt_ = 0;
  Sac sac_;
  double sacVolume_ = 0;
  NeckGrid neck_;
  long steps_ = 0;
  long fluoroSteps_ = 0;  // steps spent in an X-ray view
  std::string view_ = "3d";
  bool protruding_ = false;
  bool wasDetached_ = false;
  double deployedBefore_ = 0, twistBefore_ = 0;
  ScoreSheet score_;
  WallForceStats wall_;
  FeltTipForce felt_;
  std::vector<nlohmann::ordered_json> recorded_;  // accepted commands as the timeline file holds them
  std::vector<std::pair<double, std::string>> views_;
  std::vector<std::pair<double, std::string>> recordedCoils_;  // the next coils at their times
};

}  // namespace coilsim::planning
