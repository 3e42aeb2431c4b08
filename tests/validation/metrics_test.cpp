// The coil-measurement/1 metrics on cases computed by hand.
#include "validation/metrics.h"

#include <gtest/gtest.h>

#include <cmath>

namespace coilsim::validation {
namespace {

TEST(Metrics, HandComputedStage) {
  // Three nodes on the x axis (reference); measured displaced in z by 0, 2, 4 mm;
  // simulated off the measurement by 0, 0.2, 0.2 mm.
  const std::vector<Vec3> ref{{0, 0, 0}, {1e-3, 0, 0}, {2e-3, 0, 0}};
  const std::vector<Vec3> meas{{0, 0, 0}, {1e-3, 0, 2e-3}, {2e-3, 0, 4e-3}};
  const std::vector<Vec3> sim{{0, 0, 0}, {1e-3, 0.2e-3, 2e-3}, {2e-3, 0, 3.8e-3}};
  const StageMetrics m = computeMetrics(sim, meas, ref);
  // Node errors over nodes displaced >= 1 mm: 0.2/2 = 0.1 and 0.2/4 = 0.05.
  EXPECT_EQ(m.nodesCounted, 2);
  EXPECT_NEAR(m.nodeErrorMean, 0.075, 1e-12);
  EXPECT_NEAR(m.nodeErrorSd, 0.025, 1e-12);
  // Stage error sqrt(0.04 + 0.04) / sqrt(4 + 16).
  EXPECT_NEAR(m.stageError, std::sqrt(0.08 / 20.0), 1e-12);
  EXPECT_NEAR(m.meanDisplacement, 2e-3, 1e-15);
  EXPECT_NEAR(m.meanDistance, 0.4e-3 / 3, 1e-15);
}

TEST(Metrics, PerfectAgreementAndUndisplacedStage) {
  const std::vector<Vec3> a{{0, 0, 0}, {1e-3, 0, 0}};
  const StageMetrics m = computeMetrics(a, a, a);
  EXPECT_EQ(m.stageError, 0.0);
  EXPECT_EQ(m.nodesCounted, 0);
  const std::vector<Vec3> b{{0, 0, 0}, {1e-3, 1e-4, 0}};
  EXPECT_TRUE(std::isinf(computeMetrics(b, a, a).stageError));
  EXPECT_THROW(computeMetrics(a, {Vec3::Zero()}, a), std::invalid_argument);
}

}  // namespace
}  // namespace coilsim::validation
