// The wall's nearest-feature query (physics/contact/detect_nearest.h) with
// its shortcuts (the segment's cached walk of the tree, the last nearest
// triangle as a hint, the triangles' distance bound) against the plain query
// it must equal: the collision tree walked for the segment's box (checked
// against a brute-force scan in contact_wall_test.cpp) and every candidate
// measured by the exact segment-triangle distance, the first nearest in the
// tree's order kept. Compared bit for bit: triangle, distance and closest
// points, and the candidate list itself.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "physics/contact/detect.h"
#include "physics/contact/detect_nearest.h"
#include "physics/contact/geometry.h"
#include "physics/contact/obstacle_tree.h"
#include "physics/run.h"
#include "physics/integrator.h"
#include "support/coil_spec.h"
#include "support/refusal.h"
#include "support/meshes.h"
#include "support/rod_models.h"

namespace coilsim {
namespace {

// The reference: every triangle of the tree's walk measured.
struct Reference {
  std::vector<int> candidates;
  NearestTriangle nearest;
};

Reference plainQuery(const ObstacleTree& tree, const Vec3& a, const Vec3& b, double reach) {
  Reference out;
  std::vector<int> stack;
  const Vec3 grow = Vec3::Constant(reach);
  tree.overlapping(a.cwiseMin(b) - grow, a.cwiseMax(b) + grow, stack, out.candidates);
  const TriangleMesh& m = tree.mesh();
  for (size_t k = 0; k < out.candidates.size(); ++k) {
    const Eigen::Vector3i& f = m.triangles[out.candidates[k]];
    const SegmentTriangle hit = closestSegmentTriangle(a, b, m.vertices[f[0]], m.vertices[f[1]], m.vertices[f[2]]);
    if (out.nearest.triangle < 0 || hit.distance < out.nearest.hit.distance) out.nearest = {hit, out.candidates[k], k};
  }
  return out;
}

// A closed surface with concave and convex patches and sharp ridges, like a
// sac on its vessel: a 7 mm sphere (20,480 triangles) with radial bumps of
// 0.3 mm, and a plane cutting through it (where the two meet, ridges and
// slivers).
TriangleMesh bumpyPhantom() {
  TriangleMesh m = test::icosphere(3.5e-3, 5);
  for (Vec3& v : m.vertices) {
    const double theta = std::acos(std::clamp(v.z() / v.norm(), -1.0, 1.0)), phi = std::atan2(v.y(), v.x());
    v *= 1 + 0.09 * std::sin(3 * theta) * std::cos(4 * phi);
  }
  const TriangleMesh cut = test::plane(Vec3(0, 0, -2.0e-3), Vec3(0.2, 0.1, -1).normalized(), 5e-3, 40);
  const int offset = int(m.vertices.size());
  m.vertices.insert(m.vertices.end(), cut.vertices.begin(), cut.vertices.end());
  for (const Eigen::Vector3i& f : cut.triangles) m.triangles.push_back(f + Eigen::Vector3i::Constant(offset));
  return m;
}

void expectSame(const NearestTriangle& fast, const std::vector<int>& candidates, const Reference& ref,
                const std::string& where) {
  ASSERT_EQ(candidates, ref.candidates) << where;
  ASSERT_EQ(fast.triangle, ref.nearest.triangle) << where;
  if (ref.nearest.triangle < 0) return;
  ASSERT_EQ(fast.candidate, ref.nearest.candidate) << where;
  ASSERT_EQ(fast.hit.distance, ref.nearest.hit.distance) << where;
  ASSERT_EQ(fast.hit.s, ref.nearest.hit.s) << where;
  ASSERT_EQ(fast.hit.onTriangle, ref.nearest.hit.onTriangle) << where;
  ASSERT_EQ(fast.hit.onSegment, ref.nearest.hit.onSegment) << where;
}

// The bound by which a query skips a triangle is below the exact distance
// (closestSegmentTriangle, itself checked against dense sampling in
// contact_wall_test.cpp) for segments of every orientation near and across
// the surface, and tight under a segment lying flat over the wall.
TEST(WallNearestFeatureTest, DistanceBoundNeverExceedsTheExactDistance) {
  const ObstacleTree tree(std::make_shared<const TriangleMesh>(bumpyPhantom()));
  const TriangleMesh& m = tree.mesh();
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> unit(0, 1), sym(-1, 1);
  int tight = 0;
  for (int i = 0; i < 200000; ++i) {
    const int t = int(unit(rng) * m.triangles.size()) % int(m.triangles.size());
    const Eigen::Vector3i& f = m.triangles[t];
    const Vec3 c = (m.vertices[f[0]] + m.vertices[f[1]] + m.vertices[f[2]]) / 3;
    const bool flat = i % 2 == 0;
    // Half the segments lie parallel to the triangle's plane above it.
    const Vec3 n = tree.normal(t);
    Vec3 dir = Vec3(sym(rng), sym(rng), sym(rng)).normalized();
    if (flat) dir = (dir - dir.dot(n) * n).normalized();
    const Vec3 a = c + 0.6e-3 * Vec3(sym(rng), sym(rng), sym(rng)) + (flat ? Vec3(-0.4e-3 * unit(rng) * n) : Vec3(Vec3::Zero()));
    const Vec3 b = a + 0.8e-3 * unit(rng) * dir;
    const double exact = closestSegmentTriangle(a, b, m.vertices[f[0]], m.vertices[f[1]], m.vertices[f[2]]).distance;
    const double bound = tree.distanceBound(t, a, b);
    ASSERT_LE(bound, exact) << "sample " << i;
    tight += flat && exact > 0 && bound > 0.999 * exact;
  }
  // (Flat segments whose shadow meets the triangle: the bound is the height.)
  EXPECT_GT(tight, 1000);
}

// Segments near the surface (from a triangle, along its normal from 1 mm
// inside to 1 mm outside), each moved 30 times by up to 40 um, with a jump
// of 1 mm now and then: queried with their own cache and last nearest
// triangle, as the wall detection does, against the plain query.
TEST(WallNearestFeatureTest, CachedAndHintedQueriesEqualThePlainTreeQueryNearABumpyPhantom) {
  const ObstacleTree tree(std::make_shared<const TriangleMesh>(bumpyPhantom()));
  const TriangleMesh& m = tree.mesh();
  std::mt19937 rng(16);
  std::uniform_real_distribution<double> unit(0, 1), sym(-1, 1);
  ContactScratch scratch;
  int walks = 0, filtered = 0, found = 0;
  for (int seg = 0; seg < 300; ++seg) {
    const Eigen::Vector3i& f = m.triangles[size_t(unit(rng) * m.triangles.size()) % m.triangles.size()];
    const double u = unit(rng), v = unit(rng) * (1 - u);
    const Vec3 on = m.vertices[f[0]] + u * (m.vertices[f[1]] - m.vertices[f[0]]) + v * (m.vertices[f[2]] - m.vertices[f[0]]);
    const Vec3 n = (m.vertices[f[1]] - m.vertices[f[0]]).cross(m.vertices[f[2]] - m.vertices[f[0]]).normalized();
    Vec3 a = on + 1e-3 * sym(rng) * n;
    const Vec3 dir = Vec3(sym(rng), sym(rng), sym(rng)).normalized();
    Vec3 b = a + (0.1e-3 + 0.7e-3 * unit(rng)) * dir;
    TriangleCache cache;
    int hint = -1;
    for (int move = 0; move < 30; ++move) {
      const double jump = move % 11 == 10 ? 1e-3 : 40e-6;
      const Vec3 shift = jump * Vec3(sym(rng), sym(rng), sym(rng)) / std::sqrt(3.0);
      a += shift + 5e-6 * Vec3(sym(rng), sym(rng), sym(rng)), b += shift;
      const double reach = 0.05e-3 + 0.6e-3 * unit(rng);
      const Vec3 walked = cache.lo;
      const NearestTriangle fast = nearestWallFeature(tree, a, b, reach, scratch, reach, hint, &cache);
      (cache.lo == walked ? filtered : walks)++;
      expectSame(fast, scratch.candidates, plainQuery(tree, a, b, reach),
                 "segment " + std::to_string(seg) + ", move " + std::to_string(move));
      hint = fast.triangle;
      found += fast.triangle >= 0;
    }
  }
  // Both ways of getting the candidates, and many nearest features, were tried.
  EXPECT_GT(filtered, 3000);
  EXPECT_GT(walks, 1000);
  EXPECT_GT(found, 6000);
}

// A coil pushed into a 7 mm cavity with wall and self-contact: after every
// step each segment of the deployed coil is queried, with its own cache and
// hint carried from step to step, against the plain query.
TEST(WallNearestFeatureTest, CachedAndHintedQueriesEqualThePlainTreeQueryOnAMovingCoil) {
  ModelDef def;
  def.effects.push_back(EffectRegistry::global().use("wall_contact"));
  def.effects.push_back(EffectRegistry::global().use("self_contact"));
  def.damping.massCoeff = 20;
  def.timeStep = 1e-3;
  def.obstacles.push_back(test::obstacleOf(test::icosphere(3.5e-3, 4)));
  DeploymentDef d;
  d.coil = test::wireSpec(0.015, test::helixRest(6e-3, 0.4e-3), 7.5e9, test::kPlatinumPoisson, 21450, 0.15e-3);
  d.coilBeams = 30;
  d.tip.position = Vec3(0, 0, -2.5e-3);
  d.tip.direction = Vec3(0, 0, 1);
  d.tip.normal = Vec3(1, 0, 0);
  d.catheterDrawLength = 0.5e-3;
  def.device = d;
  const Model model = compileModel(def);
  State state = makeState(model);
  ASSERT_EQ(test::refusal(command(model, state, {DeviceCommand::Kind::Push, 0.01, d.coil.length})), "");
  const ObstacleTree& tree = *model.obstacleTrees[0];
  std::vector<TriangleCache> caches(d.coilBeams);
  std::vector<int> hints(d.coilBeams, -1);
  ContactScratch scratch;
  int near = 0;
  for (int i = 0; i < 1700; ++i) {
    ASSERT_TRUE(advance(model, state).ok()) << "step " << i;
    const RodState& r = state.rods[0];
    for (int e = 0; e + 1 < r.activeNodes && e < d.coilBeams; ++e) {
      const Vec3 &a = r.x[e], &b = r.x[e + 1];
      const double reach = (1 + kWallSkin) * r.nodes[e].radius + 0.05e-3 + 1e-3 * std::max(r.v[e].norm(), r.v[e + 1].norm());
      const NearestTriangle fast = nearestWallFeature(tree, a, b, reach, scratch, reach, hints[e], &caches[e]);
      expectSame(fast, scratch.candidates, plainQuery(tree, a, b, reach),
                 "step " + std::to_string(i) + ", segment " + std::to_string(e));
      hints[e] = fast.triangle;
      near += fast.triangle >= 0 && fast.hit.distance <= reach;
    }
  }
  EXPECT_GT(near, 5000) << "the coil hardly came near the wall: the test would prove little";
}

}  // namespace
}  // namespace coilsim
