// Case edit's window and picture (src/app/case_window.cpp, in the app's
// graphics file set; tests/app/CMakeLists.txt compiles this file only with
// the ui layer), tested by running the real binary: without a display the
// window says so (exit 1) and writes nothing; --screenshot draws the
// editor's view off-screen and leaves the case as it was. The window itself
// under Xvfb: tests/ui/case-editor-window-test.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "app/run_binary.h"

namespace {

using namespace apptest;

TEST(CaseEdit, WindowWithoutADisplaySaysSoAndTheScreenshotIsDrawnOffScreen) {
  const fs::path dir = scratch("case_edit_window_ui");
  const std::string stl = (fs::path(kSource) / "assets" / "meshes" / "sidewall-7mm.stl").string();
  const std::string file = (dir / "case.json").string();
  ASSERT_EQ(apptest::coilsim({"case", "new", stl, "--out", file}, dir).code, 0);
  const std::string original = slurp(file);
  const Exec headless = apptest::coilsim({"case", "edit", file, "--window"}, dir);  // apptest::coilsim runs without DISPLAY
  EXPECT_EQ(headless.code, 1);
  EXPECT_CONTAINS(headless.err, "display");
  EXPECT_EQ(slurp(file), original);
  const Exec shot = apptest::coilsim({"case", "edit", file, "--neck-shift", "0.5", "--screenshot",
                                      (dir / "editor.png").string(), "--out", (dir / "edited.json").string()},
                                     dir);
  ASSERT_EQ(shot.code, 0) << shot.err;
  EXPECT_GT(fs::file_size(dir / "editor.png"), 10000u);
  EXPECT_TRUE(fs::exists(dir / "edited.json"));
  EXPECT_EQ(slurp(file), original);
}

}  // namespace
