// The smoothing spline against curves whose arc length is known in closed
// form: a straight line (reproduced exactly: the penalty does not act on
// lines) and a circle (s = R theta), unevenly sampled, with and without noise.
#include "validation/random_vector.h"
#include "validation/spline.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace coilsim::validation {
namespace {

TEST(SmoothingSpline, StraightLineIsReproducedAtEveryArcLength) {
  const Vec3 a(1e-3, 2e-3, 0), dir = Vec3(1, 2, 2).normalized();
  std::vector<Vec3> pts;
  for (double s : {0.0, 0.7e-3, 1.1e-3, 3.0e-3, 3.2e-3, 6.0e-3, 9.5e-3, 10e-3}) pts.push_back(a + s * dir);
  const SmoothingSpline sp(pts);
  EXPECT_NEAR(sp.length(), 10e-3, 1e-9);
  for (double s : {0.0, 2.5e-3, 5e-3, 9.9e-3}) EXPECT_LT((sp.at(s) - (a + s * dir)).norm(), 1e-9) << s;
  // Beyond the end: continued along the tangent.
  EXPECT_LT((sp.at(12e-3) - (a + 12e-3 * dir)).norm(), 1e-9);
}

TEST(SmoothingSpline, CircleArcLengthAndPositionsFromUnevenSamples) {
  const double R = 4e-3;
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> gap(0.3e-3, 1.5e-3);
  std::vector<Vec3> pts;
  for (double s = 0; s < 2 * M_PI * R; s += gap(rng)) pts.push_back(R * Vec3(std::sin(s / R), 1 - std::cos(s / R), 0));
  const SmoothingSpline sp(pts, {1e-9});
  for (double s : {1e-3, 5e-3, 12e-3, 20e-3}) {
    const Vec3 exact = R * Vec3(std::sin(s / R), 1 - std::cos(s / R), 0);
    EXPECT_LT((sp.at(s) - exact).norm(), 2e-6) << "s = " << s;
  }
}

TEST(SmoothingSpline, NoisyCircleIsSmoothedToTheNoiseLevelAndArcLengthKept) {
  const double R = 4e-3, sigma = 0.1e-3;
  std::mt19937 rng(11);
  std::normal_distribution<double> noise(0, sigma);
  std::uniform_real_distribution<double> gap(0.5e-3, 1.2e-3);
  std::vector<Vec3> pts;
  double sLast = 0;
  for (double s = 0; s < 4 * M_PI * R; s += gap(rng)) {
    pts.push_back(R * Vec3(std::sin(s / R), 1 - std::cos(s / R), 0) + drawVec3(noise, rng));
    sLast = s;
  }
  const SmoothingSpline sp(pts, {sigma});
  // The discrepancy principle: residual RMS per normal coordinate equals sigma.
  EXPECT_NEAR(sp.residualRms(), sigma, 0.15 * sigma);
  // Chord lengths of the noisy points overshoot; the spline's arc length does not.
  double chord = 0;
  for (size_t i = 1; i < pts.size(); ++i) chord += (pts[i] - pts[i - 1]).norm();
  EXPECT_GT(chord - sLast, 0.02 * sLast);
  EXPECT_NEAR(sp.length(), sLast, 0.01 * sLast);
  const double exact = sLast;
  double worst = 0;
  for (double s = 1e-3; s < 0.9 * exact; s += 1e-3)
    worst = std::max(worst, (sp.at(s) - R * Vec3(std::sin(s / R), 1 - std::cos(s / R), 0)).norm());
  // Within a few sigma at every arc length: what remains is the drift of
  // the arc length along two tight loops (R = 40 sigma), below 1 %.
  EXPECT_LT(worst, 4 * sigma);
}

TEST(SmoothingSpline, NoiseEstimateOnAStraightLine) {
  std::mt19937 rng(3);
  std::normal_distribution<double> noise(0, 0.05e-3);
  std::vector<Vec3> pts;
  for (int i = 0; i < 400; ++i) pts.push_back(Vec3(i * 1e-3, 0, 0) + drawVec3(noise, rng));
  EXPECT_NEAR(estimateNoise(pts), 0.05e-3, 0.006e-3);
}

TEST(SmoothingSpline, RefusesFewerThanTwoDistinctPoints) {
  EXPECT_THROW(SmoothingSpline({Vec3::Zero(), Vec3::Zero()}), std::invalid_argument);
}

}  // namespace
}  // namespace coilsim::validation
