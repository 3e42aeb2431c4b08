#include "physics/controller.h"

#include <cmath>
#include <cstdio>

#include "physics/integrator.h"

namespace coilsim {
namespace {

std::string mm(double m) {
  char b[32];
  std::snprintf(b, sizeof b, "%.3g mm", m * 1e3);
  return b;
}

// Moves `value` by rate * dt, at most `left` (< 0: unlimited); returns the step.
double advanceBy(double rate, double& left, double dt) {
  double d = rate * dt;
  if (left >= 0) {
    if (std::abs(d) >= left) d = std::copysign(left, d), left = 0;
    else left -= std::abs(d);
  }
  return d;
}

}  // namespace

std::string DeploymentController::command(const Deployment& dep, const DeploymentState& ds, const DeviceCommand& c) {
  using K = DeviceCommand::Kind;
  if (!std::isfinite(c.rate) || !std::isfinite(c.amount) || c.amount < 0)
    return "refused: rate must be finite and amount finite and >= 0";
  const bool coilMotion = c.kind == K::Push || c.kind == K::Pull || c.kind == K::Twist || c.kind == K::Detach;
  if (coilMotion && ds.detached) return "refused: the coil is detached; it can no longer be pushed, pulled or twisted";
  switch (c.kind) {
    case K::Push:
    case K::Pull: {
      if (!(c.rate > 0) || c.rate > dep.maxPushSpeed)
        return "refused: push/pull speed must be in (0, " + mm(dep.maxPushSpeed) + "/s]";
      const bool push = c.kind == K::Push;
      if (push && ds.deployed >= dep.coilLength - 1e-12) return "refused: the coil is fully deployed";
      if (!push && ds.deployed <= 0) return "refused: the coil is fully inside the catheter";
      if (push && c.amount > dep.coilLength - ds.deployed + 1e-12)
        return "refused: pushing " + mm(c.amount) + " would pass the coil's end (" + mm(dep.coilLength - ds.deployed) +
               " left)";
      if (!push && c.amount > ds.deployed + 1e-12)
        return "refused: pulling " + mm(c.amount) + " is more than the " + mm(ds.deployed) + " outside";
      pushRate_ = push ? c.rate : -c.rate;
      pushLeft_ = c.amount > 0 ? c.amount : -1;
      return {};
    }
    case K::Twist:
      if (c.rate == 0 || std::abs(c.rate) > dep.maxTwistRate) return "refused: twist rate must be non-zero and within the limit";
      twistRate_ = c.rate;
      twistLeft_ = c.amount > 0 ? c.amount : -1;
      return {};
    case K::Stop:
      pushRate_ = twistRate_ = retractRate_ = 0;
      return {};
    case K::Detach:
      if (ds.deployed < dep.coilLength - 1e-9)
        return "refused: the coil is not fully out (" + mm(ds.deployed) + " of " + mm(dep.coilLength) +
               "): push it out before detaching";
      pendingDetach_ = true;
      return {};
    case K::Retract:
      if (!(c.rate > 0) || c.rate > dep.maxPushSpeed)
        return "refused: retraction speed must be in (0, " + mm(dep.maxPushSpeed) + "/s]";
      retractRate_ = c.rate;
      retractLeft_ = c.amount > 0 ? c.amount : -1;
      return {};
  }
  return "refused: unknown command";
}

void DeploymentController::advance(const Deployment& dep, const Model& model, State& state, DeploymentState& ds,
                                   double dt) {
  if (pendingDetach_) {
    pendingDetach_ = false;
    const std::string why = detach(dep, model, state, ds);
    notes.push_back(why.empty() ? "detached" : "refused: " + why);
    pushRate_ = twistRate_ = 0;
  }
  double deployed = ds.deployed, twist = ds.twist;
  if (retractRate_ != 0) {
    const double d = advanceBy(retractRate_, retractLeft_, dt);
    setTipOffset(dep, state, ds, ds.tipOffset + d);
    deployed += d;  // the pusher holds the coil: it is unsheathed as the catheter goes back
    if (retractLeft_ == 0) retractRate_ = 0;
  }
  if (pushRate_ != 0) {
    deployed += advanceBy(pushRate_, pushLeft_, dt);
    if (pushLeft_ == 0) pushRate_ = 0;
  }
  if (twistRate_ != 0) {
    twist += advanceBy(twistRate_, twistLeft_, dt);
    if (twistLeft_ == 0) twistRate_ = 0;
  }
  if (deployed >= dep.coilLength && (pushRate_ > 0 || retractRate_ > 0)) {
    // Said once, when the limit is reached (a push stops on it): retracting
    // the catheter over a coil that is already out hits it every step.
    if (pushRate_ > 0 || ds.deployed < dep.coilLength - 1e-9) notes.push_back("the coil is fully deployed");
    deployed = dep.coilLength;
    pushRate_ = std::min(pushRate_, 0.0);
  }
  if (deployed <= 0 && pushRate_ < 0) {
    deployed = 0;
    pushRate_ = 0;
    notes.push_back("the coil is back inside the catheter");
  }
  if (!ds.detached && (deployed != ds.deployed || twist != ds.twist)) setDeployment(dep, model, state, ds, deployed, twist);
  syncCatheterDrawing(dep, state);
}

TimelineRun runTimeline(const Deployment& dep, const Model& model, State& state, DeploymentState& ds,
                        DeploymentController& controller, const std::vector<TimedCommand>& timeline, double duration) {
  TimelineRun run;
  const double dt = model.timeStep;
  const long steps = long(std::llround(duration / dt));
  size_t next = 0;
  for (long s = 0; s < steps; ++s) {
    const double t = s * dt;
    while (next < timeline.size() && timeline[next].time <= t + 1e-9 * dt) {
      const std::string why = controller.command(dep, ds, timeline[next].command);
      if (!why.empty()) run.log.push_back("t = " + std::to_string(timeline[next].time) + " s: " + why);
      ++next;
    }
    controller.advance(dep, model, state, ds, dt);
    for (const std::string& n : controller.notes) run.log.push_back("t = " + std::to_string(t) + " s: " + n);
    controller.notes.clear();
    const StepReport rep = step(model, state);
    ++run.steps;
    if (!rep.ok()) {
      run.log.push_back("t = " + std::to_string(t) + " s: step refused: " + rep.message);
      run.ok = false;
      break;
    }
  }
  return run;
}

}  // namespace coilsim
