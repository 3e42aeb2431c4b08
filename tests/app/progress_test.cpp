// Progress on a terminal and silence off one, by running the real binary
// under a pseudo-terminal (script(1) from util-linux) and with stderr in a
// file.
#include "app/progress.h"

#include <gtest/gtest.h>

#include <string>

#include "app/run_binary.h"

namespace apptest {
namespace {

// A dynamic run long enough (about 2 s on the development machine) for the progress line to be drawn.
const std::vector<std::string> kLongRun = {"run", scene("helix-settling.json"), "--headless", "--duration", "30"};

// Runs coilsim under a pseudo-terminal; returns what the terminal showed (stdout and stderr).
Exec onTerminal(const std::vector<std::string>& args, const fs::path& dir) {
  std::string cmd = "env -u DISPLAY -u WAYLAND_DISPLAY " + quote(COILSIM_BINARY);
  for (const std::string& a : args) cmd.append(" ").append(quote(a));
  const std::string shell =
      "script -q -e -c " + quote(cmd) + " /dev/null >" + quote((dir / "tty.txt").string()) + " 2>&1";
  const int status = std::system(shell.c_str());
  Exec r;
  r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.out = slurp(dir / "tty.txt");
  return r;
}

TEST(Progress, ShownOnATerminal) {
  const fs::path dir = scratch("progress_tty");
  const Exec r = onTerminal(kLongRun, dir);
  ASSERT_EQ(r.code, 0) << r.out;
  EXPECT_CONTAINS(r.out, "s simulated");
  EXPECT_CONTAINS(r.out, "ETA");
  EXPECT_CONTAINS(r.out, "s simulated per s");             // the rate
  EXPECT_CONTAINS(r.out, "helix-settling.json: dynamic");  // the summary, after the progress line
}

TEST(Progress, SilentOffATerminalAndWithQuiet) {
  const fs::path dir = scratch("progress_quiet");
  const Exec file = coilsim(kLongRun, dir);
  ASSERT_EQ(file.code, 0) << file.err;
  EXPECT_EQ(file.err.find("ETA"), std::string::npos) << file.err;
  EXPECT_EQ(file.err.find('\r'), std::string::npos);
  std::vector<std::string> quiet = kLongRun;
  quiet.push_back("--quiet");
  const Exec tty = onTerminal(quiet, dir);
  ASSERT_EQ(tty.code, 0) << tty.out;
  EXPECT_EQ(tty.out.find("ETA"), std::string::npos) << tty.out;
  EXPECT_CONTAINS(tty.out, "helix-settling.json: dynamic");
}

TEST(Progress, PlanSaysWhichCoilsEachRunDeploys) {
  const fs::path dir = scratch("progress_plan");
  const Exec r = onTerminal({"plan", kSource + "/scenes/cases/sphere-7mm-wide-neck.json", "--coils",
                             "finishing-2x10,finishing-2x10+finishing-3x40", "--no-screenshots", "--out",
                             (dir / "plan").string()},
                            dir);
  ASSERT_EQ(r.code, 0) << r.out;
  EXPECT_CONTAINS(r.out, "run 1 of 2: deploying coil finishing-2x10 (nominal)");
  EXPECT_CONTAINS(r.out, "run 2 of 2: deploying sequence of 2 coils finishing-2x10 + finishing-3x40 (nominal)");
  // How far the runs are: mm deployed of the 60 mm of coil the plan holds, and a run's coil (the 40 mm one
  // takes long enough to be drawn) and simulated time.
  EXPECT_CONTAINS(r.out, " of 60 mm deployed");
  EXPECT_CONTAINS(r.out, "mm deployed per s");
  EXPECT_CONTAINS(r.out, "coil 2 of 2 finishing-3x40: ");
  EXPECT_CONTAINS(r.out, " s simulated (");
  const Exec file = coilsim({"plan", kSource + "/scenes/cases/sphere-7mm-wide-neck.json", "--coils", "finishing-2x10",
                             "--no-screenshots", "--out", (dir / "plan2").string()},
                            dir);
  ASSERT_EQ(file.code, 0) << file.err;
  EXPECT_EQ(file.err.find("deploying"), std::string::npos) << file.err;
}

TEST(Progress, DurationsReadAsAClockDoes) {
  using coilsim::app::Progress;
  EXPECT_EQ(Progress::duration(12.4), "12 s");
  EXPECT_EQ(Progress::duration(245), "4 min 05 s");
  EXPECT_EQ(Progress::duration(3720), "1 h 02 min");
}

}  // namespace
}  // namespace apptest
