// The automatic operator: push, stop-and-twist on resistance, settle, detach.
#include "planning/auto_deploy.h"

#include <cmath>
#include <cstdio>

#include "physics/beam.h"
#include "physics/integrator.h"

namespace coilsim::planning {

Vec3 tipForce(const Deployment& dep, const State& state) {
  const RodState& chain = state.rods[size_t(dep.chainRod)];
  const int t = dep.tipNode;  // the catheter tip node; the coil leaves it through beam t
  if (chain.activeNodes < t + 2) return Vec3::Zero();
  BeamEval e;
  evalBeam(chain.beams[size_t(t)], chain.x[size_t(t)], chain.q[size_t(t)], chain.x[size_t(t) + 1], chain.q[size_t(t) + 1],
           false, e);
  // forceA is the beam's restoring force on the tip node: what the coil does to the catheter.
  return e.forceA.head<3>();
}

AutoDeployResult autoDeploy(const Deployment& dep, const Model& model, State& state, DeploymentState& ds,
                            const AutoDeployOptions& o, const ContactForceSource& contacts) {
  AutoDeployResult r;
  DeploymentController controller;
  const double dt = model.timeStep;
  std::vector<std::vector<double>> forces;
  enum class Phase { Push, Twist, Pause, Settle, After } phase = Phase::Push;
  double phaseEnd = 0, twistSign = 1;
  auto issue = [&](double t, const DeviceCommand& c) {
    const std::string why = controller.command(dep, ds, c);
    if (!why.empty()) r.log.push_back("t = " + std::to_string(t) + " s: refused: " + why);
    else r.timeline.push_back({t, c});
  };
  const long maxSteps = long(std::ceil(o.maxTime / dt));
  for (long s = 0; s < maxSteps; ++s) {
    const double t = double(s) * dt;  // exactly the time runTimeline applies commands at
    const bool fullyOut = ds.deployed >= dep.coilLength - 1e-12;
    if (phase == Phase::Push && s == 0) issue(t, {DeviceCommand::Kind::Push, o.pushSpeed, 0});
    if (phase == Phase::Push && fullyOut) {
      phase = Phase::Settle, phaseEnd = t + o.settle;
    } else if (phase == Phase::Push && s > 0) {
      const Vec3 f = tipForce(dep, state);
      if (f.norm() > o.forceThreshold) {
        issue(t, {DeviceCommand::Kind::Stop, 0, 0});
        issue(t, {DeviceCommand::Kind::Twist, twistSign * o.twistRate, o.twistAngle});
        twistSign = -twistSign;
        ++r.corrections;
        phase = Phase::Twist, phaseEnd = t + o.twistAngle / o.twistRate;
      }
    } else if (phase == Phase::Twist && t >= phaseEnd - 1e-12) {
      phase = Phase::Pause, phaseEnd = t + o.pause;
    } else if (phase == Phase::Pause && t >= phaseEnd - 1e-12) {
      issue(t, {DeviceCommand::Kind::Push, o.pushSpeed, 0});
      phase = Phase::Push;
    } else if (phase == Phase::Settle && t >= phaseEnd - 1e-12) {
      issue(t, {DeviceCommand::Kind::Detach, 0, 0});
      phase = Phase::After, phaseEnd = t + o.afterDetach;
    } else if (phase == Phase::After && t >= phaseEnd - 1e-12) {
      r.time = t;
      return r;
    }
    controller.advance(dep, model, state, ds, dt);
    for (const std::string& n : controller.notes) r.log.push_back("t = " + std::to_string(t) + " s: " + n);
    controller.notes.clear();
    const StepReport rep = step(model, state);
    ++r.steps;
    if (!rep.ok()) {
      r.ok = false;
      r.error = "step refused at t = " + std::to_string(t) + " s: " + rep.message;
      r.time = t;
      return r;
    }
    if (!ds.detached) {
      const Vec3 f = tipForce(dep, state);
      r.maxTipForce = std::max(r.maxTipForce, f.norm());
      // Axial part along the first coil beam out of the tip: what the pusher feels.
      const RodState& chain = state.rods[size_t(dep.chainRod)];
      const size_t t = size_t(dep.tipNode);
      if (chain.activeNodes > int(t) + 1) {
        const Vec3 axis = (chain.x[t + 1] - chain.x[t]).normalized();
        r.maxDeploymentForce = std::max(r.maxDeploymentForce, -f.dot(axis));
      }
    }
    r.maxKickback = std::max(r.maxKickback, catheterTip(dep, state, ds).kickback);
    if (contacts && contacts(model, state, forces)) {
      r.wallForcesAvailable = true;
      r.wall.add(forces, dt, o.wallForceThreshold);
    }
  }
  r.ok = false;
  r.time = o.maxTime;
  r.error = "the coil was not detached within " + std::to_string(o.maxTime) + " s of simulated time";
  return r;
}

}  // namespace coilsim::planning
