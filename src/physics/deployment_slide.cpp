// The predictor of a static push: the coil slides along its own shape.
#include <algorithm>
#include <cmath>

#include "physics/deployment.h"

namespace coilsim {
namespace {

struct Sample {
  double s = 0;  // arc length from the tip, m
  Vec3 x = Vec3::Zero();
  Quat q = Quat::Identity();
};

// The chain's coil nodes as a curve of arc length from the tip (the tip
// node at s = 0 with the coil's frame there).
std::vector<Sample> coilCurve(const Deployment& dep, const RodState& chain, const DeviceState& ds) {
  const int T = dep.tipNode;
  std::vector<Sample> out;
  out.push_back({0.0, chain.x[T], coilFrameAtTip(dep, chain, ds.twist)});
  for (int i = T + 1; i < chain.activeNodes; ++i) {
    const int j = ds.firstOutside + i - T - 1;
    out.push_back({ds.deployed - (dep.coilLength - j * dep.spacing), chain.x[i], chain.q[i]});
  }
  return out;
}

// The pose at arc s of the curve: Hermite positions on the frames'
// tangents, slerped frames. Beyond the distal end the curve goes on as the
// coil's rest shape does from its tip (a free end is unloaded, so it takes
// its rest curvature): the rest motion from material coordinate e to the
// tip, repeated from the tip.
void poseAt(const Deployment& dep, const std::vector<Sample>& c, double s, Vec3& x, Quat& q) {
  if (s >= c.back().s) {
    const double e = s - c.back().s;
    const double jTip = dep.coilBeams, jBack = std::max(0.0, jTip - e / dep.spacing);
    Vec3 xt, xb;
    Quat ft, fb;
    dep.restPose(jTip, xt, ft);
    dep.restPose(jBack, xb, fb);
    const Quat toEnd = c.back().q * fb.conjugate();
    x = c.back().x + toEnd * (xt - xb);
    q = (c.back().q * (fb.conjugate() * ft)).normalized();
    return;
  }
  size_t k = 1;
  while (c[k].s < s) ++k;
  const Sample &a = c[k - 1], &b = c[k];
  const double f = std::clamp((s - a.s) / (b.s - a.s), 0.0, 1.0);
  const double chord = (b.x - a.x).norm();
  x = hermite(a.x, a.q * Vec3::UnitX(), b.x, b.q * Vec3::UnitX(), chord, f);
  q = a.q.slerp(f, b.q).normalized();
}

}  // namespace

void slideDeployment(const Model& model, State& state, double deployed,
                     double twist) {
  const Deployment& dep = *model.device;
  const DeviceState& ds = state.device;
  if (ds.detached) return;
  RodState& chain = state.rods[dep.chainRod];
  const std::vector<Sample> before = coilCurve(dep, chain, ds);
  const double pushed = std::clamp(deployed, 0.0, dep.coilLength) - ds.deployed;
  setDeployment(model, state, deployed, twist);
  // Only a push slides: the curve of a withdrawal or of a first node out
  // has nothing to slide along.
  if (!(pushed > 0) || before.size() < 2) return;
  const int T = dep.tipNode;
  for (int i = T + 1; i < chain.activeNodes; ++i) {
    const int j = ds.firstOutside + i - T - 1;
    const double s = ds.deployed - (dep.coilLength - j * dep.spacing);
    poseAt(dep, before, s, chain.x[i], chain.q[i]);
    chain.v[i].setZero(), chain.w[i].setZero();
  }
}

}  // namespace coilsim
