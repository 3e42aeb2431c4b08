#pragma once
// A coil deployed the way a clinician pushes it, headless: push a short
// stroke at a set speed, stop and feel the resistance; when the force at the
// catheter tip is above a threshold, twist a little (alternating sides) and
// let the loops find room until the felt force has decayed; if it stays
// high, push on through moderate resistance, and pull back a little to
// re-advance when it is high; when the coil is fully out, let it settle
// until it is still and detach. A coil that still meets a high resistance
// after the pull-backs is reported as not placed (it does not fit), never
// pushed on for ever. The commands it gives are kept as a timeline, so
// `coilsim run --input` can replay the same deployment.
// Measures the felt tip (deployment) force, the catheter kickback and the
// wall forces, and at the end the sac metrics.
#include <functional>
#include <string>
#include <vector>

#include "physics/run.h"
#include "physics/deployment.h"
#include "physics/model.h"
#include "physics/state.h"
#include "planning/metrics.h"

namespace coilsim::planning {

struct AutoDeployOptions {
  double pushSpeed = 5e-3;       // m/s (clinical: 1-10 mm/s)
  double stroke = 1e-3;          // m pushed between two feels of the resistance
  double forceThreshold = 5e-3;  // N felt at the tip that makes the operator stop and twist
  double hardLimitFactor = 3;    // above forceThreshold times this, pull back instead of pushing on
  int maxTwists = 3;             // corrections at one place before pushing on (or pulling back)
  int maxPullBacks = 3;          // pull-backs without progress before the coil is given up
  double pullBack = 2e-3;        // m pulled back to re-advance
  double twistAngle = M_PI / 6;  // rad per correction
  double twistRate = M_PI;       // rad/s
  double pause = 0.2;            // s: longest rest after a twist before feeling again
  // N: the rest after a twist ends once the felt force has decayed to within
  // this of where it is going (ForceDecay); 0: always the whole pause.
  double pauseTolerance = 0.5e-3;
  double decayWindow = 0.01;     // s: ForceDecay's lag
  double settle = 0.5;           // s: longest wait after full deployment before detach
  double afterDetach = 0.2;      // s: longest simulated after detach
  // m/s: the settling before detach, and the run after it, end once no node
  // of the coil has moved faster than this for decayWindow; 0: always the whole time.
  double settleSpeed = 0;
  double maxTime = 0;            // s: give up (reported) beyond this; 0: 60 s + 4 L / pushSpeed
  double wallForceThreshold = 0.05;  // N: wall load counted as "above the safety threshold"
};

// Whether a run has wall forces to report (its wall load, State::stats and
// RodContacts::wallForce, kept by the contact layer): false when the scene
// has no wall contact, and then they are reported as unavailable, never as
// zero.
using WallForceCheck = std::function<bool(const Model&, const State&)>;

struct AutoDeployResult {
  bool ok = true;              // false: a step was refused (blow-up) or maxTime passed
  bool placed = false;         // the coil was pushed out fully and detached
  std::string error;           // why not ok
  std::string notPlaced;       // why the operator gave the coil up (ok, but not placed)
  double time = 0;             // s simulated
  long steps = 0;
  double deployed = 0;         // m out of the catheter at the end
  double maxTipForce = 0;      // N, largest felt force of the coil on the catheter tip
  double maxDeploymentForce = 0;  // N, largest felt axial (push) component of it
  double maxKickback = 0;      // m the catheter tip moved back along its axis
  int corrections = 0;         // stop-and-twist manoeuvres
  int pullBacks = 0;           // repositionings (pull back, re-advance)
  bool wallForcesAvailable = false;
  WallForceStats wall;
  // Deepest wall penetration of the wire seen at any step's contact
  // detection (State::stats), m and as a fraction of the wire radius there.
  double maxWallPenetration = 0, maxWallPenetrationOfRadius = 0;
  std::vector<TimedCommand> timeline;  // what was commanded, replayable
  std::vector<std::string> log;
  // Where a run's time goes: steps by what the operator was doing, steps
  // retaken in substeps, and the wall time of the steps against that of
  // the operator's own work (feeling, wall-load bookkeeping, decisions).
  struct Effort {
    long pushing = 0, feeling = 0, twisting = 0, pausing = 0, pullingBack = 0, settling = 0, afterDetach = 0;
    long substepped = 0;
    double stepSeconds = 0, operatorSeconds = 0;
  } effort;
};

// Tip force of a deployment now: the elastic force of the first beam outside the catheter on the tip node.
Vec3 tipForce(const Deployment& dep, const State& state);

// The tip force as a hand feels it. While the coil slides, the tip beam's
// force is dominated by the sliding itself (the partial beam at the tip
// changes its rest length every step and a node is inserted every spacing,
// giving spikes of up to newtons that last a step or two); a clinician
// feels the resistance when the pusher rests. So the felt force is the tip
// force averaged over `window` s once the pusher has not moved for `window` s.
class FeltTipForce {
 public:
  explicit FeltTipForce(double window = 0.02) : window_(window) {}
  // One step, after it was taken: `still` when the pusher did not move
  // (push, pull or twist) during it. Returns true when a felt value is available: the pusher has
  // rested `window` s; `felt` and `axial` (N) then follow the tip force with
  // a time constant of window / 4, started window / 2 into the rest (past
  // the decay of the sliding transients).
  bool add(const Deployment& dep, const State& state, bool still, double dt);
  double felt = 0, axial = 0;

 private:
  double window_, stillTime_ = 0;
};

// Whether a sampled signal has settled, for ending a rest as soon as what
// it waits for is over. Settled when, over the last 2 lags, the signal moved
// by at most `tolerance`, and an exponential decay through its values at
// t - 2 lag, t - lag and t has at most `tolerance` still to go (the tail of
// the geometric series of its steps, d2 r / (1 - r), r = d2 / d1).
class ForceDecay {
 public:
  ForceDecay(double lag, double tolerance, double dt);
  void reset() { count_ = 0; }
  // One sample; returns true once settled (false before 2 lags of samples).
  bool add(double value);

 private:
  size_t lag_;
  double tolerance_;
  std::vector<double> ring_;  // (2 lag + 1) latest samples
  size_t count_ = 0;
};

// Told every 100 steps how far a deployment is: m of coil out, s simulated.
using DeployProgress = std::function<void(double deployed, double time)>;

// Runs the model's deployment from the state's current configuration to
// detach (or until the operator gives up, or maxTime).
AutoDeployResult autoDeploy(const Model& model, State& state, const AutoDeployOptions& options,
                            const WallForceCheck& contacts = {}, const DeployProgress& progress = {});

}  // namespace coilsim::planning
