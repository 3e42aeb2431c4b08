#include "scenes.h"

#include "physics/effect.h"
#include "render/geometry.h"

namespace coilsim::testing {
namespace {

RodDef platinumRod(const std::string& name, RodRole role, double length, int beams, double radius) {
  RodDef r;
  r.name = name;
  r.role = role;
  r.length = length;
  r.beams = beams;
  r.material = {7.5e9, shearModulusOf(7.5e9, 0.39), 21450};
  r.section = circularSection(radius, 0.39);
  r.constraints.push_back({0, kAllDofs});
  return r;
}

// A closed render mesh as a draw mesh (the vessel phantom is drawn, not simulated).
DrawMesh toDrawMesh(const std::string& name, const render::TriangleMesh& t, const Colour& colour) {
  DrawMesh m;
  m.name = name;
  m.colour = colour;
  for (const render::Vertex& v : t.vertices) m.vertices.emplace_back(v.position[0], v.position[1], v.position[2]);
  for (size_t k = 0; k + 2 < t.indices.size(); k += 3)
    m.triangles.emplace_back(int(t.indices[k]), int(t.indices[k + 1]), int(t.indices[k + 2]));
  return m;
}

// Centre of the coil's loops: the helix axis passes through it along y.
const Vec3 kSacCentre(0.0, -0.0012, 0.003);

}  // namespace

Model straightRodModel() {
  ModelDef d;
  RodDef r = platinumRod("rod", RodRole::Coil, 0.01, 20, 0.25e-3);
  r.rest = makeStraight(r.length, r.beams);
  d.rods.push_back(r);
  return compileModel(d);
}

Model helixModel() {
  ModelDef d;
  RodDef coil = platinumRod("coil", RodRole::Coil, 0.06, 120, 0.15e-3);
  coil.rest = makeHelix(coil.length, coil.beams, 0.006, 0.0008, true);
  // Tangent +x, principal normal (towards the helix axis) +z: the axis runs along -y.
  coil.placement.direction = Vec3::UnitX();
  coil.placement.normal = Vec3::UnitZ();
  d.rods.push_back(coil);

  RodDef cath = platinumRod("catheter", RodRole::Catheter, 0.014, 14, 0.35e-3);
  cath.material = {1.5e9, shearModulusOf(1.5e9, 0.4), 1100};
  cath.rest = makeStraight(cath.length, cath.beams);
  // Up from the parent vessel through the neck, its tip at the coil's first node.
  const Vec3 dir = Vec3(1.0, 0.0, 0.35).normalized();
  cath.placement.position = -cath.length * dir;
  cath.placement.direction = dir;
  cath.placement.normal = Vec3::UnitY();
  d.rods.push_back(cath);

  d.effects.push_back(EffectRegistry::global().use("gravity"));
  d.damping.massCoeff = 5.0;
  return compileModel(d);
}

void decorateRod(const Model&, const State&, DrawData& out) {
  if (out.tubes.empty()) return;
  DrawTube& t = out.tubes[0];
  const size_t n = t.colours.size();
  for (size_t i = 0; i < n; ++i) {
    const float s = n > 1 ? float(i) / float(n - 1) : 0.0f;
    t.colours[i] = Colour(0.15f + 0.8f * s, 0.35f, 0.9f - 0.75f * s, 1.0f);  // blue to red along the rod
  }
}

void decorateHelix(const Model&, const State&, DrawData& out) {
  render::TriangleMesh sac, parent;
  render::appendSphere(kSacCentre, 0.0045, Colour(1, 1, 1, 1), sac, 32, 20);
  DrawTube vessel;
  vessel.radius = 0.0022;
  for (int i = 0; i <= 16; ++i) vessel.centre.emplace_back(-0.014 + 0.028 * i / 16.0, kSacCentre.y(), -0.0035);
  render::TubeOptions o;
  o.sides = 32;
  o.capRings = 6;
  render::appendTube(vessel, o, parent);
  const Colour wall(0.85f, 0.32f, 0.30f, 0.30f);
  out.meshes.push_back(toDrawMesh("aneurysm", sac, wall));
  out.meshes.push_back(toDrawMesh("parent vessel", parent, wall));
  const Vec3 a = kSacCentre + 0.0045 * Vec3(0.6, 0.0, 0.8), b = kSacCentre + 0.0045 * Vec3(-0.8, 0.0, 0.6);
  out.points.push_back({a, -0.0025 * Vec3(0.6, 0.0, 0.8), Colour(1.0f, 0.85f, 0.1f, 1.0f)});
  out.points.push_back({b, -0.0015 * Vec3(-0.8, 0.0, 0.6), Colour(1.0f, 0.85f, 0.1f, 1.0f)});
}

DrawData rodDrawData(const Model& model, const State& state) {
  DrawData out;
  fillDrawData(model, state, out);
  decorateRod(model, state, out);
  return out;
}

DrawData helixDrawData(const Model& model, const State& state) {
  DrawData out;
  fillDrawData(model, state, out);
  decorateHelix(model, state, out);
  return out;
}

}  // namespace coilsim::testing
