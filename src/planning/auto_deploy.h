#pragma once
// A coil deployed the way a clinician pushes it, headless: push at a set
// speed; when the force at the catheter tip rises above a threshold, stop,
// twist a little (alternating sides) and pause so the loops can find room,
// then push on; when the coil is fully out, let it settle and detach. The
// commands it gives are kept as a timeline, so `coilsim run --input` can
// replay the same deployment. Measures, step by step, the tip (deployment)
// force, the catheter kickback and the wall forces, and at the end the sac
// metrics.
#include <functional>
#include <string>
#include <vector>

#include "physics/controller.h"
#include "physics/deployment.h"
#include "physics/model.h"
#include "physics/state.h"
#include "planning/metrics.h"

namespace coilsim::planning {

struct AutoDeployOptions {
  double pushSpeed = 5e-3;       // m/s (clinical: 1-10 mm/s)
  double forceThreshold = 5e-3;  // N at the tip that makes the operator stop and twist
  double twistAngle = M_PI / 6;  // rad per correction
  double twistRate = M_PI;       // rad/s
  double pause = 0.2;            // s of rest after a twist before pushing on
  double settle = 0.5;           // s after full deployment before detach
  double afterDetach = 0.2;      // s simulated after detach
  double maxTime = 600;          // s: give up (reported) beyond this
  double wallForceThreshold = 0.05;  // N: wall load counted as "above the safety threshold"
};

// Per-node wall (contact) force magnitudes of every rod, N, or false when
// there are none to read (no wall contact in the scene): then wall forces
// are reported as unavailable, never as zero.
using ContactForceSource = std::function<bool(const Model&, const State&, std::vector<std::vector<double>>&)>;

struct AutoDeployResult {
  bool ok = true;              // false: a step was refused (blow-up) or maxTime passed
  std::string error;
  double time = 0;             // s simulated
  long steps = 0;
  double maxTipForce = 0;      // N, largest elastic force of the coil on the catheter tip
  double maxDeploymentForce = 0;  // N, largest axial (push) component of it
  double maxKickback = 0;      // m the catheter tip moved back along its axis
  int corrections = 0;         // stop-and-twist manoeuvres
  bool wallForcesAvailable = false;
  WallForceStats wall;
  std::vector<TimedCommand> timeline;  // what was commanded, replayable
  std::vector<std::string> log;
};

// Tip force of a deployment now: the elastic force of the first beam outside the catheter on the tip node.
Vec3 tipForce(const Deployment& dep, const State& state);

// Runs the deployment from the state's current configuration to detach.
AutoDeployResult autoDeploy(const Deployment& dep, const Model& model, State& state, DeploymentState& ds,
                            const AutoDeployOptions& options, const ContactForceSource& contacts = {});

}  // namespace coilsim::planning
