#include "golden.h"

#include <cstdio>
#include <cstdlib>
#include <filesystem>

namespace coilsim::testing {

std::string outputDir() {
  const std::string dir = COILSIM_TEST_OUTPUT_DIR;
  std::filesystem::create_directories(dir);
  return dir;
}

::testing::AssertionResult matchesGolden(const render::Image& actual, const std::string& name,
                                         const GoldenTolerance& tol) {
  const std::string goldenPath = std::string(COILSIM_GOLDEN_DIR) + "/" + name + ".png";
  const std::string actualPath = outputDir() + "/" + name + ".png";
  const std::string diffPath = outputDir() + "/" + name + ".diff.png";
  std::string error;
  if (!render::writePng(actualPath, actual, error)) return ::testing::AssertionFailure() << error;

  const char* update = std::getenv("COILSIM_UPDATE_GOLDEN");
  if (update && std::string(update) == "1") {
    if (!render::writePng(goldenPath, actual, error)) return ::testing::AssertionFailure() << error;
    std::printf("updated golden %s\n", goldenPath.c_str());
    return ::testing::AssertionSuccess();
  }

  render::Image expected;
  if (!render::readPng(goldenPath, expected, error))
    return ::testing::AssertionFailure() << error << " (render it with COILSIM_UPDATE_GOLDEN=1, then look at "
                                         << actualPath << ")";
  if (expected.width != actual.width || expected.height != actual.height)
    return ::testing::AssertionFailure() << name << ": golden is " << expected.width << "x" << expected.height
                                         << ", rendered " << actual.width << "x" << actual.height << " ("
                                         << actualPath << ")";
  const render::ImageDiff d = render::compareImages(expected, actual, tol.threshold);
  const std::string summary = render::describe(d, tol.threshold);
  if (d.fractionOff <= tol.maxFractionOff && d.meanAbs <= tol.maxMeanAbs) {
    std::printf("%s: %s\n", name.c_str(), summary.c_str());
    return ::testing::AssertionSuccess();
  }
  render::writePng(diffPath, d.diff, error);
  char allowed[96];
  std::snprintf(allowed, sizeof allowed, "allowed %.2f%% off, mean %.2f", 100 * tol.maxFractionOff, tol.maxMeanAbs);
  return ::testing::AssertionFailure() << name << " differs from " << goldenPath << ": " << summary << " ("
                                       << allowed << "); rendered " << actualPath << ", diff (red) " << diffPath;
}

}  // namespace coilsim::testing
