#include "physics/deployment.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "physics/beam.h"
#include "physics/failure.h"

namespace coilsim {
namespace {

Quat twistAboutTangent(double angle) { return Quat(Eigen::AngleAxisd(angle, Vec3::UnitX())); }

// Material coordinate of coil node j is u_j = L - j h; its distance outside
// the tip at deployed length l is l - u_j.
double outside(const Deployment& dep, double l, int j) { return l - (dep.coilLength - j * dep.spacing); }


NodeProps coilNodeProps(const Deployment& dep, double length) {
  const double rho = dep.material.density;
  const Section& s = dep.section;
  return {rho * s.area * length, Vec3(rho * s.torsion, rho * s.iy, rho * s.iz) * length, length, s.radius};
}

// Adds the mass and rotary inertia of `length` of coil lying inside a
// catheter node; its length and radius stay the catheter's (what the fluid sees).
void addCoilInside(const Deployment& dep, NodeProps& node, double length) {
  const NodeProps c = coilNodeProps(dep, length);
  node.mass += c.mass;
  node.inertia += c.inertia;
}

// The composite part of a flexible catheter: element constants and node
// properties of catheter nodes 0..T for the coil lying inside now.
void rebuildComposite(const Deployment& dep, RodState& chain, const DeviceState& ds) {
  const int T = dep.tipNode;
  const double L = dep.coilLength, l = ds.deployed, h = dep.spacing, S = dep.catheterArc[T];
  for (int i = 0; i <= T; ++i) chain.nodes[i] = dep.catheterNodes[i];
  const Quat tw = twistAboutTangent(ds.twist);
  for (int e = 0; e < T; ++e) {
    // Arc distances of the element's ends behind the tip; the coil lies in [0, L - l] behind it.
    const double da = S - dep.catheterArc[e], db = S - dep.catheterArc[e + 1];
    const double cover = std::clamp(L - l - db, 0.0, da - db);
    if (!(cover > 0)) {
      chain.beams[e] = dep.catheterBeams[e];
      continue;
    }
    // Coil material at the element's ends (u = l + d, j = (L - u) / h), clamped to the coil's proximal end.
    Vec3 xa, xb;
    Quat fa, fb;
    dep.restPose(std::max(0.0, (L - l - da) / h), xa, fa);
    dep.restPose((L - l - db) / h, xb, fb);
    // The coil's frame inside is the catheter's turned by the twist about the tangent.
    const Quat coilRel = (tw * fa.conjugate() * fb * tw.conjugate()).normalized();
    chain.beams[e] = compositeBeamRest(dep.catheterRel[e], dep.catheterChord[e], coilRel, cover / (da - db),
                                       dep.catheter.material, dep.catheterSection, dep.material, dep.section,
                                       dep.catheter.weighting);
    addCoilInside(dep, chain.nodes[e], 0.5 * cover);
    addCoilInside(dep, chain.nodes[e + 1], 0.5 * cover);
  }
}

// Rewrites the chain's element constants and node properties for the
// current first outside node k, deployed length and twist.
void rebuildChain(const Deployment& dep, const Model& model, RodState& chain, const DeviceState& ds,
                  bool allBeams) {
  const int N = dep.coilBeams, k = ds.firstOutside, T = dep.tipNode;
  const double h = dep.spacing;
  const int outsideNodes = k <= N ? N - k + 1 : 0;
  chain.activeNodes = T + 1 + outsideNodes;
  const RodModel& nominal = model.rods[dep.chainRod];
  if (dep.flexible()) rebuildComposite(dep, chain, ds);
  // The tip node carries, on behalf of the coil, the whole stub (nothing
  // outside) or half the partial beam.
  const double atTip = outsideNodes == 0 ? ds.deployed : 0.5 * outside(dep, ds.deployed, k);
  if (dep.flexible()) addCoilInside(dep, chain.nodes[T], atTip);
  else chain.nodes[0] = coilNodeProps(dep, atTip);  // held: its zero or small mass is fine
  if (outsideNodes == 0) return;
  const double delta = outside(dep, ds.deployed, k);
  // The partial beam: from the coil material at the tip (u = l) to node k.
  Vec3 xa;
  Quat fa;
  dep.restPose((dep.coilLength - ds.deployed) / h, xa, fa);
  chain.beams[T] = makeBeamRest(xa, fa, dep.restX[k], dep.restF[k], dep.material, dep.section);
  chain.beams[T].nodeToElement = (twistAboutTangent(ds.twist) * chain.beams[T].nodeToElement).normalized();
  // Whole material beams j -> j+1 behind it, as the nominal (fully deployed) chain has them.
  if (allBeams)
    for (int e = 1; T + e + 1 < chain.activeNodes; ++e) chain.beams[T + e] = nominal.beams[T + k + e - 1];
  for (int i = 1; T + i < chain.activeNodes; ++i) {
    const int j = k + i - 1;
    const double before = i == 1 ? delta : h, after = j < N ? h : 0.0;
    chain.nodes[T + i] = coilNodeProps(dep, 0.5 * (before + after));
  }
}

}  // namespace

Quat coilFrameAtTip(const Deployment& dep, const RodState& chain, double twist) {
  return (chain.q[dep.tipNode] * twistAboutTangent(twist)).normalized();
}

Vec3 coilForceOnTip(const Deployment& dep, const State& state) {
  const RodState& chain = state.rods[size_t(dep.chainRod)];
  const size_t t = size_t(dep.tipNode);  // the coil leaves the tip node through beam t
  if (chain.activeNodes < dep.tipNode + 2) return Vec3::Zero();
  BeamEval e;
  evalBeam(chain.beams[t], chain.x[t], chain.q[t], chain.x[t + 1], chain.q[t + 1], false, e);
  return e.forceA.head<3>();  // the beam's restoring force on the tip node
}

void Deployment::restPose(double j, Vec3& x, Quat& f) const {
  j = std::clamp(j, 0.0, double(coilBeams));
  const int j0 = std::min(int(std::floor(j)), coilBeams - 1);
  const double s = j - j0;
  const Vec3 t0 = restF[j0] * Vec3::UnitX(), t1 = restF[j0 + 1] * Vec3::UnitX();
  const double chord = (restX[j0 + 1] - restX[j0]).norm();
  x = hermite(restX[j0], t0, restX[j0 + 1], t1, chord, s);
  f = restF[j0].slerp(s, restF[j0 + 1]).normalized();
}

namespace {

// The flexible catheter's constants; returns its rest curve placed so that
// its tip node lies at the tip pose (position, exit direction, normal).
RestCurve buildCatheter(const DeploymentDef& d, Deployment& dep) {
  const CatheterDef& c = d.catheter;
  auto bad = [&](const std::string& what) { throw PhysicsError(badDefinition("catheter", what)); };
  const Material& m = c.material;
  if (!(m.youngModulus > 0) || !(m.shearModulus > 0) || !(m.density > 0) || !std::isfinite(m.youngModulus) ||
      !std::isfinite(m.shearModulus) || !std::isfinite(m.density))
    bad("material constants must be finite positive numbers");
  if (!(c.outerRadius > c.innerRadius) || !(c.innerRadius >= 0) || !std::isfinite(c.outerRadius))
    bad("outer radius must exceed the inner radius, both finite and >= 0");
  if (!(c.heldLength >= 0) || !(c.freeLength > 0) || !std::isfinite(c.heldLength + c.freeLength))
    bad("held length must be >= 0 and free length > 0");
  if (c.beams < 2) bad("needs at least 2 beams");
  const CatheterShape& sh = c.shape;
  if (sh.type != CatheterShape::Type::Straight && (!(sh.angle > 0) || !(sh.radius > 0) || !std::isfinite(sh.angle + sh.radius)))
    bad("a shaped tip needs a finite angle > 0 and radius > 0");
  if (!(sh.bendLength() <= c.freeLength * (1 + 1e-12)))
    bad("the tip bends need " + std::to_string(sh.bendLength() * 1e3) + " mm of arc but the free length is " +
        std::to_string(c.freeLength * 1e3) + " mm");
  const double S = c.heldLength + c.freeLength;
  const RestCurve canonical = makeCatheterRest(sh, S, c.beams);
  // Place it so that its tip frame is the tip pose: P F_T = R_tip.
  const Quat tipRot = d.tip.rotation();
  const Quat place = (tipRot * canonical.frames.back().conjugate()).normalized();
  Placement p;
  p.direction = place * Vec3::UnitX();
  p.normal = place * Vec3::UnitY();
  p.position = d.tip.position - place * canonical.points.back();
  const RestCurve rest = placed(canonical, p);

  const int T = c.beams;
  dep.tipNode = T;
  dep.catheter = c;
  dep.catheterSection = tubeSection(c.outerRadius, c.innerRadius, m.youngModulus / (2 * m.shearModulus) - 1);
  dep.retractDirection = p.direction;
  dep.catheterNodes.assign(T + 1, NodeProps{});
  dep.catheterArc.clear();
  for (int i = 0; i <= T; ++i) {
    dep.catheterArc.push_back(S * i / T);
    dep.catheterNodes[i].radius = c.outerRadius;
  }
  const Section& sec = dep.catheterSection;
  for (int e = 0; e < T; ++e) {
    dep.catheterRel.push_back((rest.frames[e].conjugate() * rest.frames[e + 1]).normalized());
    dep.catheterChord.push_back((rest.points[e + 1] - rest.points[e]).norm());
    dep.catheterBeams.push_back(makeBeamRest(rest.points[e], rest.frames[e], rest.points[e + 1], rest.frames[e + 1], m, sec));
    const double half = 0.5 * (dep.catheterArc[e + 1] - dep.catheterArc[e]);
    for (int i : {e, e + 1}) {
      NodeProps& n = dep.catheterNodes[i];
      n.length += half;
      n.mass += m.density * sec.area * half;
      n.inertia += Vec3(sec.torsion, sec.iy, sec.iz) * (m.density * half);
    }
  }
  return rest;
}

}  // namespace

Deployment addDeployment(const DeploymentDef& d, ModelDef& def) {
  auto bad = [&](const std::string& what) { throw PhysicsError(badDefinition("deployment of '" + d.coilName + "'", what)); };
  const double length = d.coil.length;
  if (!(length > 0) || !std::isfinite(length)) bad("coil length must be a finite positive number");
  if (d.coilBeams < 2) bad("the coil needs at least 2 beams");
  RestCurve coilRest;
  try {
    coilRest = makeRest(d.coil.rest, length, d.coilBeams);
  } catch (const PhysicsError& ex) {
    bad("rest shape: " + ex.failure().message());
  }
  if (!(d.initialDeployed >= 0) || d.initialDeployed > length * (1 + 1e-12))
    bad("initial deployed length must lie in [0, coil length]");
  if (!std::isfinite(d.initialTwist)) bad("initial twist is not finite");
  if (!(d.maxPushSpeed > 0) || !(d.maxTwistRate > 0)) bad("speed limits must be positive");
  const Vec3 dir = d.tip.direction, nrm = d.tip.normal;
  if (!dir.allFinite() || dir.norm() < 1e-12) bad("tip direction must be a non-zero vector");
  if (!nrm.allFinite() || nrm.cross(dir).norm() < 1e-9 * nrm.norm() * dir.norm())
    bad("tip reference normal must not be parallel to the direction");

  Deployment dep;
  dep.coilLength = length;
  dep.coilBeams = d.coilBeams;
  dep.spacing = length / d.coilBeams;
  dep.restX = coilRest.points;
  dep.restF = coilRest.frames;
  dep.material = materialOf(d.coil);
  dep.section = sectionOf(d.coil);
  dep.tip = d.tip;
  dep.maxPushSpeed = d.maxPushSpeed;
  dep.maxTwistRate = d.maxTwistRate;
  dep.initialDeployed = d.initialDeployed;
  dep.initialTwist = d.initialTwist;
  dep.retractDirection = dir.normalized();
  dep.catheterArc = {0.0};
  dep.catheterNodes = {NodeProps{}};
  RestCurve catheterRest;
  if (d.catheter.flexible) {
    try {
      catheterRest = buildCatheter(d, dep);
    } catch (const PhysicsError& ex) {
      bad(ex.failure().message());
    }
  }
  const int T = dep.tipNode;

  // The coil nominally fully deployed, its proximal end (j = 0) at the tip.
  RodDef free;
  free.name = d.coilName + " (detached)";
  free.role = RodRole::Coil;
  free.length = length;
  free.beams = d.coilBeams;
  free.rest = coilRest;
  free.placement = d.tip;
  free.material = dep.material;
  free.section = dep.section;

  // The chain: catheter nodes 0..T-1, then the tip node T and coil nodes
  // 1..N. Coil material and section throughout (the catheter's elements and
  // nodes are rewritten in the state; the radius is the coil's, drawn
  // inside the catheter's tube).
  RodDef chain = free;
  chain.name = d.coilName;
  if (T > 0) {
    const RestCurve coil = placed(coilRest, d.tip);
    chain.rest = catheterRest;
    chain.rest.points.pop_back(), chain.rest.frames.pop_back();
    chain.rest.points.insert(chain.rest.points.end(), coil.points.begin(), coil.points.end());
    chain.rest.frames.insert(chain.rest.frames.end(), coil.frames.begin(), coil.frames.end());
    chain.placement = Placement{};
    chain.length = length + d.catheter.heldLength + d.catheter.freeLength;
    chain.beams = T + d.coilBeams;
  }
  // Held: every catheter node within the held length (the tip node alone for the rigid tip).
  for (int i = 0; i <= T; ++i)
    if (i == 0 || dep.catheterArc[i] <= d.catheter.heldLength * (1 + 1e-12)) chain.constraints.push_back({i, kAllDofs});
  if (!d.tipClamped) chain.constraints.front().mask = kFreeDofs;
  dep.chainRod = int(def.rods.size());
  def.rods.push_back(chain);
  dep.freeRod = int(def.rods.size());
  def.rods.push_back(free);

  // The drawn catheter: held in every node. The rigid one moves only by
  // retraction; the flexible one follows the chain's catheter nodes.
  RodDef cath;
  cath.name = "catheter";
  cath.role = RodRole::Catheter;
  if (T > 0) {
    cath.length = d.catheter.heldLength + d.catheter.freeLength;
    cath.beams = T;
    cath.rest = catheterRest;
    cath.material = d.catheter.material;
    cath.section = dep.catheterSection;
  } else {
    cath.length = d.catheterDrawLength;
    cath.beams = 4;
    cath.rest = makeStraight(cath.length, cath.beams);
    cath.placement = d.tip;
    cath.placement.position = d.tip.position - d.catheterDrawLength * dir.normalized();
    cath.material = {1e9, shearModulusOf(1e9, 0.4), 1100};
    cath.section = circularSection(d.catheterOuterRadius, 0.4);
  }
  for (int i = 0; i <= cath.beams; ++i) cath.constraints.push_back({i, kAllDofs});
  dep.catheterRod = int(def.rods.size());
  def.rods.push_back(cath);
  return dep;
}

void resetDevice(const Model& model, State& state, double deployed, double twist) {
  const Deployment& dep = *model.device;
  DeviceState& ds = state.device;
  ds = DeviceState{};
  ds.deployed = std::clamp(deployed, 0.0, dep.coilLength);
  ds.twist = twist;
  const int N = dep.coilBeams, T = dep.tipNode;
  ds.firstOutside = N + 1;
  while (ds.firstOutside > 1 && outside(dep, ds.deployed, ds.firstOutside - 1) >= 0.5 * dep.spacing) --ds.firstOutside;
  state.rods[dep.freeRod].active = false;
  RodState& chain = state.rods[dep.chainRod];
  rebuildChain(dep, model, chain, ds, true);
  // The free catheter nodes in the unloaded composite shape, walked from
  // the held ones along the element rest frames: x_b = x_a + R_a Q (L0 e_x), R_b = R_a Q P.
  const RodModel& rm = model.rods[dep.chainRod];
  int held = 0;
  for (const Constraint& c : rm.constraints) held = std::max(held, c.node);
  for (int e = held; e < T; ++e) {
    const BeamRest& b = chain.beams[e];
    const Quat E = (chain.q[e] * b.nodeToElement).normalized();
    chain.x[e + 1] = chain.x[e] + E * Vec3(b.length, 0, 0);
    chain.q[e + 1] = (E * b.restRelative).normalized();
  }
  // Outside nodes in their rest shape relative to the coil frame at the tip.
  const Quat C = coilFrameAtTip(dep, chain, twist);
  Vec3 xt;
  Quat ft;
  dep.restPose((dep.coilLength - ds.deployed) / dep.spacing, xt, ft);
  for (int j = ds.firstOutside; j <= N; ++j) {
    const int i = T + 1 + j - ds.firstOutside;
    chain.x[i] = chain.x[T] + C * (ft.conjugate() * (dep.restX[j] - xt));
    chain.q[i] = (C * ft.conjugate() * dep.restF[j]).normalized();
  }
  for (int i = 0; i < int(chain.v.size()); ++i) chain.v[i].setZero(), chain.w[i].setZero();
  ds.tipStart = chain.x[T];
  ds.exitStart = chain.q[T] * Vec3::UnitX();
  syncCatheterDrawing(model, state);
}

void setDeployment(const Model& model, State& state, double deployed, double twist) {
  const Deployment& dep = *model.device;
  DeviceState& ds = state.device;
  if (ds.detached) return;
  RodState& chain = state.rods[dep.chainRod];
  const int N = dep.coilBeams, T = dep.tipNode;
  const double h = dep.spacing;
  ds.deployed = std::clamp(deployed, 0.0, dep.coilLength);
  ds.twist = twist;
  bool shifted = false;
  // Insert nodes that have come out: each appears on the partial beam at its
  // material place, so nothing jumps.
  while (ds.firstOutside > 1 && outside(dep, ds.deployed, ds.firstOutside - 1) >= 0.5 * h &&
         (ds.firstOutside > N || outside(dep, ds.deployed, ds.firstOutside) >= 1.5 * h)) {
    const int n = chain.activeNodes;
    for (int i = n; i >= T + 2; --i) {
      chain.x[i] = chain.x[i - 1], chain.q[i] = chain.q[i - 1];
      chain.v[i] = chain.v[i - 1], chain.w[i] = chain.w[i - 1];
    }
    const double d = ds.firstOutside <= N ? outside(dep, ds.deployed, ds.firstOutside) : 0.0;
    const double f = d > 0 ? std::clamp((d - h) / d, 0.0, 1.0) : 0.0;  // fraction from the tip to node k
    const Quat C = coilFrameAtTip(dep, chain, ds.twist);
    if (n >= T + 2) {
      chain.x[T + 1] = (1 - f) * chain.x[T] + f * chain.x[T + 2];
      chain.q[T + 1] = C.slerp(f, chain.q[T + 2]).normalized();
      chain.v[T + 1] = (1 - f) * chain.v[T] + f * chain.v[T + 2];
      chain.w[T + 1] = (1 - f) * chain.w[T] + f * chain.w[T + 2];
    } else {  // the very first node out: straight ahead of the tip
      chain.x[T + 1] = chain.x[T] + C * Vec3(outside(dep, ds.deployed, ds.firstOutside - 1), 0, 0);
      chain.q[T + 1] = C;
      chain.v[T + 1] = chain.v[T];
      chain.w[T + 1] = chain.w[T];
    }
    --ds.firstOutside;
    chain.activeNodes = n + 1;
    shifted = true;
  }
  // Withdraw nodes that have gone back in.
  while (ds.firstOutside <= N && outside(dep, ds.deployed, ds.firstOutside) < 0.5 * h) {
    const int n = chain.activeNodes;
    for (int i = T + 1; i + 1 < n; ++i) {
      chain.x[i] = chain.x[i + 1], chain.q[i] = chain.q[i + 1];
      chain.v[i] = chain.v[i + 1], chain.w[i] = chain.w[i + 1];
    }
    ++ds.firstOutside;
    chain.activeNodes = n - 1;
    shifted = true;
  }
  rebuildChain(dep, model, chain, ds, shifted);
}

void setTipOffset(const Model& model, State& state, double offset) {
  const Deployment& dep = *model.device;
  DeviceState& ds = state.device;
  const Vec3 back = -dep.retractDirection;
  const double change = offset - ds.tipOffset;
  ds.tipOffset = offset;
  for (int rod : {dep.chainRod, dep.catheterRod})
    for (Pose& t : state.rods[rod].targets) t.position += change * back;
}

std::optional<Failure> detach(const Model& model, State& state) {
  const Deployment& dep = *model.device;
  DeviceState& ds = state.device;
  const auto refused = [](std::string why) {
    Failure f;
    f.kind = FailureKind::DeviceRefusal;
    f.text = std::move(why);
    return f;
  };
  if (ds.detached) return refused("the coil is detached already");
  if (ds.deployed < dep.coilLength - 1e-9) {
    Failure f = refused("the coil is not fully out of the catheter (" + std::to_string(ds.deployed * 1e3) + " of " +
                        std::to_string(dep.coilLength * 1e3) + " mm): push it out before detaching");
    f.quantity = "deployed length", f.value = ds.deployed, f.limit = dep.coilLength;
    return f;
  }
  RodState& chain = state.rods[dep.chainRod];
  RodState& free = state.rods[dep.freeRod];
  const int T = dep.tipNode, n = chain.activeNodes - T;  // tip node + coil nodes 1..N
  free.x[0] = chain.x[T];
  free.q[0] = coilFrameAtTip(dep, chain, ds.twist);
  free.v[0] = chain.v[T];
  free.w[0] = chain.w[T];
  for (int i = 1; i < n; ++i)
    free.x[i] = chain.x[T + i], free.q[i] = chain.q[T + i], free.v[i] = chain.v[T + i], free.w[i] = chain.w[T + i];
  // The pusher held the coil's end with a force and a moment (large when the
  // coil presses on a wall). Released, the end node, with almost no mass or
  // rotary inertia, swings within microseconds to where its beam is
  // unstrained; placing it there now spares one implicit step a turn of
  // tens of degrees, which its linearisation overshoots.
  if (n > 1) {
    const Quat toFirst = dep.restF[1].conjugate();
    free.q[0] = (free.q[1] * toFirst * dep.restF[0]).normalized();
    free.x[0] = free.x[1] + free.q[1] * (toFirst * (dep.restX[0] - dep.restX[1]));
  }
  free.beams = model.rods[dep.freeRod].beams;
  free.activeNodes = n;
  free.active = true;
  chain.activeNodes = T + 1;
  if (dep.flexible()) chain.nodes[T] = dep.catheterNodes[T];
  else chain.nodes[0] = coilNodeProps(dep, 0.5 * dep.spacing);
  ds.detached = true;
  ds.releasedAt = chain.x[T];
  return std::nullopt;
}

namespace {

// Coil mass the chain's (or free rod's) nodes carry; the catheter's own is taken off.
double coilMassInNodes(const Deployment& dep, const State& state, const DeviceState& ds, double& outsideLength) {
  outsideLength = 0;
  if (ds.detached) {
    const RodState& r = state.rods[dep.freeRod];
    double mass = 0;
    for (int i = 0; i < r.activeNodes; ++i) mass += r.nodes[i].mass, outsideLength += r.nodes[i].length;
    return mass;
  }
  const RodState& r = state.rods[dep.chainRod];
  const int T = dep.tipNode;
  double mass = 0;
  for (int i = 0; i <= T; ++i) mass += r.nodes[i].mass - dep.catheterNodes[i].mass;
  for (int i = T + 1; i < r.activeNodes; ++i) mass += r.nodes[i].mass, outsideLength += r.nodes[i].length;
  return mass;
}

// Coil inside the catheter but behind its base (not simulated).
double coilBehindBase(const Deployment& dep, const DeviceState& ds) {
  return ds.detached ? 0.0 : std::max(0.0, dep.coilLength - ds.deployed - dep.catheterArc[dep.tipNode]);
}

}  // namespace

double representedCoilLength(const Model& model, const State& state) {
  const Deployment& dep = *model.device;
  const DeviceState& ds = state.device;
  double outsideLength = 0;
  const double mass = coilMassInNodes(dep, state, ds, outsideLength);
  if (ds.detached) return outsideLength;
  // The chain's catheter nodes stand for the catheter's length; the coil's
  // share there is known through its mass (the tip node of the rigid tip has
  // only coil, and its length is the coil's).
  const RodState& r = state.rods[dep.chainRod];
  double outsideMass = 0;
  for (int i = dep.tipNode + 1; i < r.activeNodes; ++i) outsideMass += r.nodes[i].mass;
  return coilBehindBase(dep, ds) + outsideLength + (mass - outsideMass) / (dep.material.density * dep.section.area);
}

double representedCoilMass(const Model& model, const State& state) {
  const Deployment& dep = *model.device;
  const DeviceState& ds = state.device;
  double outsideLength = 0;
  return dep.material.density * dep.section.area * coilBehindBase(dep, ds) + coilMassInNodes(dep, state, ds, outsideLength);
}

CatheterTip catheterTip(const Model& model, const State& state) {
  const Deployment& dep = *model.device;
  const DeviceState& ds = state.device;
  const RodState& chain = state.rods[dep.chainRod];
  const int T = dep.tipNode;
  CatheterTip tip;
  const Vec3 expected = ds.tipStart - ds.tipOffset * dep.retractDirection;
  tip.kickback = -(chain.x[T] - expected).dot(ds.exitStart);
  auto angle = [](const Vec3& a, const Vec3& b) { return std::atan2(a.cross(b).norm(), a.dot(b)); };
  tip.angle = angle(chain.q[0] * Vec3::UnitX(), chain.q[T] * Vec3::UnitX());
  if (dep.flexible()) {
    Quat rel = Quat::Identity();
    for (const Quat& r : dep.catheterRel) rel = rel * r;
    tip.restAngle = angle(Vec3::UnitX(), rel * Vec3::UnitX());
  }
  return tip;
}

void syncCatheterDrawing(const Model& model, State& state) {
  const Deployment& dep = *model.device;
  if (!dep.flexible()) return;
  const RodState& chain = state.rods[dep.chainRod];
  RodState& cath = state.rods[dep.catheterRod];
  for (int i = 0; i <= dep.tipNode; ++i) {
    cath.x[i] = chain.x[i], cath.q[i] = chain.q[i];
    cath.targets[i] = {chain.x[i], chain.q[i]};
  }
}

}  // namespace coilsim
