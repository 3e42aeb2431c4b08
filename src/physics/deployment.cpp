#include "physics/deployment.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "physics/beam.h"

namespace coilsim {
namespace {

Quat twistAboutTangent(double angle) { return Quat(Eigen::AngleAxisd(angle, Vec3::UnitX())); }

// Material coordinate of coil node j is u_j = L - j h; its distance outside
// the tip at deployed length l is l - u_j.
double outside(const Deployment& dep, double l, int j) { return l - (dep.coilLength - j * dep.spacing); }

// The frame the coil has at the tip: the tip node's frame turned by the twist.
Quat coilFrameAtTip(const RodState& chain, double twist) { return (chain.q[0] * twistAboutTangent(twist)).normalized(); }

NodeProps coilNodeProps(const Deployment& dep, double length) {
  const double rho = dep.material.density;
  const Section& s = dep.section;
  return {rho * s.area * length, Vec3(rho * s.torsion, rho * s.iy, rho * s.iz) * length, length, s.radius};
}

// Rewrites the chain's element constants and node properties for the
// current first outside node k, deployed length and twist.
void rebuildChain(const Deployment& dep, const Model& model, RodState& chain, const DeploymentState& ds,
                  bool allBeams) {
  const int N = dep.coilBeams, k = ds.firstOutside;
  const double h = dep.spacing;
  const int outsideNodes = k <= N ? N - k + 1 : 0;
  chain.activeNodes = 1 + outsideNodes;
  const RodModel& nominal = model.rods[dep.chainRod];
  if (outsideNodes == 0) {
    chain.nodes[0] = coilNodeProps(dep, ds.deployed);  // the whole stub (held: zero mass is fine)
    return;
  }
  const double delta = outside(dep, ds.deployed, k);
  // The partial beam: from the coil material at the tip (u = l) to node k.
  Vec3 xa;
  Quat fa;
  dep.restPose((dep.coilLength - ds.deployed) / h, xa, fa);
  chain.beams[0] = makeBeamRest(xa, fa, dep.restX[k], dep.restF[k], dep.material, dep.section);
  chain.beams[0].nodeToElement = (twistAboutTangent(ds.twist) * chain.beams[0].nodeToElement).normalized();
  // Whole material beams j -> j+1 behind it, as the nominal (fully deployed) chain has them.
  if (allBeams)
    for (int e = 1; e + 1 < chain.activeNodes; ++e) chain.beams[e] = nominal.beams[k + e - 1];
  chain.nodes[0] = coilNodeProps(dep, 0.5 * delta);
  for (int i = 1; i < chain.activeNodes; ++i) {
    const int j = k + i - 1;
    const double before = i == 1 ? delta : h, after = j < N ? h : 0.0;
    chain.nodes[i] = coilNodeProps(dep, 0.5 * (before + after));
  }
}

// Hermite interpolation of a position between two samples with unit tangents.
Vec3 hermite(const Vec3& p0, const Vec3& t0, const Vec3& p1, const Vec3& t1, double h, double s) {
  const double s2 = s * s, s3 = s2 * s;
  return (2 * s3 - 3 * s2 + 1) * p0 + (s3 - 2 * s2 + s) * h * t0 + (-2 * s3 + 3 * s2) * p1 + (s3 - s2) * h * t1;
}

}  // namespace

void Deployment::restPose(double j, Vec3& x, Quat& f) const {
  j = std::clamp(j, 0.0, double(coilBeams));
  const int j0 = std::min(int(std::floor(j)), coilBeams - 1);
  const double s = j - j0;
  const Vec3 t0 = restF[j0] * Vec3::UnitX(), t1 = restF[j0 + 1] * Vec3::UnitX();
  const double chord = (restX[j0 + 1] - restX[j0]).norm();
  x = hermite(restX[j0], t0, restX[j0 + 1], t1, chord, s);
  f = restF[j0].slerp(s, restF[j0 + 1]).normalized();
}

Deployment addDeployment(const DeploymentDef& d, ModelDef& def) {
  auto bad = [&](const std::string& what) { throw std::invalid_argument("deployment of '" + d.coilName + "': " + what); };
  if (!(d.coilLength > 0) || !std::isfinite(d.coilLength)) bad("coil length must be a finite positive number");
  if (d.coilBeams < 2) bad("the coil needs at least 2 beams");
  if (int(d.coilRest.points.size()) != d.coilBeams + 1) bad("rest shape has the wrong number of samples");
  if (!(d.initialDeployed >= 0) || d.initialDeployed > d.coilLength * (1 + 1e-12))
    bad("initial deployed length must lie in [0, coil length]");
  if (!std::isfinite(d.initialTwist)) bad("initial twist is not finite");
  if (!(d.maxPushSpeed > 0) || !(d.maxTwistRate > 0)) bad("speed limits must be positive");
  const Vec3 dir = d.tip.direction, nrm = d.tip.normal;
  if (!dir.allFinite() || dir.norm() < 1e-12) bad("tip direction must be a non-zero vector");
  if (!nrm.allFinite() || nrm.cross(dir).norm() < 1e-9 * nrm.norm() * dir.norm())
    bad("tip reference normal must not be parallel to the direction");

  Deployment dep;
  dep.coilLength = d.coilLength;
  dep.coilBeams = d.coilBeams;
  dep.spacing = d.coilLength / d.coilBeams;
  dep.restX = d.coilRest.points;
  dep.restF = d.coilRest.frames;
  dep.material = d.coilMaterial;
  dep.section = d.coilSection;
  dep.tip = d.tip;
  dep.maxPushSpeed = d.maxPushSpeed;
  dep.maxTwistRate = d.maxTwistRate;

  // The chain: tip node then coil nodes 1..N, nominally fully deployed.
  RodDef chain;
  chain.name = d.coilName;
  chain.role = RodRole::Coil;
  chain.length = d.coilLength;
  chain.beams = d.coilBeams;
  chain.rest = d.coilRest;
  chain.placement = d.tip;
  chain.material = d.coilMaterial;
  chain.section = d.coilSection;
  chain.constraints.push_back({0, kAllDofs});
  dep.chainRod = int(def.rods.size());
  def.rods.push_back(chain);

  RodDef free = chain;
  free.name = d.coilName + " (detached)";
  free.constraints.clear();
  dep.freeRod = int(def.rods.size());
  def.rods.push_back(free);

  // The catheter is rigid: drawn, held in every node, moved only by retraction.
  RodDef cath;
  cath.name = "catheter";
  cath.role = RodRole::Catheter;
  cath.length = d.catheterDrawLength;
  cath.beams = 4;
  cath.rest = makeStraight(cath.length, cath.beams);
  cath.placement = d.tip;
  cath.placement.position = d.tip.position - d.catheterDrawLength * dir.normalized();
  cath.material = {1e9, shearModulusOf(1e9, 0.4), 1100};
  cath.section = circularSection(d.catheterOuterRadius, 0.4);
  for (int i = 0; i <= cath.beams; ++i) cath.constraints.push_back({i, kAllDofs});
  dep.catheterRod = int(def.rods.size());
  def.rods.push_back(cath);
  return dep;
}

DeploymentState initDeployment(const Deployment& dep, const Model& model, State& state, double deployed,
                               double twist) {
  DeploymentState ds;
  ds.deployed = std::clamp(deployed, 0.0, dep.coilLength);
  ds.twist = twist;
  const int N = dep.coilBeams;
  ds.firstOutside = N + 1;
  while (ds.firstOutside > 1 && outside(dep, ds.deployed, ds.firstOutside - 1) >= 0.5 * dep.spacing) --ds.firstOutside;
  state.rods[dep.freeRod].active = false;
  RodState& chain = state.rods[dep.chainRod];
  // Outside nodes in their rest shape relative to the coil frame at the tip.
  const Quat C = coilFrameAtTip(chain, twist);
  Vec3 xt;
  Quat ft;
  dep.restPose((dep.coilLength - ds.deployed) / dep.spacing, xt, ft);
  for (int j = ds.firstOutside; j <= N; ++j) {
    const int i = 1 + j - ds.firstOutside;
    chain.x[i] = chain.x[0] + C * (ft.conjugate() * (dep.restX[j] - xt));
    chain.q[i] = (C * ft.conjugate() * dep.restF[j]).normalized();
    chain.v[i].setZero();
    chain.w[i].setZero();
  }
  rebuildChain(dep, model, chain, ds, true);
  return ds;
}

void setDeployment(const Deployment& dep, const Model& model, State& state, DeploymentState& ds, double deployed,
                   double twist) {
  if (ds.detached) return;
  RodState& chain = state.rods[dep.chainRod];
  const int N = dep.coilBeams;
  const double h = dep.spacing;
  ds.deployed = std::clamp(deployed, 0.0, dep.coilLength);
  ds.twist = twist;
  bool shifted = false;
  // Insert nodes that have come out: each appears on the partial beam at its
  // material place, so nothing jumps.
  while (ds.firstOutside > 1 && outside(dep, ds.deployed, ds.firstOutside - 1) >= 0.5 * h &&
         (ds.firstOutside > N || outside(dep, ds.deployed, ds.firstOutside) >= 1.5 * h)) {
    const int n = chain.activeNodes;
    for (int i = n; i >= 2; --i) {
      chain.x[i] = chain.x[i - 1], chain.q[i] = chain.q[i - 1];
      chain.v[i] = chain.v[i - 1], chain.w[i] = chain.w[i - 1];
    }
    const double d = ds.firstOutside <= N ? outside(dep, ds.deployed, ds.firstOutside) : 0.0;
    const double f = d > 0 ? std::clamp((d - h) / d, 0.0, 1.0) : 0.0;  // fraction from the tip to node k
    const Quat C = coilFrameAtTip(chain, ds.twist);
    if (n >= 2) {
      chain.x[1] = (1 - f) * chain.x[0] + f * chain.x[2];
      chain.q[1] = C.slerp(f, chain.q[2]).normalized();
      chain.v[1] = f * chain.v[2];
      chain.w[1] = f * chain.w[2];
    } else {  // the very first node out: straight ahead of the tip
      chain.x[1] = chain.x[0] + C * Vec3(outside(dep, ds.deployed, ds.firstOutside - 1), 0, 0);
      chain.q[1] = C;
      chain.v[1].setZero();
      chain.w[1].setZero();
    }
    --ds.firstOutside;
    chain.activeNodes = n + 1;
    shifted = true;
  }
  // Withdraw nodes that have gone back in.
  while (ds.firstOutside <= N && outside(dep, ds.deployed, ds.firstOutside) < 0.5 * h) {
    const int n = chain.activeNodes;
    for (int i = 1; i + 1 < n; ++i) {
      chain.x[i] = chain.x[i + 1], chain.q[i] = chain.q[i + 1];
      chain.v[i] = chain.v[i + 1], chain.w[i] = chain.w[i + 1];
    }
    ++ds.firstOutside;
    chain.activeNodes = n - 1;
    shifted = true;
  }
  rebuildChain(dep, model, chain, ds, shifted);
}

void setTipOffset(const Deployment& dep, State& state, DeploymentState& ds, double offset) {
  const Vec3 back = -dep.tip.direction.normalized();
  const double change = offset - ds.tipOffset;
  ds.tipOffset = offset;
  for (int rod : {dep.chainRod, dep.catheterRod})
    for (Pose& t : state.rods[rod].targets) t.position += change * back;
}

std::string detach(const Deployment& dep, const Model& model, State& state, DeploymentState& ds) {
  if (ds.detached) return "the coil is detached already";
  if (ds.deployed < dep.coilLength - 1e-9)
    return "the coil is not fully out of the catheter (" + std::to_string(ds.deployed * 1e3) + " of " +
           std::to_string(dep.coilLength * 1e3) + " mm): push it out before detaching";
  RodState& chain = state.rods[dep.chainRod];
  RodState& free = state.rods[dep.freeRod];
  const int n = chain.activeNodes;  // tip node + coil nodes 1..N
  free.x[0] = chain.x[0];
  free.q[0] = coilFrameAtTip(chain, ds.twist);
  free.v[0] = chain.v[0];
  free.w[0] = chain.w[0];
  for (int i = 1; i < n; ++i) free.x[i] = chain.x[i], free.q[i] = chain.q[i], free.v[i] = chain.v[i], free.w[i] = chain.w[i];
  free.beams = model.rods[dep.freeRod].beams;
  free.activeNodes = n;
  free.active = true;
  chain.activeNodes = 1;
  chain.nodes[0] = coilNodeProps(dep, 0.5 * dep.spacing);
  ds.detached = true;
  return {};
}

double representedCoilLength(const Deployment& dep, const State& state, const DeploymentState& ds) {
  const RodState& r = state.rods[ds.detached ? dep.freeRod : dep.chainRod];
  double length = ds.detached ? 0.0 : dep.coilLength - ds.deployed;  // still inside
  for (int i = 0; i < r.activeNodes; ++i) length += r.nodes[i].length;  // arc length each node stands for
  return length;
}

double representedCoilMass(const Deployment& dep, const State& state, const DeploymentState& ds) {
  const RodState& r = state.rods[ds.detached ? dep.freeRod : dep.chainRod];
  const double perLength = dep.material.density * dep.section.area;
  double mass = ds.detached ? 0.0 : perLength * (dep.coilLength - ds.deployed);
  // Outside, the tip node carries half the partial beam on behalf of the coil.
  for (int i = 0; i < r.activeNodes; ++i) mass += r.nodes[i].mass;
  return mass;
}

}  // namespace coilsim
