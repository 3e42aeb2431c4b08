// Headless `coilsim run` on a scene with a phantom and its sac: the clinical
// read-outs (packing, coil in the sac, neck coverage, protrusion, sustained
// wall load) are printed and written into result.json. References: the
// packing's definition (pi r^2 times the coil length in the sac over the
// sac's volume, r from the scene file), the coil pushed out (all of it in
// the sac, which the scene's own test shows), and the printed lines equal
// to the file's numbers.
#include <gtest/gtest.h>

#include <cmath>

#include "app/run_binary.h"

namespace {

using namespace apptest;

TEST(RunScene, HeadlessRunOfAPhantomScenePrintsAndWritesTheClinicalReadouts) {
  const fs::path dir = scratch("run_readouts");
  const Exec r = coilsim({"run", scene("default.json"), "--headless", "--input", kSource + "/timelines/push-default.json",
                          "--duration", "0.8", "--out", (dir / "result.json").string()},
                         dir);
  ASSERT_EQ(r.code, 0) << r.err;
  for (const char* line : {"read-outs", "packing density", "coil in the sac", "neck coverage", "protrusion", "wall load"})
    EXPECT_CONTAINS(r.out, line);
  const nlohmann::json result = readJson(dir / "result.json");
  ASSERT_TRUE(result.contains("readouts")) << result.dump();
  const nlohmann::json& c = result["readouts"];
  const nlohmann::json sceneFile = readJson(scene("default.json"));
  const double radius = sceneFile["deployment"]["coil"]["section"]["outer_radius_mm"].get<double>();
  // 1 mm out at the start and 8 mm pushed at 10 mm/s, all in the sac.
  const double deployed = result["deployment"]["deployed_mm"].get<double>();
  EXPECT_NEAR(deployed, 9.0, 0.05);
  EXPECT_NEAR(c["coil_in_sac_mm"].get<double>(), deployed, 0.5);
  EXPECT_NEAR(c["coil_volume_mm3"].get<double>(), M_PI * radius * radius * c["coil_in_sac_mm"].get<double>(),
              1e-6 * c["coil_volume_mm3"].get<double>());
  EXPECT_NEAR(c["packing_percent"].get<double>(),
              100 * c["coil_volume_mm3"].get<double>() / c["sac_volume_mm3"].get<double>(), 1e-9);
  EXPECT_FALSE(c["protruding"].get<bool>());
  EXPECT_GE(c["neck_coverage_percent"].get<double>(), 0.0);
  EXPECT_LE(c["neck_coverage_percent"].get<double>(), 100.0);
  // The scene has wall contact: the load is measured (not null), over its stated window.
  EXPECT_DOUBLE_EQ(c["wall_load_window_ms"].get<double>(), 5.0);
  ASSERT_TRUE(c["wall_load_mN"].is_number()) << c.dump();
  EXPECT_GE(c["largest_wall_load_mN"].get<double>(), c["wall_load_mN"].get<double>());
  // The printed packing is the file's.
  char printed[64];
  std::snprintf(printed, sizeof printed, "packing density: %.1f %%", c["packing_percent"].get<double>());
  EXPECT_CONTAINS(r.out, printed);
}

}  // namespace
