#include "physics/model.h"

#include <cmath>

#include "physics/beam.h"
#include "physics/contact/obstacle_tree.h"
#include "physics/deployment.h"
#include "physics/failure.h"

namespace coilsim {
namespace {

void requirePositive(const std::string& rod, const char* what, double v) {
  if (std::isfinite(v) && v > 0) return;
  Failure f = badRod(rod, std::string(what) + " must be a finite positive number, got " + std::to_string(v));
  f.quantity = what, f.value = v, f.limit = 0;
  throw PhysicsError(std::move(f));
}

void requireNode(const std::string& rod, const char* what, int node, int nnode) {
  if (node >= 0 && node < nnode) return;
  Failure f = badRod(rod, std::string(what) + " names node " + std::to_string(node) + " but the rod has nodes 0.." +
                              std::to_string(nnode - 1));
  f.quantity = what, f.value = node, f.limit = nnode - 1;
  throw PhysicsError(std::move(f));
}

RodModel compileRod(const RodDef& d) {
  requirePositive(d.name, "length", d.length);
  if (d.beams < 1) throw PhysicsError(badRod(d.name, "needs at least 1 beam"));
  requirePositive(d.name, "Young's modulus", d.material.youngModulus);
  requirePositive(d.name, "shear modulus", d.material.shearModulus);
  requirePositive(d.name, "density", d.material.density);
  requirePositive(d.name, "section area", d.section.area);
  requirePositive(d.name, "second moment Iy", d.section.iy);
  requirePositive(d.name, "second moment Iz", d.section.iz);
  requirePositive(d.name, "torsion constant", d.section.torsion);
  if (!std::isfinite(d.section.shearFactor) || d.section.shearFactor < 0)
    throw PhysicsError(badRod(d.name, "shear factor must be >= 0"));
  const int nnode = d.beams + 1;
  if (int(d.rest.points.size()) != nnode || int(d.rest.frames.size()) != nnode)
    throw PhysicsError(badRod(d.name, "rest shape has " + std::to_string(d.rest.points.size()) +
                                          " samples, expected beams + 1 = " + std::to_string(nnode)));

  RodModel r;
  r.name = d.name;
  r.role = d.role;
  r.nnode = nnode;
  r.material = d.material;
  r.section = d.section;
  const RestCurve rest = placed(d.rest, d.placement);
  r.restPoints = rest.points;
  r.restFrames = rest.frames;
  for (int e = 0; e + 1 < nnode; ++e) {
    r.beams.push_back(makeBeamRest(rest.points[e], rest.frames[e], rest.points[e + 1], rest.frames[e + 1],
                                   d.material, d.section));
    if (!(r.beams.back().length > 1e-12))
      throw PhysicsError(badRod(d.name, "beam " + std::to_string(e) + " has zero rest length"));
  }
  // Lumped mass: each node carries half of each neighbouring beam, with the
  // rotary inertia of that piece of rod about its own axes (rho J l, rho I l).
  r.nodeMass.assign(nnode, 0.0);
  r.nodeLength.assign(nnode, 0.0);
  for (int e = 0; e + 1 < nnode; ++e) {
    const double half = 0.5 * r.beams[e].length;
    r.nodeLength[e] += half;
    r.nodeLength[e + 1] += half;
  }
  const double rho = d.material.density;
  for (int i = 0; i < nnode; ++i) {
    r.nodeMass[i] = rho * d.section.area * r.nodeLength[i];
    r.nodeInertia.emplace_back(rho * d.section.torsion * r.nodeLength[i], rho * d.section.iy * r.nodeLength[i],
                               rho * d.section.iz * r.nodeLength[i]);
  }
  for (const Constraint& c : d.constraints) requireNode(d.name, "a constraint", c.node, nnode);
  for (const NodalLoad& l : d.loads) requireNode(d.name, "a load", l.node, nnode);
  r.constraints = d.constraints;
  r.loads = d.loads;
  return r;
}

}  // namespace

Model compileModel(const ModelDef& def) {
  if (def.device) {
    ModelDef rods = def;
    rods.device.reset();
    Deployment device = addDeployment(*def.device, rods);
    Model m = compileModel(rods);
    m.device = std::move(device);
    return m;
  }
  if (def.rods.empty()) throw PhysicsError(badDefinition({}, "model has no rod"));
  if (!def.gravity.allFinite()) throw PhysicsError(badDefinition({}, "gravity is not finite"));
  if (!std::isfinite(def.timeStep) || !(def.timeStep > 0))
    throw PhysicsError(badDefinition({}, "time step must be a finite positive number"));
  if (!(def.damping.massCoeff >= 0) || !(def.damping.stiffnessCoeff >= 0))
    throw PhysicsError(badDefinition({}, "Rayleigh damping coefficients must be finite and >= 0"));
  if (def.newtonIterations < 1) throw PhysicsError(badDefinition({}, "newton iterations must be >= 1"));
  Model m;
  for (const RodDef& r : def.rods) m.rods.push_back(compileRod(r));
  m.gravity = def.gravity;
  m.damping = def.damping;
  if (!std::isfinite(def.sleep.speed + def.sleep.time + def.sleep.wakeForce) || !(def.sleep.speed >= 0) ||
      !(def.sleep.time >= 0) || !(def.sleep.wakeForce >= 0))
    throw PhysicsError(badDefinition({}, "sleep thresholds must be finite and >= 0"));
  m.sleep = def.sleep;
  m.timeStep = def.timeStep;
  m.newtonIterations = def.newtonIterations;
  m.coupledPairs = def.coupledPairs;
  m.health = def.health;
  m.effects = def.effects;
  for (const Obstacle& o : def.obstacles) {
    if (!o.mesh || o.mesh->triangles.empty())
      throw PhysicsError(badDefinition("obstacle '" + o.name + "'", "has no triangles"));
    if (!(o.friction >= 0) || !std::isfinite(o.friction))
      throw PhysicsError(badDefinition("obstacle '" + o.name + "'", "friction must be finite and >= 0"));
  }
  m.obstacles = def.obstacles;
  m.obstacleTrees = buildObstacleTrees(m.obstacles);
  for (const EffectUse& u : m.effects) {
    if (!u.effect) throw PhysicsError(badDefinition({}, "effect use without an effect"));
    const auto specs = u.effect->params();
    if (u.values.size() != specs.size())
      throw PhysicsError(badDefinition("effect '" + std::string(u.name()) + "'",
                                       "has " + std::to_string(u.values.size()) + " values for " +
                                           std::to_string(specs.size()) + " parameters"));
    for (size_t i = 0; i < specs.size(); ++i) {
      const double edge = u.values[i] / specs[i].toSI;
      if (std::isfinite(u.values[i]) && edge >= specs[i].min && edge <= specs[i].max) continue;
      Failure f = badDefinition("effect '" + std::string(u.name()) + "'",
                                "parameter '" + std::string(specs[i].name) + "' = " + std::to_string(edge) +
                                    " is outside [" + std::to_string(specs[i].min) + ", " +
                                    std::to_string(specs[i].max) + "] " + std::string(specs[i].unit));
      f.quantity = specs[i].name, f.value = u.values[i];
      throw PhysicsError(std::move(f));
    }
  }
  return m;
}

const EffectUse* findEffect(const Model& model, std::string_view name) {
  for (const EffectUse& u : model.effects)
    if (u.name() == name) return &u;
  return nullptr;
}

EffectUse* findEffect(Model& model, std::string_view name) {
  for (EffectUse& u : model.effects)
    if (u.name() == name) return &u;
  return nullptr;
}

}  // namespace coilsim
