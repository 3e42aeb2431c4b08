// `coilsim practice --size WxH`, tested by running the real binary: a bad
// size is refused (exit 2) with run's wording, before any session starts;
// a good one sizes the picture (the reference: the PNG's own header).
#include <gtest/gtest.h>

#include <cstdint>
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

// The line of stderr that says what --size needed.
std::string sizeComplaint(const std::string& err) {
  const size_t at = err.find("--size needs");
  if (at == std::string::npos) return "";
  return err.substr(at, err.find('"', err.find("got \"", at) + 5) + 1 - at);
}

TEST(PracticeCommand, BadSizeIsRefusedWithRunsWording) {
  const fs::path dir = scratch("practice_size_bad");
  for (const char* bad : {"8x480", "640x480x3", "640", "x480", "640x-480", "99999x480"}) {
    const Exec p = coilsim({"practice", kCase, "--window", "--size", bad}, dir);
    const Exec r = coilsim({"run", kSource + "/scenes/default.json", "--size", bad}, dir);
    EXPECT_EQ(p.code, 2) << bad << ": " << p.err;
    EXPECT_EQ(r.code, 2) << bad << ": " << r.err;
    const std::string said = sizeComplaint(p.err);
    EXPECT_NE(said, "") << p.err;
    EXPECT_EQ(said, sizeComplaint(r.err)) << "practice: " << p.err << "run: " << r.err;
    EXPECT_CONTAINS(said, std::string("got \"") + bad + "\"");
  }
  // A size is never taken from the next option.
  const Exec p = coilsim({"practice", kCase, "--window", "--size", "--quiet"}, dir);
  EXPECT_EQ(p.code, 2) << p.err;
  EXPECT_CONTAINS(p.err, "--size");
}

TEST(PracticeCommand, HelpListsSize) {
  const fs::path dir = scratch("practice_size_help");
  const Exec h = coilsim({"practice", "--help"}, dir);
  ASSERT_EQ(h.code, 0) << h.err;
  EXPECT_CONTAINS(h.out, "--size WxH");
  EXPECT_CONTAINS(h.out, "--window [--coil NAME]");
}

#ifdef COILSIM_HAVE_UI
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
#endif

}  // namespace
}  // namespace apptest
