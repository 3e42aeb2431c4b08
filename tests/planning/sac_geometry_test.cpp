// Sac volume and clipped coil lengths against closed-form sphere geometry.
#include "planning/sac_geometry.h"

#include <cmath>

#include <gtest/gtest.h>

namespace coilsim::planning {
namespace {

// Volume of the sphere of radius R above a plane at height z0 (relative to the centre, |z0| < R):
// the whole sphere minus the cap below, cap height hc = R + z0, cap volume pi hc^2 (3R - hc) / 3.
double sphereAbove(double R, double z0) {
  const double hc = R + z0;
  return 4.0 / 3.0 * M_PI * R * R * R - M_PI * hc * hc * (3 * R - hc) / 3.0;
}

TEST(SacGeometry, WholeIcosphereVolumeApproachesTheSphere) {
  const double R = 3.5e-3;
  const double exact = 4.0 / 3.0 * M_PI * R * R * R;
  double lastError = 1;
  for (int level = 2; level <= 5; ++level) {
    const TriangleMesh m = makeIcosphere(Vec3(1e-3, -2e-3, 0.5e-3), R, level);
    const double err = std::abs(enclosedVolume(m) - exact) / exact;
    EXPECT_LT(err, lastError) << "level " << level;  // converges under refinement
    lastError = err;
  }
  EXPECT_LT(lastError, 0.01);
}

TEST(SacGeometry, SacVolumeIsSphereMinusCapCutByNeckPlane) {
  const double R = 3.5e-3;
  const Vec3 c(0.2e-3, 0.1e-3, -0.3e-3);
  const auto mesh = std::make_shared<TriangleMesh>(makeIcosphere(c, R, 5));
  for (const double z0 : {-0.8 * R, -0.5 * R, 0.0, 0.3 * R}) {
    // A tilted neck plane: the cap depends only on the plane's distance to the centre.
    const Vec3 n = Vec3(0.3, -0.2, 1.0).normalized();
    Plane neck{c + z0 * n, n};
    const double v = volumeOnSide(*mesh, neck);
    EXPECT_NEAR(v, sphereAbove(R, z0), 0.01 * sphereAbove(R, z0)) << "z0 = " << z0 / R << " R";
    // Both sides add up to the whole mesh volume (conservation of the cut).
    Plane other{neck.point, -n};
    EXPECT_NEAR(v + volumeOnSide(*mesh, other), enclosedVolume(*mesh), 1e-12 * enclosedVolume(*mesh));
  }
}

TEST(SacGeometry, InsideTestOnSphere) {
  const Sac sac = makeSac(std::make_shared<TriangleMesh>(makeIcosphere(Vec3::Zero(), 1.0, 3)), Plane{});
  EXPECT_TRUE(insideSurface(sac, Vec3(0, 0, 0)));
  EXPECT_TRUE(insideSurface(sac, Vec3(0.5, 0.3, -0.6)));
  EXPECT_FALSE(insideSurface(sac, Vec3(1.2, 0, 0)));
  EXPECT_FALSE(insideSurface(sac, Vec3(0.8, 0.8, 0.1)));
}

TEST(SacGeometry, ChordLengthClippedBySphereAndNeckPlane) {
  const double R = 3.5e-3;
  const Sac sac = makeSac(std::make_shared<TriangleMesh>(makeIcosphere(Vec3::Zero(), R, 5)), Plane{Vec3(0, 0, -1e-3), Vec3::UnitZ()});
  // A line through the sphere at offset y = 1 mm, from far left to far right: chord 2 sqrt(R^2 - y^2).
  const double y = 1e-3, chord = 2 * std::sqrt(R * R - y * y);
  EXPECT_NEAR(lengthInSac(sac, Vec3(-10e-3, y, 0), Vec3(10e-3, y, 0)), chord, 0.005 * chord);
  // A vertical line x = y = 0 from below: inside from z = -1 mm (the plane) to z = R.
  EXPECT_NEAR(lengthInSac(sac, Vec3(0, 0, -10e-3), Vec3(0, 0, 10e-3)), R + 1e-3, 0.005 * (R + 1e-3));
  EXPECT_NEAR(lengthBeyondNeck(sac, Vec3(0, 0, -10e-3), Vec3(0, 0, 10e-3)), R - 1e-3, 0.005 * (R - 1e-3));
  // Entirely inside: the whole length.
  EXPECT_DOUBLE_EQ(lengthInSac(sac, Vec3(0, 0, 0), Vec3(1e-3, 1e-3, 1e-3)), std::sqrt(3.0) * 1e-3);
}

}  // namespace
}  // namespace coilsim::planning
