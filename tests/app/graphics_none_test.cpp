// The app without graphics (src/app/graphics_none.cpp, built without the ui
// layer; tests/app/CMakeLists.txt compiles this file only then): what asks
// for a picture is a usage error that says why, tested by running the real
// binary.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "app/run_binary.h"

namespace {

namespace fs = std::filesystem;
using namespace apptest;

TEST(Cli, ScreenshotWithoutUiSaysSoAndExits2) {
  const fs::path dir = scratch("screenshot");
  const Exec r = coilsim({scene("cantilever-static.json"), "--headless", "--screenshot", (dir / "s.png").string()}, dir);
  EXPECT_EQ(r.code, 2);
  EXPECT_CONTAINS(r.err, "without the ui layer");
}

// Case edit and practice refuse a window or a picture before reading the
// case further: a usage error (exit 2) that names the missing layer.
TEST(Cli, CaseEditAndPracticeWindowsWithoutUiAreUsageErrors) {
  const fs::path dir = scratch("no_ui_windows");
  const std::string stl = (fs::path(kSource) / "assets" / "meshes" / "sidewall-7mm.stl").string();
  const std::string file = (dir / "case.json").string();
  ASSERT_EQ(coilsim({"case", "new", stl, "--out", file}, dir).code, 0);
  const std::string practiceCase = kSource + "/scenes/cases/sphere-7mm-wide-neck.json";
  for (const std::vector<std::string>& args :
       {std::vector<std::string>{"case", "edit", file, "--window"},
        {"case", "edit", file, "--screenshot", (dir / "editor.png").string()},
        {"practice", practiceCase, "--window"},
        {"practice", practiceCase, "--screenshot", (dir / "p.png").string(), "--out", (dir / "s.json").string()}}) {
    const Exec r = coilsim(args, dir);
    EXPECT_EQ(r.code, 2) << args[0] << " " << args.back();
    EXPECT_CONTAINS(r.err, "no window or screenshots (no ui layer)");
  }
  EXPECT_FALSE(fs::exists(dir / "editor.png"));
  EXPECT_FALSE(fs::exists(dir / "p.png"));
}

// The validation panel likewise (validate_panel_test.cpp draws it in a build
// with the ui layer).
TEST(Cli, ValidatePanelWithoutUiIsAUsageError) {
  const fs::path dir = scratch("no_ui_validate");
  const std::string example = kSource + "/examples/measurements/soft-catheter-helix.json";
  for (const std::vector<std::string>& args : {std::vector<std::string>{"validate", example, "--window"},
                                               {"validate", example, "--screenshot", (dir / "v.png").string()}}) {
    const Exec r = coilsim(args, dir);
    EXPECT_EQ(r.code, 2) << args.back();
    EXPECT_CONTAINS(r.err, "no ui layer");
  }
  EXPECT_FALSE(fs::exists(dir / "v.png"));
}

}  // namespace
