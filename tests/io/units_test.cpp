// Edge units <-> SI: the one place they convert (src/io/units.h).
#include "io/units.h"

#include <gtest/gtest.h>

#include <cmath>

namespace coilsim::units {
namespace {

TEST(Units, LengthsAreaAndSecondMoments) {
  EXPECT_DOUBLE_EQ(mmToM(150.0), 0.15);
  EXPECT_DOUBLE_EQ(mToMm(0.0035), 3.5);
  EXPECT_DOUBLE_EQ(mm2ToM2(2.0), 2e-6);
  EXPECT_DOUBLE_EQ(mm4ToM4(3.0), 3e-12);
}

TEST(Units, MaterialConstants) {
  EXPECT_DOUBLE_EQ(gpaToPa(7.5), 7.5e9);
  EXPECT_DOUBLE_EQ(paToGpa(2e11), 200.0);
  EXPECT_DOUBLE_EQ(gcm3ToKgm3(21.45), 21450.0);
  EXPECT_DOUBLE_EQ(kgm3ToGcm3(1000.0), 1.0);
}

TEST(Units, AnglesMomentsAndRates) {
  EXPECT_DOUBLE_EQ(degToRad(180.0), M_PI);
  EXPECT_DOUBLE_EQ(radToDeg(M_PI / 2), 90.0);
  EXPECT_DOUBLE_EQ(nmmToNm(2.0), 2e-3);
  EXPECT_DOUBLE_EQ(nmToNmm(2e-3), 2.0);
  EXPECT_DOUBLE_EQ(mmPerSToMPerS(10.0), 0.01);
  EXPECT_DOUBLE_EQ(degPerSToRadPerS(90.0), M_PI / 2);
  // 1 deg/mm of intrinsic twist is 1000 deg/m.
  EXPECT_DOUBLE_EQ(degPerMmToRadPerM(1.0), 1000.0 * M_PI / 180.0);
}

}  // namespace
}  // namespace coilsim::units
