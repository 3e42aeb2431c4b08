// SceneSpec checks across fields, and its compilation into an SI ModelDef.
#include "io/scene.h"

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

void checkNode(const SceneSpec& s, const RodSpec& rod, const NodeRef& node, const std::string& path) {
  if (!node.last && (node.index < 0 || node.index > rod.beams))
    fail(s, path,
         "node " + std::to_string(node.index) + " is out of range: rod \"" + rod.name + "\" has nodes 0.." +
             std::to_string(rod.beams) + " (beams + 1 nodes); \"last\" names node " + std::to_string(rod.beams));
}

void checkRod(const SceneSpec& s, const RodSpec& rod, size_t k) {
  const std::string at = rodPath(k);
  if (rod.rest.type == RestShapeSpec::Type::Polyline) {
    double arc = 0;
    for (size_t i = 1; i < rod.rest.pointsMm.size(); ++i) arc += (rod.rest.pointsMm[i] - rod.rest.pointsMm[i - 1]).norm();
    if (!(std::abs(arc - rod.lengthMm) <= 0.01 * rod.lengthMm))
      fail(s, at + "/rest_shape/points_mm",
           "the polyline is " + fmt(arc) + " mm long but length_mm is " + fmt(rod.lengthMm) +
               " mm; they must agree within 1 %");
  }
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
  if (s.solve == SolveMode::Dynamic) {
    const double steps = s.durationS / s.timeStepS;
    if (!(steps <= 1e9))
      fail(s, "/duration_s", "duration_s / time_step_s = " + fmt(steps) + " steps; at most 1e9 are allowed");
  }
}

ModelDef compileScene(const SceneSpec& s) {
  using namespace units;
  ModelDef def;
  def.gravity = s.gravityMS2;
  def.timeStep = s.solve == SolveMode::Dynamic ? s.timeStepS : 1e-3;  // unused by static solves
  def.newtonIterations = s.newtonIterations;
  def.damping = {s.rayleighMass, s.rayleighStiffness};
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
    const RodSpec& r = s.rods[k];
    RodDef d;
    d.name = r.name;
    d.role = r.role;
    d.length = mmToM(r.lengthMm);
    d.beams = r.beams;
    const RestShapeSpec& rest = r.rest;
    try {
      switch (rest.type) {
        case RestShapeSpec::Type::Straight: d.rest = makeStraight(d.length, d.beams); break;
        case RestShapeSpec::Type::Helix:
          d.rest = makeHelix(d.length, d.beams, mmToM(rest.loopDiameterMm), mmToM(rest.pitchMm), rest.rightHanded);
          break;
        case RestShapeSpec::Type::Polyline: {
          std::vector<Vec3> points;
          for (const Vec3& p : rest.pointsMm) points.push_back(p * kMetresPerMm);
          d.rest = makePolyline(points, d.length, d.beams, rest.frames, degPerMmToRadPerM(rest.twistDegPerMm));
          break;
        }
        case RestShapeSpec::Type::Birdcage:
          d.rest = makeBirdcage(d.length, d.beams, mmToM(rest.sphereDiameterMm), degToRad(rest.planeTurnPerLoopDeg));
          break;
      }
    } catch (const std::exception& ex) {
      fail(s, rodPath(k) + "/rest_shape", std::string("cannot build the rest shape: ") + ex.what());
    }
    d.placement.position = r.placement.positionMm * kMetresPerMm;
    d.placement.direction = r.placement.direction;
    d.placement.normal = r.placement.normal;
    const double young = gpaToPa(r.material.youngModulusGpa);
    d.material = {young, shearModulusOf(young, r.material.poissonRatio), gcm3ToKgm3(r.material.densityGcm3)};
    if (r.section.circular) {
      d.section = circularSection(mmToM(r.section.wireRadiusMm), r.material.poissonRatio);
    } else {
      d.section.area = mm2ToM2(r.section.areaMm2);
      d.section.iy = d.section.iz = mm4ToM4(r.section.inertiaMm4);
      d.section.torsion = mm4ToM4(r.section.torsionMm4);
      d.section.shearFactor = r.section.shearFactor;
      d.section.radius = mmToM(r.section.outerRadiusMm);
    }
    for (const BoundarySpec& b : r.boundary)
      d.constraints.push_back({b.node.resolve(r.beams), b.clamped ? unsigned(kAllDofs) : unsigned(kTranslation),
                               b.velocityMmS * kMetresPerMm, b.angularVelocityDegS * kRadPerDeg});
    for (const LoadSpec& l : r.loads)
      d.loads.push_back({l.node.resolve(r.beams), l.forceN, l.momentNmm * kMetresPerMm});
    def.rods.push_back(std::move(d));
  }
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
