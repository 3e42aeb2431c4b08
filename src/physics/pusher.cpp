// The force-limited pusher (physics/pusher.h).
#include "physics/pusher.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "physics/beam.h"
#include "physics/deployment.h"

namespace coilsim {
namespace {

// The lowest inserted fraction of a step: a coil pushing back harder than
// the limit drives the pusher back, at most as fast as it was pushing.
constexpr double kMinFraction = -1.0;

// The pusher's force for the beam `rest` from the tip node (a) to the first
// outside node (b) at the given end-of-step poses: the axial part, along the
// exit direction, of what the beam presses the tip node with; > 0 when the
// coil pushes back into the catheter.
double pushForce(const BeamRest& rest, const Vec3& xa, const Quat& qa, const Vec3& xb, const Quat& qb) {
  BeamEval e;
  evalBeam(rest, xa, qa, xb, qb, false, e);
  return -e.forceA.head<3>().dot(qa * Vec3::UnitX());
}

// End-of-step pose of node i for the velocity change dv of this iterate.
void endPose(const RodState& r, int i, const Vec6& dv, double h, Vec3& x, Quat& q) {
  const RodWorkspace& w = r.work;
  x = w.x0[i] + h * (r.v[i] + dv.head<3>());
  q = (quatExp(h * (r.w[i] + dv.tail<3>())) * w.q0[i]).normalized();
}

}  // namespace

void armPusher(const Model& model, State& state, double deployedBefore, double commanded, double rate,
               double leftBefore) {
  PusherState& p = state.device.pusher;
  p.armed = false;
  p.fraction = 1;
  if (!model.device || state.device.detached || !(commanded > 0)) return;
  const Deployment& dep = *model.device;
  const RodState& chain = state.rods[size_t(dep.chainRod)];
  if (chain.activeNodes < dep.tipNode + 2) return;  // nothing outside the tip yet: no beam to push through
  p.armed = true;
  p.rate = rate;
  p.leftBefore = leftBefore;
  p.deployedBefore = deployedBefore;
  p.commanded = commanded;
  p.restBefore = partialBeamRest(dep, state.device, deployedBefore);
  p.response.resize(chain.x.size());
}

void limitPushInStep(const Deployment& dep, PusherState& p, RodState& chain, double h) {
  if (!p.armed) return;
  RodWorkspace& w = chain.work;
  const int a = dep.tipNode, b = a + 1, n = chain.activeNodes;
  const BeamRest& restNow = chain.beams[size_t(a)];
  Vec3 xa, xb;
  Quat qa, qb;
  endPose(chain, a, w.rhs[a], h, xa, qa);
  endPose(chain, b, w.rhs[b], h, xb, qb);
  const double full = pushForce(restNow, xa, qa, xb, qb);
  const double limit = dep.maxPushForce;
  if (full <= limit) {
    p.fraction = 1, p.force = full;
    return;
  }
  // The right-hand side holds h f; the partial beam's forces at this
  // iterate's poses with the whole insertion and with none differ by df.
  BeamEval with, without;
  evalBeam(restNow, chain.x[a], chain.q[a], chain.x[b], chain.q[b], false, with);
  evalBeam(p.restBefore, chain.x[a], chain.q[a], chain.x[b], chain.q[b], false, without);
  std::vector<Vec6>& y = p.response;
  std::fill(y.begin(), y.begin() + n, Vec6::Zero());
  y[a] = h * (with.forceA - without.forceA);
  y[b] = h * (with.forceB - without.forceB);
  for (int i : {a, b})
    for (int d = 0; d < 6; ++d)
      if (w.fixedMask[i] & (1u << d)) y[i][d] = 0;
  w.solver.solve(y);
  endPose(chain, a, w.rhs[a] - y[a], h, xa, qa);
  endPose(chain, b, w.rhs[b] - y[b], h, xb, qb);
  const double none = pushForce(p.restBefore, xa, qa, xb, qb);
  // N(s) affine between s = 0 (none) and s = 1 (full).
  double s = full > none ? (limit - none) / (full - none) : kMinFraction;
  s = std::clamp(s, kMinFraction, 1.0);
  for (int i = 0; i < n; ++i) w.rhs[i] -= (1 - s) * y[i];
  p.fraction = s;
  p.force = none + s * (full - none);
}

void finishPush(const Model& model, State& state, bool stepOk) {
  PusherState& p = state.device.pusher;
  const bool wasStalled = p.stalled;
  if (!p.armed) {
    // Between pushes the pusher is at rest; a push's step that moved a node
    // through the tip keeps what the push felt last.
    if (!(state.device.motion.pushRate > 0)) p.force = 0, p.stalled = false;
    return;
  }
  p.armed = false;
  p.stalled = p.fraction < 1;
  if (!stepOk || !p.stalled) return;
  DeviceState& ds = state.device;
  DeviceMotion& m = ds.motion;
  const double inserted = p.fraction * p.commanded;
  setDeployment(model, state, p.deployedBefore + inserted, ds.twist);
  // The push goes on for what it did not insert, and for what the coil
  // pushed it back (moveDevice ended it if the step's command would have
  // completed it): a push's distance is net insertion.
  m.pushRate = p.rate;
  m.pushLeft = p.leftBefore < 0 ? -1.0 : p.leftBefore - inserted;
  if (!wasStalled) {
    char b[160];
    std::snprintf(b, sizeof b, "the pusher stalls: the coil resists with the push force limit (%.0f mN)",
                  model.device->maxPushForce * 1e3);
    ds.notes.push_back(b);
  }
}

}  // namespace coilsim
