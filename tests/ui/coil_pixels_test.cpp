// The window check's coil detector, on goldens whose content is known: it
// finds the platinum coil in the 3D view and nothing in X-rays or in a rod
// coloured blue to red.
#include "coil_pixels.h"

#include <gtest/gtest.h>

namespace coilsim::testing {
namespace {

long countIn(const std::string& name) {
  render::Image image;
  std::string error;
  EXPECT_TRUE(render::readPng(std::string(COILSIM_GOLDEN_DIR) + "/" + name, image, error)) << error;
  return countCoilPixels(image);
}

TEST(CoilPixels, FindsTheCoilOnlyWhereItIsDrawnIn3d) {
  EXPECT_GT(countIn("helix_3d.png"), 500);
  EXPECT_LT(countIn("helix_xray.png"), 10);
  EXPECT_LT(countIn("helix_biplane.png"), 10);
  EXPECT_LT(countIn("rod_3d.png"), 100);  // a few highlights on the middle of the ramp
}

}  // namespace
}  // namespace coilsim::testing
