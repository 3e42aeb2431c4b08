// Chart ticks (ui/validation_charts.h): steps of 1, 2 or 5 times a power of
// ten, the smallest such step giving at most the asked number of intervals.
#include "ui/validation_charts.h"

#include <gtest/gtest.h>

namespace coilsim::ui {
namespace {

TEST(ValidationCharts, TickStepsAreOneTwoOrFiveTimesAPowerOfTen) {
  EXPECT_FLOAT_EQ(niceTickStep(10.0f, 5), 2.0f);     // 10 / 5 = 2
  EXPECT_FLOAT_EQ(niceTickStep(75.0f, 8), 10.0f);    // 9.4 -> 10
  EXPECT_FLOAT_EQ(niceTickStep(1.3f, 3), 0.5f);      // 0.43 -> 0.5
  EXPECT_FLOAT_EQ(niceTickStep(0.0011f, 3), 0.0005f);
  EXPECT_FLOAT_EQ(niceTickStep(3.0f, 3), 1.0f);      // exactly 1: not the next step up
  EXPECT_FLOAT_EQ(niceTickStep(12.0f, 4), 5.0f);     // 3 -> 5
}

TEST(ValidationCharts, ADegenerateRangeStillGivesAPositiveStep) {
  EXPECT_GT(niceTickStep(0.0f, 3), 0.0f);
  EXPECT_GT(niceTickStep(-1.0f, 0), 0.0f);
}

}  // namespace
}  // namespace coilsim::ui
