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

// The display units against their SI definitions: 1 mm2 = 1e-6 m2,
// 1 mm3 = 1e-9 m3, 1 um = 1e-6 m, 1 mN = 1e-3 N, 1 ms = 1e-3 s,
// 1 us = 1e-6 s, 1 ns = 1e-9 s.
TEST(Units, ReportUnitsAgainstTheirSiDefinitions) {
  EXPECT_DOUBLE_EQ(m2ToMm2(1e-6), 1.0);
  EXPECT_DOUBLE_EQ(m2ToMm2(2.5e-5), 25.0);
  EXPECT_DOUBLE_EQ(m3ToMm3(1e-9), 1.0);
  EXPECT_DOUBLE_EQ(m3ToMm3(4.0 / 3.0 * M_PI * 3.5e-3 * 3.5e-3 * 3.5e-3), 4.0 / 3.0 * M_PI * 3.5 * 3.5 * 3.5);
  EXPECT_DOUBLE_EQ(mToUm(1e-6), 1.0);
  EXPECT_DOUBLE_EQ(mToUm(0.1e-3), 100.0);
  EXPECT_DOUBLE_EQ(nToMn(1e-3), 1.0);
  EXPECT_DOUBLE_EQ(nToMn(0.25), 250.0);
  EXPECT_DOUBLE_EQ(mnToN(1.0), 1e-3);
  EXPECT_DOUBLE_EQ(mnToN(100.0), 0.1);
  EXPECT_DOUBLE_EQ(sToMs(1e-3), 1.0);
  EXPECT_DOUBLE_EQ(sToMs(0.005), 5.0);
  EXPECT_DOUBLE_EQ(sToUs(1e-6), 1.0);
  EXPECT_DOUBLE_EQ(sToUs(0.0025), 2500.0);
  EXPECT_DOUBLE_EQ(nsToUs(1000.0), 1.0);
  EXPECT_DOUBLE_EQ(nsToUs(999999999.0), 999999.999);
  // A clock reading (s, ns) in microseconds: 1.5 s is 1,500,000 us however it is split.
  EXPECT_DOUBLE_EQ(sToUs(1.0) + nsToUs(5e8), sToUs(1.5));
  // Each pair inverts: an area and a volume are lengths squared and cubed.
  EXPECT_DOUBLE_EQ(mm2ToM2(m2ToMm2(3e-6)), 3e-6);
  EXPECT_DOUBLE_EQ(m3ToMm3(mmToM(2.0) * mmToM(3.0) * mmToM(4.0)), 24.0);
  EXPECT_DOUBLE_EQ(mnToN(nToMn(0.0123)), 0.0123);
}

}  // namespace
}  // namespace coilsim::units
