// The wire-injection experiment of Stoop et al. 2011 (see wire_injection.h).
#include "planning/wire_injection.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "physics/effect.h"
#include "physics/run.h"
#include "physics/section.h"
#include "planning/auto_deploy.h"
#include "planning/run_contacts.h"
#include "planning/sac_geometry.h"
#include "planning/winding_order.h"

namespace coilsim::planning {
namespace {

// The catalogue's filling-helical-4x80: platinum wound into a 0.254 mm
// primary coil, B 0.001827 N mm^2, C 0.002174 N mm^2 (docs/coils.md), as
// planning/dense_sac.cpp lays it.
constexpr double kYoung = 168e9, kPoisson = 0.38, kDensity = 21450, kArea = 0.023e-6;
constexpr double kBending = 1.827e-9, kTorsion = 2.174e-9;  // N m^2

void check(bool good, const char* field, const char* expected) {
  if (!good) throw std::invalid_argument(std::string("wire injection: ") + field + " must be " + expected);
}

EffectUse contactWithFriction(const char* name, double mu) {
  EffectUse use = EffectRegistry::global().use(name);
  use.set("friction_static", mu);
  use.set("friction_dynamic", 0.9 * mu);
  return use;
}

double coilLengthFor(const WireInjectionSpec& s) {
  const double d = s.wireDiameter, big = s.cavityRatio * d;
  // phi = (pi d^2 / 4) L / (pi D^3 / 6), and a stroke more, so the wire is never fully out.
  return s.targetPacking * (2.0 / 3.0) * big * big * big / (d * d) + 2 * s.stroke;
}

}  // namespace

double injectedPacking(double length, double d, double big) { return 1.5 * length * d * d / (big * big * big); }

Model wireInjectionModel(const WireInjectionSpec& s) {
  check(std::isfinite(s.cavityRatio) && s.cavityRatio >= 6 && s.cavityRatio <= 200, "cavity ratio D/d", "in [6, 200]");
  check(std::isfinite(s.friction) && s.friction >= 0 && s.friction <= 2, "friction", "in [0, 2]");
  check(std::isfinite(s.turnsPerDiameter) && std::abs(s.turnsPerDiameter) <= 20, "turns per cavity diameter",
        "in [-20, 20]");
  check(std::isfinite(s.targetPacking) && s.targetPacking > 0 && s.targetPacking <= 0.5, "target packing",
        "in (0, 0.5]");
  check(s.wireDiameter > 0 && s.beam > 0 && s.pushSpeed > 0 && s.stroke > 0 && s.jamForceRatio > 0,
        "wire diameter, beam, push speed, stroke and jam force", "positive");
  ModelDef def;
  def.damping = {1.0, 0.0};
  def.timeStep = 1e-3;
  def.gravity = Vec3::Zero();
  def.effects.push_back(contactWithFriction("wall_contact", s.friction));
  def.effects.push_back(contactWithFriction("self_contact", s.friction));
  const double radius = 0.5 * s.cavityRatio * s.wireDiameter;
  Obstacle wall;
  wall.name = "cavity";
  wall.friction = s.friction;
  wall.mesh = std::make_shared<const TriangleMesh>(makeIcosphere(Vec3::Zero(), radius, s.wallSubdivisions, "cavity"));
  def.obstacles.push_back(wall);

  DeploymentDef d;
  d.coilName = "wire";
  d.coil.length = coilLengthFor(s);
  d.coil.rest.type = RestShapeDef::Type::Straight;
  d.coil.youngModulus = kYoung;
  d.coil.poissonRatio = kPoisson;
  d.coil.density = kDensity;
  d.coil.explicitSection.area = kArea;
  d.coil.explicitSection.iy = d.coil.explicitSection.iz = kBending / kYoung;
  d.coil.explicitSection.torsion = kTorsion / shearModulusOf(kYoung, kPoisson);
  d.coil.explicitSection.radius = 0.5 * s.wireDiameter;
  d.coilBeams = std::max(2, int(std::lround(d.coil.length / s.beam)));
  // The tip a wire diameter inside the wall at -z, pushing towards the centre.
  d.tip.position = Vec3(0, 0, -(radius - s.wireDiameter));
  d.tip.direction = Vec3(std::sin(s.tilt), 0, std::cos(s.tilt));
  d.tip.normal = Vec3(0, 1, 0);
  d.catheterOuterRadius = 0.5 * s.wireDiameter;
  d.catheterDrawLength = 2e-3;
  d.maxPushSpeed = std::max(0.05, s.pushSpeed);
  d.maxTwistRate = 1e3;
  def.device = d;
  return compileModel(def);
}

WireInjectionResult runWireInjection(const WireInjectionSpec& s) {
  using Kind = DeviceCommand::Kind;
  WireInjectionResult r;
  const Model model = wireInjectionModel(s);
  State state = makeState(model);
  const Deployment& dep = *model.device;
  setDrawnCatheterActive(dep, state, false);
  const double big = s.cavityRatio * s.wireDiameter, dt = model.timeStep;
  const double target = coilLengthFor(s) - 2 * s.stroke;
  r.forceScale = kBending / (0.25 * big * big);
  const double twistPerLength = 2 * M_PI * s.turnsPerDiameter / big;  // rad per m pushed
  FeltTipForce feel(0.02);
  const DeviceState& ds = state.device;
  bool stroking = false;
  // Enough simulated time for every stroke and every feel, twice over.
  const long maxSteps = long(std::ceil(2 * (target / s.pushSpeed + (target / s.stroke + 1) * 0.04) / dt));
  for (long k = 0; k < maxSteps; ++k) {
    if (!stroking) {
      const double stroke = std::min(s.stroke, target - ds.deployed);
      command(model, state, {Kind::Push, s.pushSpeed, stroke});
      if (twistPerLength != 0)
        command(model, state, {Kind::Twist, twistPerLength * s.pushSpeed, std::abs(twistPerLength) * stroke});
      stroking = true;
    }
    const double before = ds.deployed, twistBefore = ds.twist;
    const StepReport rep = advance(model, state);
    ++r.steps;
    if (!rep.ok()) {
      r.ok = false;
      r.error = rep.message();
      break;
    }
    r.maxWallPenetrationOfRadius = state.stats.maxWallPenetrationOfRadius;
    if (!feel.add(dep, state, ds.deployed == before && ds.twist == twistBefore, dt)) continue;
    // At rest after a stroke: one point of the force curve.
    r.samples.push_back({ds.deployed, injectedPacking(ds.deployed, s.wireDiameter, big), feel.axial});
    r.maxForce = std::max(r.maxForce, feel.axial);
    stroking = false;
    if (ds.deployed >= target - 1e-9) break;
    if (feel.axial > s.jamForceRatio * r.forceScale) {
      r.jammed = true;
      break;
    }
  }
  r.simulated = state.time;
  if (r.ok && !r.jammed && ds.deployed < target - 1e-9) {
    r.ok = false;
    r.error = "the wire did not reach the target packing within " + std::to_string(r.simulated) + " s simulated";
  }
  r.injected = ds.deployed;
  r.packing = injectedPacking(ds.deployed, s.wireDiameter, big);
  const RodState& chain = state.rods[size_t(dep.chainRod)];
  r.wire.assign(chain.x.begin() + dep.tipNode, chain.x.begin() + chain.activeNodes);
  r.order = windingOrder(r.wire, Vec3::Zero()).order;
  return r;
}

}  // namespace coilsim::planning
