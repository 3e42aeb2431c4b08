// The fixed error colour scale of the validation pictures (app/validate_plots.h)
// against its stated definition: log10-linear from 0.01 mm (blue) to 1 mm
// (red), clamped outside, the same whatever the picture's largest error.
#include "app/validate_plots.h"

#include <gtest/gtest.h>

#include <cmath>

namespace coilsim::app {
namespace {

TEST(ErrorColourScale, PositionIsLogarithmicBetweenTheStatedEnds) {
  EXPECT_DOUBLE_EQ(kErrorColourLowMm, 0.01);
  EXPECT_DOUBLE_EQ(kErrorColourHighMm, 1.0);
  EXPECT_EQ(errorScalePosition(0.01), 0.0);
  EXPECT_EQ(errorScalePosition(1.0), 1.0);
  EXPECT_NEAR(errorScalePosition(0.1), 0.5, 1e-12);                    // one decade of two
  EXPECT_NEAR(errorScalePosition(std::pow(10.0, -1.5)), 0.25, 1e-12);  // half a decade
  EXPECT_NEAR(errorScalePosition(0.3), std::log10(30.0) / 2.0, 1e-12);
}

TEST(ErrorColourScale, AGoodFitIsBlueAndAMissIsRedWhateverElseIsInThePicture) {
  // The pair: a 0.003 mm fit and a 1.3 mm miss, each at the end of its own scale.
  EXPECT_EQ(errorScalePosition(0.003), 0.0);
  EXPECT_EQ(errorScalePosition(1.3), 1.0);
  const std::array<float, 3> fit = errorScaleColour(errorScalePosition(0.003));
  const std::array<float, 3> miss = errorScaleColour(errorScalePosition(1.3));
  EXPECT_EQ(fit[0], 0.0f);  // no red
  EXPECT_EQ(fit[2], 1.0f);  // full blue
  EXPECT_EQ(miss[0], 1.0f);
  EXPECT_EQ(miss[2], 0.0f);
}

TEST(ErrorColourScale, BadNumbersSitAtTheLowEnd) {
  EXPECT_EQ(errorScalePosition(std::nan("")), 0.0);
  EXPECT_EQ(errorScalePosition(-1.0), 0.0);
  EXPECT_EQ(errorScalePosition(INFINITY), 0.0);
  const std::array<float, 3> c = errorScaleColour(std::nan(""));
  EXPECT_EQ(c[2], 1.0f);
}

TEST(ErrorColourScale, TheLegendStatesTheEnds) {
  const std::string l = errorScaleLegend();
  EXPECT_NE(l.find("0.01 mm"), std::string::npos) << l;
  EXPECT_NE(l.find("1 mm"), std::string::npos) << l;
  EXPECT_NE(l.find("log"), std::string::npos) << l;
}

}  // namespace
}  // namespace coilsim::app
