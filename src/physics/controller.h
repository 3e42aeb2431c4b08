#pragma once
// The device as a clinician drives it: push and pull the coil at a speed, by
// a distance; twist at a rate, by an angle; detach; retract the catheter.
// One controller API for the UI, scripted timelines and tests. Commands are
// checked against what the real device allows and refused with a reason,
// never by crashing.
#include <string>
#include <vector>

#include "physics/deployment.h"

namespace coilsim {

struct DeviceCommand {
  enum class Kind { Push, Pull, Twist, Stop, Detach, Retract };
  Kind kind = Kind::Stop;
  double rate = 0;    // m/s for push / pull / retract, rad/s for twist (signed: + right-hand about the exit direction)
  double amount = 0;  // m or rad to move; 0 = keep going until stopped or a limit is reached
};

struct TimedCommand {
  double time = 0;  // s
  DeviceCommand command;
};

class DeploymentController {
 public:
  // Starts the command; returns "" or why it was refused (and changes nothing).
  std::string command(const Deployment& dep, const DeploymentState& ds, const DeviceCommand& c);
  // Advances the motions by dt and applies them to the deployment; call before step().
  void advance(const Deployment& dep, const Model& model, State& state, DeploymentState& ds, double dt);
  bool moving() const { return pushRate_ != 0 || twistRate_ != 0 || retractRate_ != 0; }
  std::vector<std::string> notes;  // limits reached ("coil fully deployed"), for UI and logs

 private:
  double pushRate_ = 0, pushLeft_ = 0;      // m/s (signed), m (<0: unlimited)
  double twistRate_ = 0, twistLeft_ = 0;    // rad/s (signed), rad
  double retractRate_ = 0, retractLeft_ = 0;
  bool pendingDetach_ = false;
};

// Runs a timeline: commands are applied at the first step whose start time
// (step index * dt) is at or after their time, so a replay is bit-for-bit.
// Stops after `duration` s. Refused commands and refused steps are reported
// in `log`; returns false if a step was refused (numerical blow-up).
struct TimelineRun {
  std::vector<std::string> log;
  long steps = 0;
  bool ok = true;
};
TimelineRun runTimeline(const Deployment& dep, const Model& model, State& state, DeploymentState& ds,
                        DeploymentController& controller, const std::vector<TimedCommand>& timeline, double duration);

}  // namespace coilsim
