// The app without graphics (src/app/graphics_none.cpp, built without the ui
// layer; tests/app/CMakeLists.txt compiles this file only then): what asks
// for a picture is a usage error that says why, tested by running the real
// binary.
#include <gtest/gtest.h>

#include <filesystem>

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

}  // namespace
