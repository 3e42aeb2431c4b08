// Sac volume and clipped coil lengths against closed-form sphere geometry.
#include "planning/sac_geometry.h"

#include <cmath>
#include <stdexcept>

#include "geometry/marching_tets.h"

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

// A parent vessel (a tube of radius 2 mm along x) with two balls of radius
// 3.2 mm on it, centred 4 mm above its axis at x = -4 and +4 mm; a
// horizontal neck plane at z = 2.5 mm cuts each ball apart (sections of
// radius 2.83 mm, 8 mm apart), above the tube. The sac is the left ball's
// cap, over the neck's point; the right one stands for a daughter vessel
// that rises past the plane of a bifurcation's neck. Closed forms: the cap
// above a plane 1.5 mm below a ball's centre, and chords of the balls.
struct TwoPieces {
  static constexpr double R = 3.2e-3, zc = 4e-3, zn = 2.5e-3, xc = 4e-3;
  Sac sac;
  TwoPieces() {
    const geometry::Field field = [](const Vec3& p) {
      const double tube = std::max(std::hypot(p.y(), p.z()) - 2, std::abs(p.x()) - 12);
      return std::min({tube, (p - Vec3(-4, 0, 4)).norm() - 3.2, (p - Vec3(4, 0, 4)).norm() - 3.2});
    };
    TriangleMesh mesh = geometry::polygonise(field, Vec3(-13, -4, -3), Vec3(13, 4, 8), 0.2);
    for (Vec3& v : mesh.vertices) v *= 1e-3;
    sac = makeSac(std::make_shared<TriangleMesh>(std::move(mesh)), Plane{Vec3(-xc, 0, zn), Vec3::UnitZ()});
  }
  static double cap() {
    const double h = R + (zc - zn);
    return M_PI * h * h * (3 * R - h) / 3.0;
  }
};

TEST(SacGeometry, APlaneCuttingTwoPiecesTakesTheOneOverItsPointAsTheSac) {
  const TwoPieces t;
  ASSERT_TRUE(t.sac.piece);
  // Volume: the left cap only; the whole sac side holds both caps.
  EXPECT_NEAR(sacVolume(t.sac), TwoPieces::cap(), 0.02 * TwoPieces::cap());
  EXPECT_NEAR(volumeOnSide(*t.sac.mesh, t.sac.neck), 2 * TwoPieces::cap(), 0.04 * TwoPieces::cap());
  // Points: over the neck's point, in the other piece, below the plane, outside.
  EXPECT_TRUE(inSac(t.sac, Vec3(-4e-3, 0.5e-3, 5e-3)));
  EXPECT_FALSE(inSac(t.sac, Vec3(4e-3, 0.5e-3, 5e-3)));
  EXPECT_FALSE(inSac(t.sac, Vec3(-4e-3, 0, 1e-3)));
  EXPECT_FALSE(inSac(t.sac, Vec3(0, 0, 5e-3)));
  // A line through both balls 1 mm below their centres: one chord in the
  // sac, the other beyond it (in the daughter), and none in the tube.
  const double z = 3e-3, chord = 2 * std::sqrt(TwoPieces::R * TwoPieces::R - (TwoPieces::zc - z) * (TwoPieces::zc - z));
  EXPECT_NEAR(lengthInSac(t.sac, Vec3(-12e-3, 0, z), Vec3(12e-3, 0, z)), chord, 0.01 * chord);
  EXPECT_NEAR(lengthBeyondNeck(t.sac, Vec3(-12e-3, 0, z), Vec3(12e-3, 0, z)), chord, 0.01 * chord);
  // Vertical lines through each ball's centre, from the axis of the tube up.
  const double upper = TwoPieces::zc + TwoPieces::R - TwoPieces::zn;
  EXPECT_NEAR(lengthInSac(t.sac, Vec3(-4e-3, 0, 0), Vec3(-4e-3, 0, 9e-3)), upper, 0.01 * upper);
  EXPECT_NEAR(lengthBeyondNeck(t.sac, Vec3(-4e-3, 0, 0), Vec3(-4e-3, 0, 9e-3)), TwoPieces::zn, 0.01 * TwoPieces::zn);
  EXPECT_NEAR(lengthInSac(t.sac, Vec3(4e-3, 0, 0), Vec3(4e-3, 0, 9e-3)), 0.0, 1e-12);
  EXPECT_NEAR(lengthBeyondNeck(t.sac, Vec3(4e-3, 0, 0), Vec3(4e-3, 0, 9e-3)), TwoPieces::zc + TwoPieces::R, 0.01 * upper);
}

TEST(SacGeometry, APlaneCuttingTwoPiecesWithItsPointOutsideIsRefused) {
  const TwoPieces t;
  // Between the balls, above the tube: outside the surface.
  EXPECT_THROW(makeSac(t.sac.mesh, Plane{Vec3(0, 0, TwoPieces::zn), Vec3::UnitZ()}), std::invalid_argument);
  // One piece on the sac side: no piece is chosen (the whole side is the sac).
  EXPECT_FALSE(makeSac(std::make_shared<TriangleMesh>(makeIcosphere(Vec3::Zero(), 1e-3, 3)), Plane{}).piece);
}

}  // namespace
}  // namespace coilsim::planning
