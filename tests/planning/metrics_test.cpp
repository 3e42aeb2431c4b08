// Packing density, protrusion and neck coverage of hand-built coil configurations.
#include "planning/metrics.h"

#include <cmath>

#include <gtest/gtest.h>

namespace coilsim::planning {
namespace {

constexpr double kR = 3.5e-3;      // sac radius
constexpr double kNeckZ = -2.5e-3;  // neck plane height below the centre
constexpr double kWire = 0.127e-3;  // primary coil radius (0.010 inch coil)

Sac sphericalSac() {
  return makeSac(std::make_shared<TriangleMesh>(makeIcosphere(Vec3::Zero(), kR, 5)), Plane{Vec3(0, 0, kNeckZ), Vec3::UnitZ()});
}

double analyticSacVolume() {
  const double hc = kR + kNeckZ;
  return 4.0 / 3.0 * M_PI * kR * kR * kR - M_PI * hc * hc * (3 * kR - hc) / 3.0;
}

TEST(Metrics, PackingDensityOfStraightSegmentsMatchesTheAnalyticValue) {
  const Sac sac = sphericalSac();
  // Parallel chords at z = 0 (and one at z = 1 mm), y = -2..2 mm: each line runs far beyond the
  // sphere, so the length inside is the chord 2 sqrt(R^2 - y^2 - z^2), clipped by the sphere.
  CoilLines coil;
  coil.radius = kWire;
  double analyticLength = 0;
  for (int k = -4; k <= 4; ++k) {
    const double y = 0.5e-3 * k, z = (k % 2) ? 1e-3 : 0.0;
    coil.lines.push_back({Vec3(-6e-3, y, z), Vec3(-1e-3, y, z), Vec3(6e-3, y, z)});
    analyticLength += 2 * std::sqrt(kR * kR - y * y - z * z);
  }
  const double analytic = M_PI * kWire * kWire * analyticLength / analyticSacVolume();
  const SacMetrics m = measureSac(sac, volumeOnSide(*sac.mesh, sac.neck), sampleNeck(sac), coil);
  EXPECT_NEAR(m.packingDensity, analytic, 0.01 * analytic);
  EXPECT_NEAR(m.sacVolume, analyticSacVolume(), 0.01 * analyticSacVolume());
  EXPECT_FALSE(m.protruding);
}

TEST(Metrics, CoilThroughTheNeckProtrudesOneInsideDoesNot) {
  const Sac sac = sphericalSac();
  const double V = volumeOnSide(*sac.mesh, sac.neck);
  const NeckGrid neck = sampleNeck(sac);
  // The neck opening is the circle where the plane cuts the sphere: radius sqrt(R^2 - z^2).
  const double neckArea = M_PI * (kR * kR - kNeckZ * kNeckZ);
  EXPECT_NEAR(neck.area(), neckArea, 0.03 * neckArea);

  CoilLines inSac;
  inSac.radius = kWire;
  for (int i = 0; i <= 40; ++i) {  // a 2 mm loop well above the neck
    const double a = 2 * M_PI * i / 40;
    inSac.lines.resize(1);
    inSac.lines[0].push_back(Vec3(2e-3 * std::cos(a), 2e-3 * std::sin(a), 0.5e-3));
  }
  const SacMetrics kept = measureSac(sac, V, neck, inSac);
  EXPECT_FALSE(kept.protruding);
  EXPECT_EQ(kept.protrudingLength, 0.0);

  // A loop hanging 1.5 mm through the wide neck into the vessel below (inside the surface there).
  CoilLines through = inSac;
  for (Vec3& p : through.lines[0]) p.z() = kNeckZ - 0.5e-3 + 0.5e-3 * std::sin(std::atan2(p.y(), p.x()));
  const SacMetrics forced = measureSac(sac, V, neck, through);
  EXPECT_TRUE(forced.protruding);
  EXPECT_GT(forced.maxProtrusionDepth, 0.9e-3);
}

TEST(Metrics, NeckCoverageOfParallelWiresIsTheirShadowOnTheNeck) {
  const Sac sac = sphericalSac();
  const NeckGrid neck = sampleNeck(sac, 200);
  // Wires just above the neck plane, spaced s apart across the neck: each shadows a strip 2 r wide,
  // so coverage is 2 r / s (all strips span the opening; the edge strips are chords of the circle).
  CoilLines coil;
  coil.radius = kWire;
  const double s = 1e-3;
  double shadow = 0;
  const double a = std::sqrt(kR * kR - kNeckZ * kNeckZ);  // neck radius
  for (int k = -2; k <= 2; ++k) {
    const double y = s * k;
    coil.lines.push_back({Vec3(-a - 1e-3, y, kNeckZ + 0.3e-3), Vec3(a + 1e-3, y, kNeckZ + 0.3e-3)});
    // Area of the strip |y' - y| < r inside the circle, approximately 2 r times the chord at y.
    shadow += 2 * kWire * 2 * std::sqrt(a * a - y * y);
  }
  const SacMetrics m = measureSac(sac, volumeOnSide(*sac.mesh, sac.neck), neck, coil);
  const double expected = shadow / (M_PI * a * a);
  EXPECT_NEAR(m.neckCoverage, expected, 0.1 * expected);
}

TEST(Metrics, OcclusionClassThresholds) {
  EXPECT_EQ(occlusionClass(0.30, 0.8), 1);
  EXPECT_EQ(occlusionClass(0.30, 0.2), 2);
  EXPECT_EQ(occlusionClass(0.22, 0.9), 2);
  EXPECT_EQ(occlusionClass(0.10, 0.9), 3);
}

TEST(Metrics, WallForceStatisticsFollowTheStatesSustainedLoad) {
  // A node pressed with 5 mN for 10 steps of 1 ms, then a 400 mN spike of
  // one step, then 2 mN for 10 steps. The sustained load (the smallest of
  // the last 5 steps' largest forces) is 5 mN from the step the window
  // fills (the 5th) to the spike's (7 steps; the spike never lasts) and
  // 2 mN for the last 10. Its mean over the steps it is not zero is
  // (7 x 5 + 10 x 2) / 17 mN, below its maximum as a mean of one figure must
  // be; the time above 2.5 mN is those 7 steps.
  State state;
  WallForceStats w;
  int step = 0;
  const auto press = [&](double f, int steps) {
    for (int s = 0; s < steps; ++s, ++step) {
      addWallLoad(state.stats.wallLoad, f, 1e-3, 1e-3 * step);
      w.add(state, 1e-3, 2.5e-3);
    }
  };
  press(5e-3, 10);
  press(0.4, 1);
  press(2e-3, 10);
  EXPECT_DOUBLE_EQ(w.max, 5e-3);
  EXPECT_DOUBLE_EQ(w.peak, 0.4);
  EXPECT_NEAR(w.mean(), (7 * 5e-3 + 10 * 2e-3) / 17, 1e-15);
  EXPECT_LE(w.mean(), w.max);
  EXPECT_NEAR(w.timeAbove, 7e-3, 1e-12);
}

}  // namespace
}  // namespace coilsim::planning
