// The tube cache: each role's mesh is exactly the tubes appendTube builds
// (the reference), in order, and an unchanged tube is not built again.
#include "render/tube_cache.h"

#include <gtest/gtest.h>

#include "physics/rest_shape.h"

namespace coilsim::render {
namespace {

DrawTube tube(RodRole role, double z, double radius = 0.2e-3) {
  const RestCurve c = makeHelix(0.02, 30, 0.004, 0.0005, true);
  DrawTube t;
  t.role = role;
  t.radius = radius;
  for (const Vec3& p : c.points) t.centre.push_back(p + Vec3(0, 0, z));
  t.colours.assign(t.centre.size(), defaultColour(role));
  return t;
}

// appendTube of the role's tubes, one after the other.
TriangleMesh reference(const std::vector<DrawTube>& tubes, int role, const TubeOptions& o) {
  TriangleMesh m;
  for (const DrawTube& t : tubes)
    if (tubeRoleIndex(t.role) == role) appendTube(t, o, m);
  return m;
}

void expectSame(const TriangleMesh& a, const TriangleMesh& b) {
  ASSERT_EQ(a.vertices.size(), b.vertices.size());
  ASSERT_EQ(a.indices, b.indices);
  for (size_t i = 0; i < a.vertices.size(); ++i)
    for (int k = 0; k < 3; ++k) ASSERT_EQ(a.vertices[i].position[k], b.vertices[i].position[k]);
}

TEST(TubeCache, RolesHoldWhatAppendTubeBuildsAndUnchangedTubesAreKept) {
  const TubeOptions o{8, 2, 1.0, 1};
  std::vector<DrawTube> tubes{tube(RodRole::Coil, 0), tube(RodRole::Catheter, 0.01), tube(RodRole::Coil, 0.02)};
  TubeCache cache;
  cache.update(tubes, o, {});
  EXPECT_EQ(cache.built(), 3);
  for (int r = 0; r < kTubeRoles; ++r) expectSame(cache.mesh(r), reference(tubes, r, o));

  // Nothing moved: nothing built, no role to upload.
  cache.update(tubes, o, {});
  EXPECT_EQ(cache.built(), 0);
  for (int r = 0; r < kTubeRoles; ++r) EXPECT_FALSE(cache.changed(r)) << r;

  // One coil moves: only it is built again, only the coil role changes.
  tubes[2].centre[5].x() += 1e-4;
  cache.update(tubes, o, {});
  EXPECT_EQ(cache.built(), 1);
  EXPECT_TRUE(cache.changed(0));
  EXPECT_FALSE(cache.changed(1));
  for (int r = 0; r < kTubeRoles; ++r) expectSame(cache.mesh(r), reference(tubes, r, o));

  // Without reuse (the renderer as before the cache) every tube is built.
  cache.update(tubes, o, {}, false);
  EXPECT_EQ(cache.built(), 3);
  for (int r = 0; r < kTubeRoles; ++r) expectSame(cache.mesh(r), reference(tubes, r, o));
}

TEST(TubeCache, DetailFollowsTheSizeOnScreen) {
  const TubeOptions most{16, 3, 1.0, 3};
  const std::vector<DrawTube> tubes{tube(RodRole::Coil, 0)};
  double chord = 0;  // the nodes' mean distance
  for (size_t i = 1; i < tubes[0].centre.size(); ++i) chord += (tubes[0].centre[i] - tubes[0].centre[i - 1]).norm();
  chord /= double(tubes[0].centre.size() - 1);
  TubeCache cache;
  // 1e4 px/m: a 0.2 mm radius is 2 px, nodes about 6.6 px apart.
  const double perMetre = 1e4;
  cache.update(tubes, most, [&](const DrawTube&) { return perMetre; });
  const TubeOptions want = tubeDetail(most, perMetre * tubes[0].radius, perMetre * chord);
  EXPECT_LT(want.sides, most.sides);
  expectSame(cache.mesh(0), reference(tubes, 0, want));
  // Closer (ten times the pixels): more detail, built again.
  cache.update(tubes, most, [&](const DrawTube&) { return 10 * perMetre; });
  EXPECT_EQ(cache.built(), 1);
  expectSame(cache.mesh(0), reference(tubes, 0, tubeDetail(most, 10 * perMetre * tubes[0].radius, 10 * perMetre * chord)));
}

}  // namespace
}  // namespace coilsim::render
