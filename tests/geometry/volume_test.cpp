// Enclosed volumes against the ball and spherical-cap formulas, and exact
// polyhedral cuts of a cube.
#include "geometry/volume.h"

#include <gtest/gtest.h>

#include <cmath>

#include "geometry/mesh_report.h"
#include "geometry/shapes.h"
#include "support/tolerance.h"

namespace coilsim::geometry {
namespace {

using test::capVolume;
using test::nearAbs;
using test::nearRel;
using test::sphereMesh;

TEST(Volume, CubeCutByPlanesIsExact) {
  const TriangleMesh cube = test::unitCube();
  const auto exact = test::roundoff(1, 200, "clipped triple products");
  EXPECT_TRUE(nearAbs("above z = 0.3", volumeAbovePlane(cube, {Vec3(0, 0, 0.3), Vec3::UnitZ()}), 0.7, exact));
  EXPECT_TRUE(nearAbs("below z = 0.3", volumeAbovePlane(cube, {Vec3(0, 0, 0.3), -Vec3::UnitZ()}), 0.3, exact));
  // A plane through the centre halves the cube by symmetry, whatever its normal.
  const Vec3 n = Vec3(0.3, -0.7, 0.5).normalized();
  EXPECT_TRUE(nearAbs("oblique half", volumeAbovePlane(cube, {Vec3::Constant(0.5), n}), 0.5, exact));
  // A corner cut off by x + y + z = 0.5 is the tetrahedron 0.5^3 / 6.
  const Vec3 diag = Vec3::Ones().normalized();
  EXPECT_TRUE(nearAbs("corner", volumeAbovePlane(cube, {Vec3(0.5, 0, 0), -diag}), 0.125 / 6, exact));
  EXPECT_TRUE(nearAbs("plane outside: everything", volumeAbovePlane(cube, {Vec3(0, 0, -1), Vec3::UnitZ()}), 1.0, exact));
  EXPECT_TRUE(nearAbs("plane outside: nothing", volumeAbovePlane(cube, {Vec3(0, 0, 2), Vec3::UnitZ()}), 0.0, exact));
  EXPECT_TRUE(nearAbs("section of the cube", sectionArea(cube, {Vec3(0, 0, 0.3), Vec3::UnitZ()}), 1.0, exact));
  EXPECT_TRUE(nearAbs("oblique section through the corner", sectionArea(cube, {Vec3(0.5, 0, 0), -diag}),
                      std::sqrt(3.0) / 8, exact));  // equilateral triangle of side 0.5 sqrt 2
}

TEST(Volume, PolygonisedBallConvergesToTheBallVolume) {
  // Linear interpolation of the distance puts vertices on the sphere to O(h^2);
  // the inscribed polyhedron's volume error is O(h^2) too.
  const double r = 3.5, exact = 4.0 / 3.0 * M_PI * r * r * r;
  double previous = 0;
  for (double h : {0.4, 0.2, 0.1}) {
    const TriangleMesh ball = sphereMesh(r, h);
    ASSERT_TRUE(analyseMesh(ball).usable());
    const double err = test::relativeError(enclosedVolume(ball), exact);
    std::printf("[ measured ] ball r = %.1f, h = %.2f: %zu triangles, volume error %.3e\n", r, h,
                ball.triangles.size(), err);
    EXPECT_TRUE(nearRel("ball volume, h = " + std::to_string(h), enclosedVolume(ball), exact,
                        {2.0 * (h / r) * (h / r), "interpolation error ~ (h/r)^2"}));
    if (previous > 0) {
      EXPECT_LT(err, previous / 2.5) << "halving h should divide the error by about 4";
    }
    previous = err;
  }
}

TEST(Volume, PlaneCutOfABallMatchesTheSphericalCap) {
  const double r = 3.5;
  const TriangleMesh ball = sphereMesh(r, 0.1, Vec3(1, -2, 0.5));
  for (double d : {-2.5, -1.0, 0.0, 1.2, 2.8}) {
    // Plane at distance d from the centre along a tilted normal; volume above it.
    const Vec3 n = Vec3(0.2, 0.4, 1).normalized();
    const Plane plane{Vec3(1, -2, 0.5) + d * n, n};
    EXPECT_TRUE(nearRel("cap above d = " + std::to_string(d), volumeAbovePlane(ball, plane), capVolume(r, d),
                        {0.01, "issue 6: within 1 %"}));
    EXPECT_TRUE(nearRel("section at d = " + std::to_string(d), sectionArea(ball, plane), M_PI * (r * r - d * d),
                        {0.01, "disc of radius sqrt(r^2 - d^2) within 1 %"}));
  }
}

}  // namespace
}  // namespace coilsim::geometry
