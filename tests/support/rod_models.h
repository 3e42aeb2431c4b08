#pragma once
// Small model builders shared by the physics tests: a rod (straight or any
// rest curve) with its material and section, clamped or not, in a model with
// chosen effects; plus read-outs (tangents, elastic forces). Units are SI
// unless a benchmark states its own consistent set.
#include <initializer_list>
#include <string>
#include <vector>

#include "physics/assembly.h"
#include "physics/effect.h"
#include "physics/integrator.h"
#include "physics/model.h"
#include "physics/rest_shape.h"
#include "physics/section.h"
#include "physics/state.h"

namespace coilsim::test {

inline constexpr double kSteelPoisson = 0.3;

// Spring steel: E = 200 GPa, nu = 0.3, rho = 7800 kg/m^3.
inline Material steel() { return {200e9, shearModulusOf(200e9, kSteelPoisson), 7800}; }

// Platinum-tungsten coil wire as in Dequidt et al. 2008 (E = 7.5 GPa,
// nu = 0.39, rho = 21450 kg/m^3).
inline constexpr double kPlatinumPoisson = 0.39;
inline Material platinum() { return {7.5e9, shearModulusOf(7.5e9, kPlatinumPoisson), 21450}; }

// A section given by its constants (benchmarks quote EA, EI, GJ directly).
inline Section customSection(double area, double iy, double iz, double torsion, double shearFactor, double radius) {
  Section s;
  s.area = area;
  s.iy = iy;
  s.iz = iz;
  s.torsion = torsion;
  s.shearFactor = shearFactor;
  s.radius = radius;
  return s;
}

inline RodDef rodWithRest(const RestCurve& rest, double length, int beams, const Material& m, const Section& s) {
  RodDef r;
  r.length = length;
  r.beams = beams;
  r.rest = rest;
  r.material = m;
  r.section = s;
  return r;
}

// Straight rod along +x from the origin, d1 = +y, d2 = +z.
inline RodDef straightRod(double length, int beams, const Material& m, const Section& s) {
  return rodWithRest(makeStraight(length, beams), length, beams, m, s);
}

// A straight platinum wire of `radius` named `name` from `start` along the
// unit `along`, d1 horizontal (z x along): the wires the contact-force
// tests lay on one another.
inline RodDef platinumWire(const char* name, const Vec3& start, const Vec3& along, double length, int beams,
                           double radius) {
  RodDef r = rodWithRest(makeStraight(length, beams), length, beams, platinum(), circularSection(radius, kPlatinumPoisson));
  r.name = name;
  r.placement.position = start;
  r.placement.direction = along;
  r.placement.normal = Vec3::UnitZ().cross(along).normalized();
  return r;
}

// Clamps node 0 (all six DOFs) at its rest pose.
inline RodDef clamped(RodDef r) {
  r.constraints.push_back({0, kAllDofs});
  return r;
}

// A model holding `rods`, no gravity vector unless given, the named effects
// switched on with their default parameters.
inline ModelDef modelOf(std::vector<RodDef> rods, std::initializer_list<const char*> effects = {},
                        const Vec3& gravity = Vec3::Zero()) {
  ModelDef d;
  d.rods = std::move(rods);
  d.gravity = gravity;
  for (const char* name : effects) d.effects.push_back(EffectRegistry::global().use(name));
  return d;
}

// Static solve settings tight enough that the Newton tolerance never sets a
// measured error: updates below 1e-13 of the rod length and 1e-12 rad are
// within a few hundred ulps of the coordinates.
inline StaticOptions tightStatic(int loadSteps) {
  StaticOptions o;
  o.loadSteps = loadSteps;
  o.maxIterations = 200;
  o.positionTolerance = 1e-13;
  o.rotationTolerance = 1e-12;
  return o;
}

inline Vec3 tangentOf(const Quat& q) { return q * Vec3::UnitX(); }

// Elastic (plus load and effect) forces of rod k at the state's poses, with
// the tangent; returns the elastic energy. The forces are in
// state.rods[k].work.force, the tangent in state.rods[k].work.stiffness.
inline double assembleAt(const Model& model, State& state, int k = 0) {
  return assembleRod(model, k, state.rods[k], state.time, 1.0, true);
}

// Rotational inertia of node i about global axes, R diag(I) R^T, from the
// model's lumped material-frame inertia (computed here, not by the core).
inline Mat3 globalInertia(const RodModel& rod, const Quat& q, int node) {
  const Mat3 r = q.toRotationMatrix();
  return r * rod.nodeInertia[node].asDiagonal() * r.transpose();
}

// Elastic energy of all rods (J), independent of any effect.
inline double elasticEnergy(const Model& model, const State& state) { return computeEnergy(model, state).elastic; }

// Runs `steps` dynamic steps; returns false (and stops) at the first refused step.
inline bool run(const Model& model, State& state, int steps) {
  for (int i = 0; i < steps; ++i)
    if (!step(model, state).ok()) return false;
  return true;
}

}  // namespace coilsim::test
