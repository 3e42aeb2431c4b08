#include "physics/run.h"

#include <cmath>
#include <cstdio>

#include "physics/contact/clearance.h"
#include "physics/contact/detect.h"
#include "physics/deployment.h"

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

// A command the device does not allow; describe() says "refused: " first.
Failure refusal(std::string why, const char* quantity = "", double value = NAN, double limit = NAN) {
  Failure f;
  f.kind = FailureKind::DeviceRefusal;
  f.quantity = quantity, f.value = value, f.limit = limit;
  f.text = std::move(why);
  return f;
}

}  // namespace

std::optional<Failure> command(const Model& model, State& state, const DeviceCommand& c) {
  using K = DeviceCommand::Kind;
  if (!model.device) return refusal("this run has no device to command");
  const Deployment& dep = *model.device;
  const DeviceState& ds = state.device;
  DeviceMotion& m = state.device.motion;
  if (!std::isfinite(c.rate) || !std::isfinite(c.amount) || c.amount < 0)
    return refusal("rate must be finite and amount finite and >= 0");
  const bool coilMotion = c.kind == K::Push || c.kind == K::Pull || c.kind == K::Twist || c.kind == K::Detach;
  if (coilMotion && ds.detached) return refusal("the coil is detached; it can no longer be pushed, pulled or twisted");
  switch (c.kind) {
    case K::Push:
    case K::Pull: {
      if (!(c.rate > 0) || c.rate > dep.maxPushSpeed)
        return refusal("push/pull speed must be in (0, " + mm(dep.maxPushSpeed) + "/s]", "push speed", c.rate,
                       dep.maxPushSpeed);
      const bool push = c.kind == K::Push;
      if (push && ds.deployed >= dep.coilLength - 1e-12) return refusal("the coil is fully deployed");
      if (!push && ds.deployed <= 0) return refusal("the coil is fully inside the catheter");
      if (push && c.amount > dep.coilLength - ds.deployed + 1e-12)
        return refusal("pushing " + mm(c.amount) + " would pass the coil's end (" + mm(dep.coilLength - ds.deployed) +
               " left)");
      if (!push && c.amount > ds.deployed + 1e-12)
        return refusal("pulling " + mm(c.amount) + " is more than the " + mm(ds.deployed) + " outside");
      m.pushRate = push ? c.rate : -c.rate;
      m.pushLeft = c.amount > 0 ? c.amount : -1;
      return std::nullopt;
    }
    case K::Twist:
      if (c.rate == 0 || std::abs(c.rate) > dep.maxTwistRate) return refusal("twist rate must be non-zero and within the limit", "twist rate", c.rate,
                                                                     dep.maxTwistRate);
      m.twistRate = c.rate;
      m.twistLeft = c.amount > 0 ? c.amount : -1;
      return std::nullopt;
    case K::Stop:
      m.pushRate = m.twistRate = m.retractRate = 0;
      return std::nullopt;
    case K::Detach:
      if (ds.deployed < dep.coilLength - 1e-9)
        return refusal("the coil is not fully out (" + mm(ds.deployed) + " of " + mm(dep.coilLength) +
               "): push it out before detaching");
      m.pendingDetach = true;
      return std::nullopt;
    case K::Retract:
      if (!(c.rate > 0) || c.rate > dep.maxPushSpeed)
        return refusal("retraction speed must be in (0, " + mm(dep.maxPushSpeed) + "/s]", "retraction speed", c.rate,
                       dep.maxPushSpeed);
      m.retractRate = c.rate;
      m.retractLeft = c.amount > 0 ? c.amount : -1;
      return std::nullopt;
  }
  return refusal("unknown command");
}

// How deep, as a fraction of the two wires' radii, the catheter tip may
// press a wire that rests on a wall before a retraction stops (moveDevice).
constexpr double kPinnedWire = 0.01;

// A pull draws the coil in with whatever force it takes. A coil pulled
// freely through the sac is held back at the tip by its drag, millinewtons;
// one caught (a loop wedged between the tip and the wall, or on the coil's
// own loops) is pulled ever harder, and the pull squeezed it into the wall
// (docs/contact.md, "Three more ways past the skin"). So a pull stops once
// the tension stays above kCaughtTension for kCaughtTime: longer than the
// one-step spikes, up to tens of newtons, that a node drawn in at the tip
// gives.
constexpr double kCaughtTension = 0.1;  // N
constexpr double kCaughtTime = 0.005;   // s

// Whether the coil pulls on the catheter tip, along its first beam, harder than kCaughtTension.
bool caughtAtTip(const Deployment& dep, const State& state) {
  const RodState& chain = state.rods[size_t(dep.chainRod)];
  const size_t t = size_t(dep.tipNode);
  if (chain.activeNodes < dep.tipNode + 2) return false;
  const Vec3 out = (chain.x[t + 1] - chain.x[t]).normalized();
  return coilForceOnTip(dep, state).dot(out) > kCaughtTension;
}

void moveDevice(const Model& model, State& state) {
  if (!model.device) return;
  const double dt = model.timeStep;
  const Deployment& dep = *model.device;
  DeviceState& ds = state.device;
  DeviceMotion& m = ds.motion;
  std::vector<std::string>& notes = ds.notes;
  if (m.pendingDetach) {
    m.pendingDetach = false;
    const std::optional<Failure> refused = detach(model, state);
    notes.push_back(refused ? describe(*refused) : "detached");
    m.pushRate = m.twistRate = 0;
  }
  double deployed = ds.deployed, twist = ds.twist;
  if (m.retractRate != 0) {
    // The catheter holds the coil's tip node by prescription, so no contact
    // can stop it: a retraction that would carry the tip into a wall's skin
    // (a closed phantom whose catheter path leaves through its wall) stops
    // at the wall instead (docs/contact.md, "The soak's penetration").
    const RodState& chain = state.rods[size_t(dep.chainRod)];
    const double keep = (1 + kWallSkin) * chain.nodes[size_t(dep.tipNode)].radius;
    const double step = std::abs(m.retractRate) * dt;
    const Vec3 tipNow = ds.tipStart - ds.tipOffset * dep.retractDirection;
    const double before = wallClearance(model, tipNow, keep + 2 * step);
    const double after = wallClearance(model, tipNow - step * dep.retractDirection, keep + 2 * step);
    // Nor may it pin the coil against a wall: a loop lying on the wall
    // behind the tip was squeezed into it (docs/contact.md, "Three more ways
    // past the skin").
    const double pinned =
        pinnedWireDepth(state, dep.chainRod, dep.tipNode, -std::copysign(step, m.retractRate) * dep.retractDirection);
    if (after < keep && after < before) {
      m.retractRate = 0, m.retractLeft = 0;
      notes.push_back("the catheter tip is at the wall: retraction stopped");
    } else if (pinned > kPinnedWire) {
      m.retractRate = 0, m.retractLeft = 0;
      notes.push_back("the catheter tip pins the coil against the wall: retraction stopped");
    } else {
      const double d = advanceBy(m.retractRate, m.retractLeft, dt);
      setTipOffset(model, state, ds.tipOffset + d);
      deployed += d;  // the pusher holds the coil: it is unsheathed as the catheter goes back
      if (m.retractLeft == 0) m.retractRate = 0;
    }
  }
  m.caughtFor = m.pushRate < 0 && caughtAtTip(dep, state) ? m.caughtFor + dt : 0.0;
  if (m.caughtFor >= kCaughtTime) {
    m.pushRate = 0, m.pushLeft = 0, m.caughtFor = 0;
    notes.push_back("the coil is caught: pull stopped");
  } else if (m.pushRate != 0) {
    deployed += advanceBy(m.pushRate, m.pushLeft, dt);
    if (m.pushLeft == 0) m.pushRate = 0;
  }
  if (m.twistRate != 0) {
    twist += advanceBy(m.twistRate, m.twistLeft, dt);
    if (m.twistLeft == 0) m.twistRate = 0;
  }
  if (deployed >= dep.coilLength && (m.pushRate > 0 || m.retractRate > 0)) {
    // Said once, when the limit is reached (a push stops on it): retracting
    // the catheter over a coil that is already out hits it every step.
    if (m.pushRate > 0 || ds.deployed < dep.coilLength - 1e-9) notes.push_back("the coil is fully deployed");
    deployed = dep.coilLength;
    m.pushRate = std::min(m.pushRate, 0.0);
  }
  if (deployed <= 0 && m.pushRate < 0) {
    deployed = 0;
    m.pushRate = 0;
    notes.push_back("the coil is back inside the catheter");
  }
  if (!ds.detached && (deployed != ds.deployed || twist != ds.twist)) setDeployment(model, state, deployed, twist);
  syncCatheterDrawing(model, state);
}

StepReport advance(const Model& model, State& state) {
  moveDevice(model, state);
  return step(model, state);
}

TimelineRun runTimeline(const Model& model, State& state, const std::vector<TimedCommand>& timeline, double duration,
                        const std::function<bool()>& keepGoing) {
  TimelineRun run;
  const double dt = model.timeStep;
  const long steps = long(std::llround(duration / dt));
  size_t next = 0;
  for (long s = 0; s < steps; ++s) {
    const double t = s * dt;
    while (next < timeline.size() && timeline[next].time <= t + 1e-9 * dt) {
      if (const std::optional<Failure> no = command(model, state, timeline[next].command))
        run.log.push_back("t = " + std::to_string(timeline[next].time) + " s: " + describe(*no));
      ++next;
    }
    const StepReport rep = advance(model, state);
    for (const std::string& n : state.device.notes) run.log.push_back("t = " + std::to_string(t) + " s: " + n);
    state.device.notes.clear();
    ++run.steps;
    if (!rep.ok()) {
      run.failure = rep.failure;
      break;
    }
    if (keepGoing && !keepGoing()) {
      run.stopped = true;
      break;
    }
  }
  return run;
}

}  // namespace coilsim
