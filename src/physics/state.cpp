#include "physics/state.h"

#include <algorithm>

#include "physics/deployment.h"
#include "physics/model.h"

namespace coilsim {

State makeState(const Model& model) {
  State s;
  for (const RodModel& rod : model.rods) {
    RodState r;
    const int n = rod.nnode;
    r.activeNodes = n;
    r.beams = rod.beams;
    for (int i = 0; i < n; ++i)
      r.nodes.push_back({rod.nodeMass[i], rod.nodeInertia[i], rod.nodeLength[i], rod.section.radius});
    r.x = rod.restPoints;
    r.q = rod.restFrames;
    r.v.assign(n, Vec3::Zero());
    r.w.assign(n, Vec3::Zero());
    for (const Constraint& c : rod.constraints) r.targets.push_back({rod.restPoints[c.node], rod.restFrames[c.node]});
    RodWorkspace& w = r.work;
    w.force.assign(n, Vec6::Zero());
    w.effectK.assign(n, Mat6::Zero());
    w.effectD.assign(n, Mat6::Zero());
    w.stiffness.resize(n);
    w.system.resize(n);
    w.solver.resize(n);
    w.rhs.assign(n, Vec6::Zero());
    w.velocity.assign(n, Vec6::Zero());
    w.stiffnessTimesVelocity.assign(n, Vec6::Zero());
    w.x0 = r.x;
    w.q0 = r.q;
    w.v0 = r.v;
    w.w0 = r.w;
    w.fixedMask.assign(n, 0u);
    w.fixedValue.assign(n, Vec6::Zero());
    s.rods.push_back(std::move(r));
  }
  if (model.device) resetDevice(model, s, model.device->initialDeployed, model.device->initialTwist);
  return s;
}

void warnOnce(State& state, const std::string& message) {
  if (std::find(state.warnings.begin(), state.warnings.end(), message) == state.warnings.end())
    state.warnings.push_back(message);
}

}  // namespace coilsim
