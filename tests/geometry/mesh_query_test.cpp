// Inside tests, closest points and signed distances against an analytic
// sphere, a cube and brute force.
#include "geometry/mesh_query.h"

#include <gtest/gtest.h>

#include <random>

#include "geometry/shapes.h"
#include "support/tolerance.h"

namespace coilsim::geometry {
namespace {

// Closest point by visiting every triangle: the reference for the hierarchy.
double bruteForceDistance(const TriangleMesh& m, const Vec3& p) {
  double best = 1e300;
  for (const auto& t : m.triangles) {
    // Sample-free exact distance: reuse the query on a one-triangle mesh.
    TriangleMesh one;
    one.vertices = {m.vertices[t[0]], m.vertices[t[1]], m.vertices[t[2]]};
    one.triangles = {Eigen::Vector3i(0, 1, 2)};
    best = std::min(best, MeshQuery(one).closest(p).distance);
  }
  return best;
}

TEST(MeshQuery, CubeInsideOutsideIncludingGrazingRays) {
  const MeshQuery q(test::unitCube());
  // Points level with the cube's edges and vertices: axis-aligned rays from
  // them would graze, the query must still answer right.
  for (double x : {-0.5, 0.0 - 1e-3, 0.5, 1.0 + 1e-3, 1.5})
    for (double y : {-0.5, 0.5, 1.5})
      for (double z : {0.5, 1.5}) {
        const Vec3 p(x, y, z);
        const bool expected = x > 0 && x < 1 && y > 0 && y < 1 && z > 0 && z < 1;
        EXPECT_EQ(q.inside(p), expected) << p.transpose();
      }
  EXPECT_TRUE(q.inside(Vec3(0.5, 0.5, 0.5)));
  EXPECT_NEAR(q.signedDistance(Vec3(0.5, 0.5, 0.2)), -0.2, 1e-15);
  EXPECT_NEAR(q.signedDistance(Vec3(2, 0.5, 0.5)), 1.0, 1e-15);
  EXPECT_NEAR(q.signedDistance(Vec3(2, 2, 2)), std::sqrt(3.0), 1e-15);  // nearest is the corner
}

TEST(MeshQuery, PolygonisedSphereAgreesWithTheAnalyticSphere) {
  const double r = 3.5, h = 0.1;
  const TriangleMesh ball = test::sphereMesh(r, h);
  const MeshQuery q(ball);
  std::printf("[ measured ] sphere mesh: %zu triangles\n", ball.triangles.size());
  // The polyhedron lies within about h^2 / r of the sphere: outside that shell
  // the answer is the analytic one.
  const double shell = h * h / r;
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.5 * r, 1.5 * r);
  int checked = 0, wrong = 0;
  double worst = 0;
  for (int i = 0; i < 4000; ++i) {
    const Vec3 p(u(rng), u(rng), u(rng));
    const double exact = p.norm() - r;
    if (std::abs(exact) < shell) continue;
    ++checked;
    wrong += q.inside(p) != (exact < 0);
    worst = std::max(worst, std::abs(q.signedDistance(p) - exact));
  }
  EXPECT_GT(checked, 3900);
  EXPECT_EQ(wrong, 0) << "of " << checked << " points";
  EXPECT_TRUE(test::small("signed distance - (|p| - r)", worst, {shell, "polyhedron within h^2/r of the sphere"}));
}

TEST(MeshQuery, HierarchyFindsTheSameClosestPointAsBruteForce) {
  const TriangleMesh ball = test::sphereMesh(2.0, 0.4, Vec3(0.3, 0.1, -0.2));
  const MeshQuery q(ball);
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-4, 4);
  for (int i = 0; i < 50; ++i) {
    const Vec3 p(u(rng), u(rng), u(rng));
    EXPECT_NEAR(q.closest(p).distance, bruteForceDistance(ball, p), 1e-12) << p.transpose();
  }
}

TEST(MeshQuery, LargeMeshInsideTestMatchesTheSphere) {
  // About 50,000 triangles, the size of the contact benchmark's aneurysm.
  const double r = 5.0;
  const TriangleMesh ball = test::sphereMesh(r, 0.09);
  EXPECT_GT(ball.triangles.size(), 40'000u);
  const MeshQuery q(ball);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-6, 6);
  int wrong = 0;
  for (int i = 0; i < 20'000; ++i) {
    const Vec3 p(u(rng), u(rng), u(rng));
    if (std::abs(p.norm() - r) < 0.01) continue;
    wrong += q.inside(p) != (p.norm() < r);
  }
  EXPECT_EQ(wrong, 0);
}

// The first triangle along a ray: from inside the unit cube along each
// axis, the face the ray leaves by (its normal is the axis); from outside,
// the face it enters by; a ray away from the cube meets none.
TEST(MeshQuery, FirstHitIsTheNearestFaceAlongTheRay) {
  const TriangleMesh cube = test::unitCube();
  const MeshQuery q(cube);
  const auto faceNormal = [&](int t) {
    const Eigen::Vector3i& f = cube.triangles[size_t(t)];
    return Vec3((cube.vertices[f[1]] - cube.vertices[f[0]]).cross(cube.vertices[f[2]] - cube.vertices[f[0]]).normalized());
  };
  const Vec3 inside(0.31, 0.42, 0.27);
  for (const Vec3& d : {Vec3(1, 0, 0), Vec3(0, -1, 0), Vec3(0, 0, 1), Vec3(0, 0, -1)}) {
    const int t = q.firstHit(inside, d);
    ASSERT_GE(t, 0);
    EXPECT_NEAR(faceNormal(t).dot(d), 1.0, 1e-12);  // leaves through the face facing along the ray
  }
  const int entered = q.firstHit(Vec3(-2, 0.31, 0.42), Vec3::UnitX());
  ASSERT_GE(entered, 0);
  EXPECT_NEAR(faceNormal(entered).dot(Vec3::UnitX()), -1.0, 1e-12);  // the x = 0 face, not x = 1
  EXPECT_EQ(q.firstHit(Vec3(2, 0.5, 0.5), Vec3::UnitX()), -1);
}

TEST(MeshQuery, EmptyMeshHasNothingInside) {
  const MeshQuery q(TriangleMesh{});
  EXPECT_FALSE(q.inside(Vec3::Zero()));
  EXPECT_EQ(q.closest(Vec3::Zero()).triangle, -1);
}

}  // namespace
}  // namespace coilsim::geometry
