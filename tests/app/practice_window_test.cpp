// The practice picture (src/app/practice_window.cpp, in the app's graphics
// file set; tests/app/CMakeLists.txt compiles this file only with the ui
// layer): --size WxH sizes it, tested by running the real binary; the
// reference is the PNG's own header.
#include <gtest/gtest.h>

#include <fstream>
#include <string>
#include <utility>

#include "app/run_binary.h"

namespace apptest {
namespace {

const std::string kCase = kSource + "/scenes/cases/sphere-7mm-wide-neck.json";

// Width and height from a PNG's IHDR chunk (bytes 16-23, big-endian).
std::pair<long, long> pngSize(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  unsigned char b[24] = {};
  in.read(reinterpret_cast<char*>(b), sizeof b);
  auto be = [&](int at) { return long(b[at]) << 24 | long(b[at + 1]) << 16 | long(b[at + 2]) << 8 | long(b[at + 3]); };
  return {be(16), be(20)};
}

TEST(PracticeCommand, SizeSizesTheScreenshot) {
  const fs::path dir = scratch("practice_size_shot");
  std::ofstream(dir / "push.json")
      << R"({"format": "coilsim-timeline/1", "commands": [{"t_s": 0, "push": {"speed_mm_s": 10, "distance_mm": 1}}]})";
  const Exec r = coilsim({"practice", kCase, "--input", (dir / "push.json").string(), "--duration", "0.1",
                          "--screenshot", (dir / "p.png").string(), "--size", "320x200", "--out",
                          (dir / "score.json").string()},
                         dir);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(pngSize(dir / "p.png"), std::make_pair(320L, 200L));
}

}  // namespace
}  // namespace apptest
