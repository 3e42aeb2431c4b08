// The automatic operator: push in strokes, feel, twist or pull back on
// resistance, settle, detach; give up honestly when the coil does not fit.
#include "planning/auto_deploy.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>

#include "io/units.h"
#include "physics/integrator.h"

namespace coilsim::planning {
namespace {

std::string mmText(double m) {
  char b[32];
  std::snprintf(b, sizeof b, "%.1f mm", units::mToMm(m));
  return b;
}
std::string mNText(double n) {
  char b[32];
  std::snprintf(b, sizeof b, "%.2f mN", units::nToMn(n));
  return b;
}
std::string sText(double s) {
  char b[32];
  std::snprintf(b, sizeof b, "t = %.3f s", s);
  return b;
}

// Adds the wall time from its construction to its end to `total`.
struct Clock {
  explicit Clock(double& total) : total_(total), start_(std::chrono::steady_clock::now()) {}
  ~Clock() { total_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count(); }
  double& total_;
  std::chrono::steady_clock::time_point start_;
};

}  // namespace

Vec3 tipForce(const Deployment& dep, const State& state) { return coilForceOnTip(dep, state); }

bool FeltTipForce::add(const Deployment& dep, const State& state, bool still, double dt) {
  if (!still) {
    stillTime_ = 0;
    return false;
  }
  stillTime_ += dt;
  if (stillTime_ < 0.5 * window_) return false;
  const Vec3 f = tipForce(dep, state);
  // Axial part along the first coil beam out of the tip: what the pusher feels.
  const RodState& chain = state.rods[size_t(dep.chainRod)];
  const size_t t = size_t(dep.tipNode);
  const double ax = chain.activeNodes > int(t) + 1 ? -f.dot((chain.x[t + 1] - chain.x[t]).normalized()) : 0.0;
  if (stillTime_ < 0.5 * window_ + 0.5 * dt) {
    felt = f.norm(), axial = ax;  // first sample of this rest
  } else {
    const double a = std::min(1.0, dt / (0.25 * window_));
    felt += a * (f.norm() - felt);
    axial += a * (ax - axial);
  }
  return stillTime_ >= window_ - 0.5 * dt;
}

ForceDecay::ForceDecay(double lag, double tolerance, double dt)
    : lag_(size_t(std::max(1.0, std::round(lag / dt)))), tolerance_(tolerance), ring_(2 * lag_ + 1) {}

bool ForceDecay::add(double value) {
  const size_t n = ring_.size();
  ring_[count_ % n] = value;
  ++count_;
  if (count_ < n) return false;
  const size_t now = count_ - 1;
  const double a = ring_[(now - 2 * lag_) % n], b = ring_[(now - lag_) % n], c = value;
  const auto [lo, hi] = std::minmax_element(ring_.begin(), ring_.end());
  if (*hi - *lo > tolerance_) return false;
  // Still decaying one way, each lag by a factor r: what is left is d2 (r + r^2 + ...).
  const double d1 = b - a, d2 = c - b;
  if (d1 * d2 > 0 && std::abs(d2) < std::abs(d1)) {
    const double r = d2 / d1;
    if (std::abs(d2) * r / (1 - r) > tolerance_) return false;
  }
  return true;
}

namespace {

// The fastest node of a rod, m/s.
double fastestNode(const RodState& rod) {
  double v2 = 0;
  for (int i = 0; i < rod.activeNodes; ++i) v2 = std::max(v2, rod.v[size_t(i)].squaredNorm());
  return std::sqrt(v2);
}

}  // namespace

AutoDeployResult autoDeploy(const Model& model, State& state, const AutoDeployOptions& o,
                            const WallForceCheck& contacts, const DeployProgress& progress) {
  using Kind = DeviceCommand::Kind;
  AutoDeployResult r;
  const Deployment& dep = *model.device;
  const DeviceState& ds = state.device;
  const double dt = model.timeStep;
  const double probe = 0.02;  // s the pusher rests to feel the resistance
  FeltTipForce feel(probe);
  enum class Phase { Stroke, Feel, Twist, Pause, PullBack, Settle, After } phase = Phase::Feel;
  const auto countStep = [](AutoDeployResult::Effort& e, Phase p) {
    long* counts[] = {&e.pushing, &e.feeling, &e.twisting, &e.pausing, &e.pullingBack, &e.settling, &e.afterDetach};
    ++*counts[int(p)];
  };
  double phaseEnd = 0, twistSign = 1;
  ForceDecay decay(o.decayWindow, o.pauseTolerance, dt);
  bool decayed = false;             // the felt force has decayed since the last twist
  double stillFor = 0, settleStart = 0;  // s the coil has been still (settling, after detach)
  int twistsHere = 0, pullBacksHere = 0;
  double progressMark = ds.deployed;  // deployed length at the last pull-back reset
  auto issue = [&](double t, const DeviceCommand& c) {
    const std::optional<Failure> refused = command(model, state, c);
    if (refused) r.log.push_back(sText(t) + ": " + describe(*refused));
    else r.timeline.push_back({t, c});
    return !refused;
  };
  auto stroke = [&](double t) {
    const double left = dep.coilLength - ds.deployed;
    issue(t, {Kind::Push, o.pushSpeed, std::min(o.stroke, left)});
    phase = Phase::Stroke;
  };
  const double maxTime = o.maxTime > 0 ? o.maxTime : 60 + 4 * dep.coilLength / o.pushSpeed;
  const long maxSteps = long(std::ceil(maxTime / dt));
  for (long s = 0; s < maxSteps; ++s) {
    const double t = double(s) * dt;  // exactly the time runTimeline applies commands at
    const bool fullyOut = ds.deployed >= dep.coilLength - 1e-12;
    if (phase == Phase::Stroke && !ds.motion.moving()) {
      phase = Phase::Feel;
    } else if (phase == Phase::Feel && fullyOut && !ds.detached) {
      phase = Phase::Settle, phaseEnd = t + o.settle, settleStart = t, stillFor = 0;
    } else if (phase == Phase::Twist && t >= phaseEnd - 1e-12) {
      phase = Phase::Pause, phaseEnd = t + o.pause;
    } else if (phase == Phase::Pause && (decayed || t >= phaseEnd - 1e-12)) {
      phase = Phase::Feel;
    } else if (phase == Phase::PullBack && !ds.motion.moving()) {
      phase = Phase::Feel;
    } else if (phase == Phase::Settle && (stillFor >= o.decayWindow - 0.5 * dt || t >= phaseEnd - 1e-12)) {
      char settled[64];
      std::snprintf(settled, sizeof settled, ": detaching after %.3f s of settling", t - settleStart);
      r.log.push_back(sText(t) + settled);
      issue(t, {Kind::Detach, 0, 0});
      phase = Phase::After, phaseEnd = t + o.afterDetach, stillFor = 0;
    } else if (phase == Phase::After && (stillFor >= o.decayWindow - 0.5 * dt || t >= phaseEnd - 1e-12)) {
      r.time = t;
      r.placed = ds.detached;
      r.deployed = ds.deployed;
      return r;
    }
    const double before = ds.deployed, twistBefore = ds.twist;
    const long substeppedBefore = state.substepped;
    const auto t0 = std::chrono::steady_clock::now();
    const StepReport rep = advance(model, state);  // a shock at detach is split into substeps by step() itself
    const auto t1 = std::chrono::steady_clock::now();
    r.effort.stepSeconds += std::chrono::duration<double>(t1 - t0).count();
    r.effort.substepped += state.substepped - substeppedBefore;
    countStep(r.effort, phase);
    if (progress && s % 100 == 0) progress(ds.deployed, t);
    const Clock operatorWork(r.effort.operatorSeconds);
    for (const std::string& n : state.device.notes) r.log.push_back(sText(t) + ": " + n);
    state.device.notes.clear();
    const bool pusherMoved = ds.deployed != before || ds.twist != twistBefore;  // pushed, pulled or twisted
    ++r.steps;
    if (!rep.ok()) {
      r.ok = false;
      r.error = "step refused at " + sText(t) + ": " + rep.message();
      r.time = t, r.deployed = ds.deployed;
      return r;
    }
    r.maxKickback = std::max(r.maxKickback, catheterTip(model, state).kickback);
    r.maxWallPenetration = state.stats.maxWallPenetration;
    r.maxWallPenetrationOfRadius = state.stats.maxWallPenetrationOfRadius;
    if (contacts && contacts(model, state)) {
      r.wallForcesAvailable = true;
      r.wall.add(state, dt, o.wallForceThreshold);
    }
    if (phase == Phase::Settle || phase == Phase::After) {
      const RodState& coil = state.rods[size_t(ds.detached ? dep.freeRod : dep.chainRod)];
      stillFor = o.settleSpeed > 0 && fastestNode(coil) < o.settleSpeed ? stillFor + dt : 0;
    }
    if (ds.detached) continue;
    const bool felt = feel.add(dep, state, !pusherMoved, dt);
    if (felt) {
      r.maxTipForce = std::max(r.maxTipForce, feel.felt);
      r.maxDeploymentForce = std::max(r.maxDeploymentForce, feel.axial);
      if (phase == Phase::Pause && o.pauseTolerance > 0) decayed = decay.add(feel.felt);
    }
    if (phase != Phase::Feel || !felt) continue;
    // The operator's decision, on the resistance felt at rest.
    const double tNext = double(s + 1) * dt;
    if (ds.deployed >= dep.coilLength - 1e-12) continue;  // next step: settle
    if (ds.deployed > progressMark + 0.5 * o.stroke) progressMark = ds.deployed, pullBacksHere = 0;
    if (feel.felt <= o.forceThreshold) {
      twistsHere = 0;
      stroke(tNext);
    } else if (twistsHere < o.maxTwists) {
      issue(tNext, {Kind::Twist, twistSign * o.twistRate, o.twistAngle});
      twistSign = -twistSign;
      ++twistsHere, ++r.corrections;
      phase = Phase::Twist, phaseEnd = tNext + o.twistAngle / o.twistRate;
      decay.reset(), decayed = false;
    } else if (feel.felt <= o.hardLimitFactor * o.forceThreshold) {
      r.log.push_back(sText(tNext) + ": pushing on through " + mNText(feel.felt) + " at " + mmText(ds.deployed));
      twistsHere = 0;
      stroke(tNext);
    } else if (pullBacksHere < o.maxPullBacks && ds.deployed > 0) {
      r.log.push_back(sText(tNext) + ": " + mNText(feel.felt) + " at " + mmText(ds.deployed) + ": pulling back");
      issue(tNext, {Kind::Pull, o.pushSpeed, std::min(o.pullBack, ds.deployed)});
      ++pullBacksHere, ++r.pullBacks;
      twistsHere = 0;
      phase = Phase::PullBack;
    } else {
      r.time = tNext;
      r.deployed = ds.deployed;
      r.notPlaced = "the coil does not fit: the tip force stays at " + mNText(feel.felt) + " (limit " +
                    mNText(o.hardLimitFactor * o.forceThreshold) + ") after " + std::to_string(o.maxTwists) +
                    " twists and " + std::to_string(o.maxPullBacks) + " pull-backs, with " + mmText(ds.deployed) +
                    " of " + mmText(dep.coilLength) + " out";
      return r;
    }
  }
  r.ok = false;
  r.time = maxTime;
  r.deployed = ds.deployed;
  r.error = "the coil was not detached within " + std::to_string(maxTime) + " s of simulated time (" +
            mmText(ds.deployed) + " of " + mmText(dep.coilLength) + " out)";
  return r;
}

}  // namespace coilsim::planning
