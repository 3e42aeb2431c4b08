#pragma once
// Screenshot comparison against tests/render/golden/<name>.png with a
// tolerance. The rendered image is always written to the test output
// directory; on failure a diff image (red where pixels are off) is written
// next to it. COILSIM_UPDATE_GOLDEN=1 rewrites the golden instead.
#include <gtest/gtest.h>

#include <string>

#include "render/image.h"

namespace coilsim::testing {

struct GoldenTolerance {
  int threshold = 24;            // a channel differing by more than this marks the pixel off (0-255)
  double maxFractionOff = 0.004; // share of pixels allowed off
  double maxMeanAbs = 1.0;       // mean |difference| over all channels (0-255)
};

// Directory for rendered images and diffs (created if missing).
std::string outputDir();

::testing::AssertionResult matchesGolden(const render::Image& actual, const std::string& name,
                                         const GoldenTolerance& tolerance = {});

}  // namespace coilsim::testing
