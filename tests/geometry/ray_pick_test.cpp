// Ray crossings against surfaces whose crossings are known in closed form:
// the faces of a cube, a polygonised sphere (chord error bounded by the
// spacing), an edge shared by two triangles counted once, a miss.
#include "geometry/ray_pick.h"

#include <gtest/gtest.h>

#include "geometry/shapes.h"

namespace coilsim::geometry {
namespace {

TEST(RayPick, ObliqueRayThroughACubeCrossesTheFacesWhereTheLineDoes) {
  const TriangleMesh cube = test::unitCube();
  // x = -1 + s, y = 0.3 + 0.1 s, z = 0.4 + 0.05 s: in at x = 0 (s = 1), out at x = 1 (s = 2).
  const Vec3 o(-1, 0.3, 0.4), d(1, 0.1, 0.05);
  const std::vector<double> hits = rayHits(cube, o, d);
  ASSERT_EQ(hits.size(), 2u);
  EXPECT_NEAR(hits[0], 1 * d.norm(), 1e-12);
  EXPECT_NEAR(hits[1], 2 * d.norm(), 1e-12);
  const auto first = firstHit(cube, o, d);
  ASSERT_TRUE(first);
  EXPECT_NEAR((*first - Vec3(0, 0.4, 0.45)).norm(), 0, 1e-12);
  const auto middle = firstLumenMiddle(cube, o, d);
  ASSERT_TRUE(middle);
  EXPECT_NEAR((*middle - Vec3(0.5, 0.45, 0.475)).norm(), 0, 1e-12);
}

TEST(RayPick, ARayAlongTheDiagonalEdgeOfTwoTrianglesCrossesOnce) {
  // The quads of z = 0 and z = 1 are split along x = y: the ray meets both halves there.
  const std::vector<double> hits = rayHits(test::unitCube(), Vec3(0.3, 0.3, -1), Vec3(0, 0, 1));
  ASSERT_EQ(hits.size(), 2u);
  EXPECT_NEAR(hits[0], 1.0, 1e-12);
  EXPECT_NEAR(hits[1], 2.0, 1e-12);
}

TEST(RayPick, ThroughASphereTheLumenMiddleIsTheChordMidpoint) {
  const double r = 3.0, h = 0.25;
  const Vec3 c(1, -2, 0.5);
  const TriangleMesh ball = test::sphereMesh(r, h, c);
  // A line at distance b from the centre: the chord runs +-sqrt(r^2 - b^2) about the foot of the perpendicular.
  const double b = 1.2;
  const Vec3 d = Vec3(1, 1, 0).normalized(), across = Vec3(0, 0, 1);
  const Vec3 foot = c + b * across, o = foot - 10 * d;
  const double half = std::sqrt(r * r - b * b);
  const std::vector<double> hits = rayHits(ball, o, d);
  ASSERT_EQ(hits.size(), 2u);
  // The polygon lies within the sphere by about h^2 / (2 r); along a chord at angle this grows to h^2 r / (2 r half).
  const double tol = h * h / half;
  EXPECT_NEAR(hits[0], 10 - half, tol);
  EXPECT_NEAR(hits[1], 10 + half, tol);
  const auto middle = firstLumenMiddle(ball, o, d);
  ASSERT_TRUE(middle);
  EXPECT_NEAR((*middle - foot).norm(), 0, tol);
}

TEST(RayPick, MissesAndBadDirectionsGiveNothing) {
  const TriangleMesh cube = test::unitCube();
  EXPECT_TRUE(rayHits(cube, Vec3(2, 2, 2), Vec3(1, 0, 0)).empty());
  EXPECT_TRUE(rayHits(cube, Vec3(-1, 0.5, 0.5), Vec3::Zero()).empty());
  EXPECT_TRUE(rayHits(cube, Vec3(-1, 0.5, 0.5), Vec3(NAN, 0, 0)).empty());
  EXPECT_FALSE(firstHit(cube, Vec3(0.5, 0.5, 3), Vec3(0, 0, 1)));  // pointing away
  // From inside the cube: one crossing, no lumen stretch seen from outside.
  EXPECT_EQ(rayHits(cube, Vec3(0.5, 0.4, 0.3), Vec3(1, 0, 0)).size(), 1u);
  EXPECT_FALSE(firstLumenMiddle(cube, Vec3(0.5, 0.4, 0.3), Vec3(1, 0, 0)));
}

}  // namespace
}  // namespace coilsim::geometry
