// Dense contact that stays right (issue 16): a 7 mm sac packed with a few
// hundred millimetres of coil (planning/dense_sac.h: nested spherical
// spirals, each turn within the contact margin of the next, the outer shell
// of the wall), with planning's contacts, stepped under gravity, buoyancy
// and drag after a jolt. References computed here, not by the contact code:
// the distance between every two segment centre lines (closed form,
// Ericson's Real-Time Collision Detection 5.1.9) against the wire diameter,
// and every node's distance to the icosphere's face planes (for a point
// inside a convex polyhedron its distance to the surface, and a segment's
// distance to a plane is least at an end) against the wire radius. With the
// coil-coil and wall contacts switched off the same checks fail within a few
// steps (the control that shows they can).
#include "planning/dense_sac.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "physics/integrator.h"
#include "physics/run.h"
#include "planning/sac_geometry.h"
#include "support/segment_distance.h"

namespace coilsim::planning {
namespace {

constexpr double kCoilLength = 0.3;  // m of coil in the sac: 8.5 % packing, 600 segments

using test::segmentDistance;  // tests/support/segment_distance.h

struct Depths {
  double pair = 0;  // deepest overlap of two wires, m (>= 0)
  double wall = 0;  // deepest the wire reaches past the wall's faces, m (>= 0)
};

// Every pair of segments of all rods but neighbours along one rod, and
// every node against every face plane of the sac.
Depths measure(const Model& model, const State& s, const TriangleMesh& sac) {
  struct Seg {
    Vec3 a, b;
    int rod, index;
  };
  std::vector<Seg> segs;
  double radius = 0;
  for (size_t r = 0; r < s.rods.size(); ++r) {
    radius = model.rods[r].section.radius;
    for (int i = 0; i + 1 < s.rods[r].activeNodes; ++i) segs.push_back({s.rods[r].x[i], s.rods[r].x[i + 1], int(r), i});
  }
  Depths d;
  for (size_t i = 0; i < segs.size(); ++i)
    for (size_t j = i + 1; j < segs.size(); ++j) {
      const Seg &p = segs[i], &q = segs[j];
      if (p.rod == q.rod && std::abs(p.index - q.index) < 2) continue;
      // Segments whose midpoints are farther apart than a segment plus a diameter cannot touch.
      const double reach = 0.5 * ((p.b - p.a).norm() + (q.b - q.a).norm()) + 2 * radius;
      if ((0.5 * (p.a + p.b - q.a - q.b)).squaredNorm() > reach * reach) continue;
      d.pair = std::max(d.pair, 2 * radius - segmentDistance(p.a, p.b, q.a, q.b));
    }
  for (const RodState& rod : s.rods)
    for (int i = 0; i < rod.activeNodes; ++i) {
      double inside = INFINITY;
      for (const auto& t : sac.triangles) {
        const Vec3 &a = sac.vertices[t[0]], &b = sac.vertices[t[1]], &c = sac.vertices[t[2]];
        const Vec3 inward = -(b - a).cross(c - a).normalized() * ((b - a).cross(c - a).dot(a) > 0 ? 1 : -1);
        inside = std::min(inside, (rod.x[i] - a).dot(inward));
      }
      d.wall = std::max(d.wall, radius - inside);
    }
  return d;
}

// The packing, every node given a random velocity of up to `jolt` m/s (a
// coil pushed in shakes the packing it meets), stepped `steps` times; the
// deepest overlaps over the steps (checked every `every` steps and at the end).
struct Outcome {
  Depths deepest;
  long refused = 0, substepped = 0;
  double radius = 0;
};

Outcome runPacking(bool contacts, int steps, int every, double jolt) {
  ModelDef def = denseSacModel(kCoilLength);
  for (EffectUse& u : def.effects)
    if (u.name() == "wall_contact" || u.name() == "self_contact" || u.name() == "rod_contact") u.enabled = contacts;
  const Model model = compileModel(def);
  State s = makeState(model);
  std::mt19937 random(16);
  std::uniform_real_distribution<double> uniform(-1, 1);
  for (RodState& rod : s.rods)
    for (Vec3& v : rod.v) v = jolt / std::sqrt(3.0) * Vec3(uniform(random), uniform(random), uniform(random));
  const TriangleMesh sac = makeIcosphere(Vec3::Zero(), DenseSacSpec{}.sacRadius, DenseSacSpec{}.subdivisions);
  Outcome o;
  o.radius = model.rods.front().section.radius;
  for (int k = 1; k <= steps; ++k) {
    if (!step(model, s).ok()) ++o.refused;
    if (k % every == 0 || k == steps) {
      const Depths d = measure(model, s, sac);
      o.deepest.pair = std::max(o.deepest.pair, d.pair);
      o.deepest.wall = std::max(o.deepest.wall, d.wall);
    }
  }
  o.substepped = s.substepped;
  return o;
}

TEST(DenseSac, PackedSacKeepsItsCoilsApartAndInsideTheWall) {
  const Outcome o = runPacking(true, 200, 5, 0.02);
  EXPECT_EQ(o.refused, 0) << "steps refused (" << o.substepped << " taken in substeps)";
  EXPECT_LE(o.deepest.pair, 0.1 * 2 * o.radius) << "deepest coil-coil overlap " << o.deepest.pair * 1e6 << " um";
  // The skin (5 % of r outside the wire) may be pressed in; the wire itself may not pass the wall.
  EXPECT_LE(o.deepest.wall, 0.0) << "deepest wall penetration of the wire " << o.deepest.wall * 1e6 << " um";
  std::printf("dense sac, 300 mm: coil-coil overlap %.2f um (%.2f %% of d), wire past the wall %.2f um, %ld of 200 "
              "steps in substeps\n",
              o.deepest.pair * 1e6, 100 * o.deepest.pair / (2 * o.radius), o.deepest.wall * 1e6, o.substepped);
}

TEST(DenseSac, WithoutContactsTheSameChecksFail) {
  const Outcome o = runPacking(false, 20, 5, 0.02);
  EXPECT_GT(o.deepest.pair, 0.1 * 2 * o.radius);
  EXPECT_GT(o.deepest.wall, 0.0);
}

}  // namespace
}  // namespace coilsim::planning
