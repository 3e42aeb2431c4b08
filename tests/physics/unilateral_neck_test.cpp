// The wall held by unilateral constraints (src/physics/unilateral.cpp)
// against a reference that does not come from them: the penalty wall
// refined in time until its answer no longer depends on its stiffness and
// step (omega h below about 50, omega = sqrt(k / (rho A)) the wire's
// angular frequency on the penalty), in a sac whose neck opens onto a
// parent vessel. docs/contact.md ("Under the constraint the push ends with
// half the coil back in the parent vessel"): in the default scene's push the
// constraint at 1 ms and every penalty with omega h <= 54 put the same
// length of coil through the neck; every penalty with omega h >= 108 kept
// the coil in the sac.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <utility>
#include <vector>

#include "physics/run.h"
#include "support/coil_spec.h"
#include "support/meshes.h"
#include "support/refusal.h"

namespace coilsim {
namespace {

// A sidewall aneurysm like the default scene's phantom, without its
// fillet: a sphere of radius R standing on the roof z = z0 of a box-shaped
// parent vessel along x (half width w, height 2 w, half length L), the neck
// the circle of radius a where the sphere meets the roof. One closed
// surface wound counter-clockwise seen from outside (the lumen behind the
// normals). The neck is wider than the phantom's 3.5 mm: through that one
// the coil's tip meets the far rim within 0.1 mm of the neck plane, where
// the phantom's fillet, absent here, decides its way (here it went back
// into the sac; 1.5 mm through the neck after 25 mm under both laws).
struct NeckGeometry {
  double sacRadius = 3.5e-3, neckRadius = 2.25e-3, roof = 2e-3;
  double halfWidth = 2.55e-3, halfLength = 12e-3;
  int around = 64;  // vertices on the neck circle (a multiple of 8: the square's corners are rays)
  int rings = 24;   // latitude rings of the sac above the neck
  Vec3 sacCentre() const {
    return Vec3(0, 0, roof + std::sqrt(sacRadius * sacRadius - neckRadius * neckRadius));
  }
};

class MeshBuilder {
 public:
  int vertex(const Vec3& p) {
    mesh.vertices.push_back(p);
    return int(mesh.vertices.size()) - 1;
  }
  // Adds (a, b, c) wound so that its normal points along `outward`.
  void triangle(int a, int b, int c, const Vec3& outward) {
    const Vec3 n = (mesh.vertices[b] - mesh.vertices[a]).cross(mesh.vertices[c] - mesh.vertices[a]);
    if (n.dot(outward) < 0) std::swap(b, c);
    mesh.triangles.emplace_back(a, b, c);
  }
  // A convex planar polygon (in order around it) as a fan from its first vertex.
  void fan(const std::vector<int>& polygon, const Vec3& outward) {
    for (size_t k = 1; k + 1 < polygon.size(); ++k) triangle(polygon[0], polygon[k], polygon[k + 1], outward);
  }
  TriangleMesh mesh;
};

TriangleMesh neckPhantom(const NeckGeometry& g) {
  MeshBuilder b;
  const Vec3 c = g.sacCentre();
  const double w = g.halfWidth, L = g.halfLength, z0 = g.roof, zb = g.roof - 2 * w;
  const int n = g.around;
  // The sac: a pole and rings down to the neck circle (polar angle from the top).
  const double neckPolar = std::acos((z0 - c.z()) / g.sacRadius);
  const int pole = b.vertex(c + Vec3(0, 0, g.sacRadius));
  std::vector<std::vector<int>> ring(g.rings);
  for (int r = 0; r < g.rings; ++r) {
    const double polar = neckPolar * (r + 1) / g.rings;
    for (int j = 0; j < n; ++j) {
      const double phi = 2 * M_PI * j / n;
      Vec3 p = c + g.sacRadius * Vec3(std::sin(polar) * std::cos(phi), std::sin(polar) * std::sin(phi), std::cos(polar));
      if (r + 1 == g.rings) p.z() = z0;  // exactly on the roof
      ring[r].push_back(b.vertex(p));
    }
  }
  const auto radial = [&](int v) { return Vec3(b.mesh.vertices[v] - c); };
  for (int j = 0; j < n; ++j) b.triangle(pole, ring[0][j], ring[0][(j + 1) % n], radial(ring[0][j]));
  for (int r = 0; r + 1 < g.rings; ++r)
    for (int j = 0; j < n; ++j) {
      const int a0 = ring[r][j], a1 = ring[r][(j + 1) % n], b0 = ring[r + 1][j], b1 = ring[r + 1][(j + 1) % n];
      b.triangle(a0, b0, b1, radial(a0));
      b.triangle(a0, b1, a1, radial(a0));
    }
  // The roof between the neck circle and the square |x|, |y| <= w: each
  // circle vertex joined to where its ray meets the square.
  const std::vector<int>& neck = ring[g.rings - 1];
  std::vector<int> square(n);
  for (int j = 0; j < n; ++j) {
    const double phi = 2 * M_PI * j / n, s = std::max(std::abs(std::cos(phi)), std::abs(std::sin(phi)));
    square[j] = b.vertex(Vec3(w * std::cos(phi) / s, w * std::sin(phi) / s, z0));
  }
  const Vec3 up = Vec3::UnitZ();
  for (int j = 0; j < n; ++j) {
    const int k = (j + 1) % n;
    b.triangle(neck[j], square[j], square[k], up);
    b.triangle(neck[j], square[k], neck[k], up);
  }
  // The roof beyond the square, the vessel's sides, ends and floor.
  const int farPlusTop[2] = {b.vertex(Vec3(L, -w, z0)), b.vertex(Vec3(L, w, z0))};
  const int farMinusTop[2] = {b.vertex(Vec3(-L, -w, z0)), b.vertex(Vec3(-L, w, z0))};
  const int farPlusBottom[2] = {b.vertex(Vec3(L, -w, zb)), b.vertex(Vec3(L, w, zb))};
  const int farMinusBottom[2] = {b.vertex(Vec3(-L, -w, zb)), b.vertex(Vec3(-L, w, zb))};
  // The square's vertices on each of its sides, in order along the side.
  const auto onSide = [&](int axis, double value, int sortAxis) {
    std::vector<int> out;
    for (int v : square)
      if (std::abs(b.mesh.vertices[v][axis] - value) < 1e-12) out.push_back(v);
    std::sort(out.begin(), out.end(), [&](int p, int q) { return b.mesh.vertices[p][sortAxis] < b.mesh.vertices[q][sortAxis]; });
    return out;
  };
  std::vector<int> plusX = onSide(0, w, 1), minusX = onSide(0, -w, 1), plusY = onSide(1, w, 0), minusY = onSide(1, -w, 0);
  {  // roof, x > w: the square's side and the far corners
    std::vector<int> poly = {farPlusTop[0]};
    poly.insert(poly.end(), plusX.begin(), plusX.end());
    poly.push_back(farPlusTop[1]);
    b.fan(poly, up);
  }
  {  // roof, x < -w
    std::vector<int> poly = {farMinusTop[0]};
    poly.insert(poly.end(), minusX.begin(), minusX.end());
    poly.push_back(farMinusTop[1]);
    b.fan(poly, up);
  }
  for (int side = 0; side < 2; ++side) {  // y = -w, y = +w: top edge through the square's side
    const std::vector<int>& top = side ? plusY : minusY;
    std::vector<int> poly = {farMinusBottom[side], farMinusTop[side]};
    poly.insert(poly.end(), top.begin(), top.end());
    poly.push_back(farPlusTop[side]);
    poly.push_back(farPlusBottom[side]);
    b.fan(poly, Vec3(0, side ? 1 : -1, 0));
  }
  b.fan({farPlusBottom[0], farPlusTop[0], farPlusTop[1], farPlusBottom[1]}, Vec3::UnitX());
  b.fan({farMinusBottom[0], farMinusTop[0], farMinusTop[1], farMinusBottom[1]}, -Vec3::UnitX());
  b.fan({farMinusBottom[0], farPlusBottom[0], farPlusBottom[1], farMinusBottom[1]}, -Vec3::UnitZ());
  b.mesh.name = "neck phantom";
  return b.mesh;
}

// Volume enclosed by a closed, outward-wound mesh (divergence theorem).
double enclosedVolume(const TriangleMesh& m) {
  double v = 0;
  for (const auto& t : m.triangles)
    v += m.vertices[t[0]].dot(m.vertices[t[1]].cross(m.vertices[t[2]])) / 6;
  return v;
}

// The default scene's coil, catheter, medium and contacts
// (scenes/default.json) in the phantom above, at time step h; the wall a
// penalty of `stiffness` N/m^2 or (rigid) constraints.
Model neckModel(const NeckGeometry& g, double h, bool rigid, double stiffness = 200e6) {
  ModelDef def;
  def.gravity = Vec3(0, -9.81, 0);
  def.timeStep = h;
  def.newtonIterations = 3;
  def.damping = {1.0, 0.0};
  def.effects.push_back(EffectRegistry::global().use("gravity"));
  def.effects.push_back(EffectRegistry::global().use("buoyancy"));
  def.effects.back().set("medium_density_g_cm3", 1060);
  def.effects.push_back(EffectRegistry::global().use("drag"));
  def.effects.back().set("viscosity_pa_s", 0.0035);
  def.effects.push_back(EffectRegistry::global().use("wall_contact"));
  def.effects.back().set("rigid", rigid ? 1.0 : 0.0);
  def.effects.back().set("stiffness_n_mm2", stiffness);
  def.effects.push_back(EffectRegistry::global().use("self_contact"));
  def.obstacles.push_back(test::obstacleOf(neckPhantom(g)));
  DeploymentDef d;
  d.coil = test::wireSpec(0.03, test::helixRest(7e-3, 0.3048e-3), 168e9, 0.38, 21450, 0);
  d.coil.explicitSection = {3.1837e-8, 1.74887e-20, 1.74887e-20, 5.74399e-20, 0, 0.1524e-3};
  d.coilBeams = 60;  // 0.5 mm, as the scenes
  d.tip.position = Vec3(0, 0, 3e-3);
  d.tip.direction = Vec3(-0.5, 0, std::sqrt(0.75));
  d.tip.normal = Vec3(std::sqrt(0.75), 0, 0.5);
  d.catheterDrawLength = 6e-3;
  d.initialDeployed = 1e-3;
  d.maxPushSpeed = 0.02;
  def.device = d;
  return compileModel(def);
}

struct PushEnd {
  double belowNeck = 0;  // m of coil centre line below the neck plane
  double load = 0;       // largest sustained wall load, N
};

// Pushes `pushed` m at 10 mm/s, as timelines/push-default.json.
PushEnd pushThroughNeck(const NeckGeometry& g, const Model& model, double pushed) {
  State state = makeState(model);
  EXPECT_EQ(test::refusal(command(model, state, {DeviceCommand::Kind::Push, 0.01, pushed})), "");
  const long steps = std::lround(pushed / 0.01 / model.timeStep);
  for (long s = 0; s < steps; ++s) {
    const StepReport r = advance(model, state);
    EXPECT_TRUE(r.ok()) << "step " << s << ": " << (r.ok() ? "" : describe(*r.failure));
    if (!r.ok()) break;
  }
  PushEnd end;
  const RodState& coil = state.rods[model.device->chainRod];
  for (int i = 0; i + 1 < coil.activeNodes; ++i) {
    const double za = coil.x[i].z() - g.roof, zb = coil.x[i + 1].z() - g.roof, length = (coil.x[i + 1] - coil.x[i]).norm();
    // The part of the segment below the plane (linear along it).
    if (za < 0 && zb < 0) end.belowNeck += length;
    else if (za < 0 || zb < 0) end.belowNeck += length * std::min(za, zb) / (std::min(za, zb) - std::max(za, zb));
  }
  end.load = state.stats.wallLoad.max;
  return end;
}

TEST(UnilateralNeck, ThePhantomIsClosedAndHoldsTheSacAndTheVessel) {
  // The fixture's own check: every edge is used once each way (closed and
  // consistently wound, no T-junction), and the volume it encloses is the
  // box's plus the sphere's cap above the roof (the polygonal sac a little less).
  const NeckGeometry g;
  const TriangleMesh mesh = neckPhantom(g);
  std::map<std::pair<int, int>, int> edges;
  for (const auto& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) ++edges[{t[k], t[(k + 1) % 3]}];
  for (const auto& [edge, count] : edges) {
    EXPECT_EQ(count, 1) << "edge " << edge.first << "-" << edge.second;
    const auto back = edges.find({edge.second, edge.first});
    EXPECT_TRUE(back != edges.end() && back->second == 1) << "edge " << edge.first << "-" << edge.second << " has no twin";
  }
  const double h = g.sacCentre().z() + g.sacRadius - g.roof;
  const double cap = M_PI * h * h * (3 * g.sacRadius - h) / 3;
  const double box = 2 * g.halfLength * 2 * g.halfWidth * 2 * g.halfWidth;
  const double v = enclosedVolume(mesh);
  EXPECT_LT(v, box + cap);
  EXPECT_GT(v, box + 0.98 * cap);
}

TEST(UnilateralNeck, ThePushLeavesAsMuchCoilThroughTheNeckAsThePenaltyResolvedInTime) {
  // The default scene's coil pushed 25 mm at 10 mm/s. The constraint at
  // the scenes' 1 ms step against the penalty resolved in time at two
  // resolutions, omega h = sqrt(k / (rho A)) h = 27 and 14 (k = 8 and
  // 2 N/mm^2, h = 0.25 ms): the wire's forces here (about a millinewton)
  // press it a micrometre or so into either. (The registered penalty,
  // 200 N/mm^2 at 1 ms, omega h = 541, kept all of it in the sac: 0.00 mm,
  // as in the default scene's push; docs/contact.md.)
  const NeckGeometry g;
  const double pushed = 0.025;
  const PushEnd constraint = pushThroughNeck(g, neckModel(g, 1e-3, true), pushed);
  const PushEnd stiffer = pushThroughNeck(g, neckModel(g, 0.25e-3, false, 8e6), pushed);
  const PushEnd softer = pushThroughNeck(g, neckModel(g, 0.25e-3, false, 2e6), pushed);
  std::printf("[ measured ] below the neck: constraint %.2f mm, penalty at omega h 27, 14: %.2f, %.2f mm; largest sustained "
              "load %.3f, %.3f, %.3f mN\n",
              constraint.belowNeck * 1e3, stiffer.belowNeck * 1e3, softer.belowNeck * 1e3, constraint.load * 1e3,
              stiffer.load * 1e3, softer.load * 1e3);
  // The reference has converged: its two resolutions agree. (Neck radius
  // 2.2-2.3 mm and vessel half width 2.55-2.7 mm moved each figure by up to
  // 0.35 mm and each load by up to 10 %.)
  const double through = 0.5 * (stiffer.belowNeck + softer.belowNeck), load = 0.5 * (stiffer.load + softer.load);
  EXPECT_LT(std::abs(stiffer.belowNeck - softer.belowNeck), 0.75e-3);
  EXPECT_GT(through, 5e-3) << "the scene must send coil through the neck, or the comparison says nothing of it";
  // The constraint puts as much coil through the neck, and reads the same load.
  EXPECT_NEAR(constraint.belowNeck, through, 0.75e-3);
  EXPECT_NEAR(constraint.load, load, 0.2 * load);
}

}  // namespace
}  // namespace coilsim
