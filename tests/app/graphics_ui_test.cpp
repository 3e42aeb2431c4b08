// The app's graphics file set (src/app/graphics_ui.cpp, built with the ui
// layer; tests/app/CMakeLists.txt compiles this file only then): the
// off-screen picture of a run, tested by running the real binary.
#include <gtest/gtest.h>

#include <filesystem>

#include "app/run_binary.h"

namespace {

namespace fs = std::filesystem;
using namespace apptest;

TEST(Cli, ScreenshotOffScreenWritesAPng) {
  const fs::path dir = scratch("screenshot");
  const Exec r = coilsim({scene("cantilever-static.json"), "--headless", "--screenshot", (dir / "s.png").string(),
                         "--size", "320x240"}, dir);
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_GT(fs::file_size(dir / "s.png"), 100u);
}

}  // namespace
