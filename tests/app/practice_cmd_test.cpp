// `coilsim practice --size WxH`, tested by running the real binary: a bad
// size is refused (exit 2) with run's wording, before any session starts.
// That a good one sizes the picture: practice_window_test.cpp (a build with
// the ui layer).
#include <gtest/gtest.h>

#include <string>

#include "app/run_binary.h"

namespace apptest {
namespace {

const std::string kCase = kSource + "/scenes/cases/sphere-7mm-wide-neck.json";

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

}  // namespace
}  // namespace apptest
