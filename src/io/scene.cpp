// SceneSpec checks across fields, and its compilation into an SI ModelDef.
#include "io/scene.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "io/units.h"

namespace coilsim::io {
namespace {

std::string fmt(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

[[noreturn]] void fail(const SceneSpec& s, const std::string& path, const std::string& message) {
  throw InputError(s.file + ": " + path + ": " + message);
}

std::string rodPath(size_t i) { return "/rods/" + std::to_string(i); }

void checkNode(const SceneSpec& s, const RodSpecMm& rod, const NodeRef& node, const std::string& path) {
  if (!node.last && (node.index < 0 || node.index > rod.beams))
    fail(s, path,
         "node " + std::to_string(node.index) + " is out of range: rod \"" + rod.name + "\" has nodes 0.." +
             std::to_string(rod.beams) + " (beams + 1 nodes); \"last\" names node " + std::to_string(rod.beams));
}

// A polyline rest shape must be as long as the rod (or coil) it shapes.
void checkRestShape(const SceneSpec& s, const RestShapeSpec& rest, double lengthMm, const std::string& at) {
  if (rest.type != RestShapeSpec::Type::Polyline) return;
  double arc = 0;
  for (size_t i = 1; i < rest.pointsMm.size(); ++i) arc += (rest.pointsMm[i] - rest.pointsMm[i - 1]).norm();
  if (!(std::abs(arc - lengthMm) <= 0.01 * lengthMm))
    fail(s, at + "/rest_shape/points_mm",
         "the polyline is " + fmt(arc) + " mm long but length_mm is " + fmt(lengthMm) +
             " mm; they must agree within 1 %");
}

void checkRod(const SceneSpec& s, const RodSpecMm& rod, size_t k) {
  const std::string at = rodPath(k);
  checkRestShape(s, rod.rest, rod.lengthMm, at);
  const PlacementSpec& p = rod.placement;
  if (!(p.direction.norm() > 1e-12)) fail(s, at + "/placement/direction", "expected a non-zero vector, got [0, 0, 0]");
  const Vec3 t = p.direction.normalized();
  if (!((p.normal - p.normal.dot(t) * t).norm() > 1e-6 * std::max(p.normal.norm(), 1e-300)))
    fail(s, at + "/placement/normal", "expected a non-zero vector not parallel to direction");
  for (size_t j = 0; j < rod.boundary.size(); ++j) {
    const std::string bp = at + "/boundary/" + std::to_string(j);
    checkNode(s, rod, rod.boundary[j].node, bp + "/node");
    for (size_t i = 0; i < j; ++i)
      if (rod.boundary[i].node.resolve(rod.beams) == rod.boundary[j].node.resolve(rod.beams))
        fail(s, bp + "/node",
             "node " + std::to_string(rod.boundary[j].node.resolve(rod.beams)) + " is already held by " + at +
                 "/boundary/" + std::to_string(i));
    if (s.solve == SolveMode::Static && (!rod.boundary[j].velocityMmS.isZero(0) || !rod.boundary[j].angularVelocityDegS.isZero(0)))
      fail(s, bp, "a static solve has no time: prescribed velocities need \"solve\": \"dynamic\"");
  }
  for (size_t j = 0; j < rod.loads.size(); ++j) checkNode(s, rod, rod.loads[j].node, at + "/loads/" + std::to_string(j) + "/node");
  if (s.solve == SolveMode::Static && rod.boundary.empty())
    fail(s, at + "/boundary", "a static solve needs every rod held by at least one clamped or pinned node");
}

// Rod names the deployment adds (see addDeployment): the coil, its detached
// copy and the catheter.
std::vector<std::string> deploymentRodNames(const DeploymentSpec& d) {
  return {d.coilName, d.coilName + " (detached)", "catheter"};
}

void checkDeployment(const SceneSpec& s, const DeploymentSpec& d) {
  const std::string at = "/deployment";
  if (s.solve != SolveMode::Dynamic)
    fail(s, at, "a deployment moves in time: it needs \"solve\": \"dynamic\"");
  checkRestShape(s, d.rest, d.lengthMm, at + "/coil");
  if (d.initialDeployedMm > d.lengthMm)
    fail(s, at + "/initial_deployed_mm",
         "expected at most the coil's length_mm (" + fmt(d.lengthMm) + " mm), got " + fmt(d.initialDeployedMm) + " mm");
  const CatheterSpec& c = d.catheter;
  if (!(c.direction.norm() > 1e-12)) fail(s, at + "/catheter/direction", "expected a non-zero vector, got [0, 0, 0]");
  if (!(c.referenceNormal.norm() > 1e-12))
    fail(s, at + "/catheter/reference_normal", "expected a non-zero vector, got [0, 0, 0]");
  // The reference normal is the coil's d1 at the tip: it must be a normal of the exit direction.
  const double cosine = c.direction.normalized().dot(c.referenceNormal.normalized());
  if (!(std::abs(cosine) <= 1e-6))
    fail(s, at + "/catheter/reference_normal",
         "expected a vector orthogonal to direction; the angle between them is " +
             fmt(units::radToDeg(std::acos(std::clamp(cosine, -1.0, 1.0)))) + " deg");
  if (c.flexible) {
    if (!(c.innerDiameterMm < c.outerDiameterMm))
      fail(s, at + "/catheter/inner_diameter_mm",
           "expected less than outer_diameter_mm (" + fmt(c.outerDiameterMm) + " mm), got " + fmt(c.innerDiameterMm) +
               " mm");
    const CatheterShape shape{c.rest.type, units::degToRad(c.rest.angleDeg), units::mmToM(c.rest.radiusMm)};
    const double bendsMm = units::mToMm(shape.bendLength());
    if (!(bendsMm <= c.freeLengthMm * (1 + 1e-9)))
      fail(s, at + "/catheter/rest_shape",
           "the bends take " + fmt(bendsMm) + " mm of arc (angle x radius) but free_length_mm is " +
               fmt(c.freeLengthMm) + " mm; shorten the radius or lengthen the free part");
  }
  const std::vector<std::string> names = deploymentRodNames(d);
  for (size_t k = 0; k < s.rods.size(); ++k)
    for (const std::string& name : names)
      if (s.rods[k].name == name)
        fail(s, rodPath(k) + "/name",
             "rod name \"" + name + "\" is taken by the deployment (coil \"" + d.coilName +
                 "\", its detached copy and the catheter); rename one of them");
}

}  // namespace

long stepCount(double durationS, double timeStepS) {
  // A duration a hair over a whole number of steps (decimal rounding) is that number.
  return std::max(1L, long(std::ceil(durationS / timeStepS - 1e-9)));
}

void checkScene(const SceneSpec& s) {
  for (size_t k = 0; k < s.rods.size(); ++k) {
    for (size_t j = 0; j < k; ++j)
      if (s.rods[j].name == s.rods[k].name)
        fail(s, rodPath(k) + "/name", "rod name \"" + s.rods[k].name + "\" is already used by " + rodPath(j));
    checkRod(s, s.rods[k], k);
  }
  if (s.deployment) checkDeployment(s, *s.deployment);
  if (s.solve == SolveMode::Dynamic) {
    const double steps = s.durationS / s.timeStepS;
    if (!(steps <= 1e9))
      fail(s, "/duration_s", "duration_s / time_step_s = " + fmt(steps) + " steps; at most 1e9 are allowed");
  }
}

namespace {

// The physics description of a rod or of the deployment's coil (SI).
RodSpec rodSpecOf(double lengthMm, const RestShapeSpec& r, const MaterialSpec& m, const SectionSpec& sec) {
  using namespace units;
  RodSpec rod;
  rod.length = mmToM(lengthMm);
  rod.rest.type = r.type;
  rod.rest.loopDiameter = mmToM(r.loopDiameterMm);
  rod.rest.pitch = mmToM(r.pitchMm);
  rod.rest.rightHanded = r.rightHanded;
  for (const Vec3& p : r.pointsMm) rod.rest.points.push_back(p * kMetresPerMm);
  rod.rest.frames = r.frames;
  rod.rest.twistPerLength = degPerMmToRadPerM(r.twistDegPerMm);
  rod.rest.sphereDiameter = mmToM(r.sphereDiameterMm);
  rod.rest.planeTurnPerLoop = degToRad(r.planeTurnPerLoopDeg);
  rod.youngModulus = gpaToPa(m.youngModulusGpa);
  rod.poissonRatio = m.poissonRatio;
  rod.density = gcm3ToKgm3(m.densityGcm3);
  if (sec.circular) {
    rod.wireRadius = mmToM(sec.wireRadiusMm);
  } else {
    Section& out = rod.explicitSection;
    out.area = mm2ToM2(sec.areaMm2);
    out.iy = out.iz = mm4ToM4(sec.inertiaMm4);
    out.torsion = mm4ToM4(sec.torsionMm4);
    out.shearFactor = sec.shearFactor;
    out.radius = mmToM(sec.outerRadiusMm);
  }
  return rod;
}

RestCurve compileRest(const SceneSpec& s, const RodSpec& rod, int beams, const std::string& at) {
  try {
    return makeRest(rod.rest, rod.length, beams);
  } catch (const std::exception& ex) {
    fail(s, at + "/rest_shape", std::string("cannot build the rest shape: ") + ex.what());
  }
}

// A flexible catheter's tube (its section comes from its diameters).
Material compileMaterial(const MaterialSpec& m) {
  const double young = units::gpaToPa(m.youngModulusGpa);
  return {young, shearModulusOf(young, m.poissonRatio), units::gcm3ToKgm3(m.densityGcm3)};
}

DeploymentDef compileDeployment(const SceneSpec& s, const DeploymentSpec& d) {
  using namespace units;
  DeploymentDef def;
  def.coilName = d.coilName;
  def.coil = rodSpecOf(d.lengthMm, d.rest, d.material, d.section);
  def.coilBeams = d.beams;
  // compileModel samples the rest shape; sampled here first so that a shape
  // that cannot be built is named by its JSON path.
  compileRest(s, def.coil, d.beams, "/deployment/coil");
  def.tip.position = d.catheter.tipPositionMm * kMetresPerMm;
  def.tip.direction = d.catheter.direction;
  def.tip.normal = d.catheter.referenceNormal;
  def.catheterOuterRadius = 0.5 * mmToM(d.catheter.outerDiameterMm);
  if (d.catheter.flexible) {
    const CatheterSpec& c = d.catheter;
    CatheterDef& f = def.catheter;
    f.flexible = true;
    f.material = compileMaterial(c.material);
    f.outerRadius = 0.5 * mmToM(c.outerDiameterMm);
    f.innerRadius = 0.5 * mmToM(c.innerDiameterMm);
    f.shape = {c.rest.type, degToRad(c.rest.angleDeg), mmToM(c.rest.radiusMm)};
    f.heldLength = mmToM(c.heldLengthMm);
    f.freeLength = mmToM(c.freeLengthMm);
    f.beams = c.beams;
    f.weighting = c.weighting;
  }
  def.catheterDrawLength = mmToM(d.catheter.drawLengthMm);
  def.initialDeployed = mmToM(d.initialDeployedMm);
  def.initialTwist = degToRad(d.initialTwistDeg);
  def.maxPushSpeed = mmPerSToMPerS(d.maxPushSpeedMmS);
  def.maxTwistRate = degPerSToRadPerS(d.maxTwistRateDegS);
  return def;
}

}  // namespace

ModelDef compileScene(const SceneSpec& s) {
  using namespace units;
  ModelDef def;
  def.gravity = s.gravityMS2;
  def.timeStep = s.solve == SolveMode::Dynamic ? s.timeStepS : 1e-3;  // unused by static solves
  def.newtonIterations = s.newtonIterations;
  def.damping = {s.rayleighMass, s.rayleighStiffness};
  def.sleep.enabled = s.sleep;  // the default thresholds unless the scene gives its own
  if (!s.sleepValues.empty()) {
    std::vector<double> si;
    for (size_t i = 0; i < s.sleepValues.size() && i < std::size(kSleepParams); ++i)
      si.push_back(s.sleepValues[i] * kSleepParams[i].toSI);
    try {
      def.sleep = sleepSettings(s.sleep, si);
    } catch (const std::exception& ex) {
      fail(s, "/sleep", ex.what());
    }
  }
  for (const EffectSpec& e : s.effects) {
    EffectUse use;
    try {
      use = EffectRegistry::global().use(e.name);
    } catch (const std::exception& ex) {
      fail(s, "/effects/" + pointerSegment(e.name), ex.what());
    }
    const auto specs = use.effect->params();
    if (e.values.size() != specs.size())
      fail(s, "/effects/" + pointerSegment(e.name),
           "expected " + std::to_string(specs.size()) + " parameter values, got " + std::to_string(e.values.size()));
    for (size_t i = 0; i < specs.size(); ++i) use.values[i] = e.values[i] * specs[i].toSI;
    use.enabled = e.enabled;
    def.effects.push_back(use);
  }
  for (size_t k = 0; k < s.rods.size(); ++k) {
    const RodSpecMm& r = s.rods[k];
    RodDef d;
    d.name = r.name;
    d.role = r.role;
    const RodSpec rod = rodSpecOf(r.lengthMm, r.rest, r.material, r.section);
    d.length = rod.length;
    d.beams = r.beams;
    d.rest = compileRest(s, rod, d.beams, rodPath(k));
    d.placement.position = r.placement.positionMm * kMetresPerMm;
    d.placement.direction = r.placement.direction;
    d.placement.normal = r.placement.normal;
    d.material = materialOf(rod);
    d.section = sectionOf(rod);
    for (const BoundarySpec& b : r.boundary)
      d.constraints.push_back({b.node.resolve(r.beams), b.clamped ? unsigned(kAllDofs) : unsigned(kTranslation),
                               b.velocityMmS * kMetresPerMm, b.angularVelocityDegS * kRadPerDeg});
    for (const LoadSpec& l : r.loads)
      d.loads.push_back({l.node.resolve(r.beams), l.forceN, l.momentNmm * kMetresPerMm});
    def.rods.push_back(std::move(d));
  }
  // The deployment's rods come after the scene's, so rod indices of the file hold.
  if (s.deployment) {
    def.device = compileDeployment(s, *s.deployment);
    try {
      // compileModel builds it again; built here, a bad deployment is named by its JSON path.
      ModelDef probe;
      (void)addDeployment(*def.device, probe);
    } catch (const std::exception& ex) {
      fail(s, "/deployment", std::string("cannot build the deployment: ") + ex.what());
    }
  }
  def.obstacles = compileObstacles(s.obstacles, s.file);
  return def;
}

StaticOptions staticOptions(const SceneSpec& s) {
  StaticOptions o;
  o.loadSteps = s.loadSteps;
  o.maxIterations = s.maxNewtonIterations;
  return o;
}

SceneSpec loadScene(const std::string& path) {
  SceneSpec s = parseScene(readJsonFile(path), path);
  checkScene(s);
  return s;
}

SceneSpec sceneFromText(std::string_view text, const std::string& label) {
  SceneSpec s = parseScene(parseJson(text, label), label);
  checkScene(s);
  return s;
}

}  // namespace coilsim::io
