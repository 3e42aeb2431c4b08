// `coilsim mesh --scale-to-mm`: a surface scaled far beyond any aneurysm (a
// file in mm read as metres) is reported; the shipped phantom at its own
// scale (a 7 mm sac on a 4 mm vessel, its sidecar) is not.
#include <gtest/gtest.h>

#include "app/run_binary.h"

namespace apptest {
namespace {

TEST(MeshCommand, WarnsWhenTheScaledSurfaceIsNoAneurysmsSize) {
  const fs::path dir = scratch("mesh_scale");
  const std::string stl = kSource + "/assets/meshes/sidewall-7mm.stl";
  const Exec right = coilsim({"mesh", stl}, dir);
  ASSERT_EQ(right.code, 0) << right.err;
  EXPECT_EQ(right.err.find("no aneurysm"), std::string::npos) << right.err;
  const Exec metres = coilsim({"mesh", stl, "--scale-to-mm", "1000"}, dir);
  EXPECT_CONTAINS(metres.err, "warning");
  EXPECT_CONTAINS(metres.err, "no aneurysm is that size");
  const Exec tiny = coilsim({"mesh", stl, "--scale-to-mm", "0.001"}, dir);
  EXPECT_CONTAINS(tiny.err, "smaller than any aneurysm");
  const Exec bad = coilsim({"mesh", stl, "--scale-to-mm", "10mm"}, dir);
  EXPECT_EQ(bad.code, 2);
  EXPECT_CONTAINS(bad.err, "--scale-to-mm needs a number > 0, got \"10mm\"");
}

}  // namespace
}  // namespace apptest
