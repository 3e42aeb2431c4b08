// Long runs stop cleanly: SIGINT or SIGTERM during a run ends it after the
// current step, with a valid result file of the state reached and the shell's
// exit code for a signal (128 + its number: 130, 143).
#include <gtest/gtest.h>

#include <csignal>
#include <fstream>
#include <string>

#include "app/run_binary.h"

namespace apptest {
namespace {

// Starts coilsim in the background on a pseudo-terminal (script(1)), waits
// until its progress line shows that steps are being taken, then sends
// `signal` and returns its exit code, stdout and what the terminal showed
// (stderr). Waiting for the progress line rather than a fixed delay: a slow
// start (a loaded machine, the sanitizers) would otherwise be signalled
// before its handlers are installed or before its first step. The progress
// line is drawn only after a step, half a second into stepping
// (app/progress.cpp). timeout(1) ends a run that ignores the signal and the
// wait is bounded, so the test cannot hang; timeout passes the signal on,
// once with --foreground: without it timeout sends it to the child and
// again to its process group, and the second, if the first was handled
// already, takes the default action (the handler is SA_RESETHAND, so that
// a second Ctrl-C ends a stuck run): the run died by the signal with no
// result written, now and then on a loaded machine.
Exec interrupted(const std::vector<std::string>& args, int signal, const fs::path& dir) {
  std::string cmd = "echo $$ >" + quote((dir / "pid.txt").string()) +
                    "; exec env -u DISPLAY -u WAYLAND_DISPLAY timeout --foreground 600 " + quote(COILSIM_BINARY);
  for (const std::string& a : args) cmd.append(" ").append(quote(a));
  cmd += " >" + quote((dir / "stdout.txt").string());
  const std::string tty = quote((dir / "tty.txt").string());
  const std::string shell = "script -q -e -c " + quote(cmd) + " /dev/null >" + tty +
                            " 2>&1 & job=$!; for i in $(seq 3000); do grep -q 's simulated' " + tty +
                            " && break; sleep 0.1; done; kill -" + std::to_string(signal) + " $(cat " +
                            quote((dir / "pid.txt").string()) + "); wait $job; echo $? >" +
                            quote((dir / "code.txt").string());
  std::system(("bash -c " + quote(shell)).c_str());
  Exec r;
  r.code = std::stoi(slurp(dir / "code.txt"));
  r.out = slurp(dir / "stdout.txt");
  r.err = slurp(dir / "tty.txt");
  return r;
}

TEST(StopSignal, SigintStopsADynamicRunWithAValidResult) {
  const fs::path dir = scratch("stop_sigint");
  const Exec r = interrupted(
      {"run", scene("helix-settling.json"), "--headless", "--duration", "1000", "--out", (dir / "r.json").string()},
      SIGINT, dir);
  EXPECT_EQ(r.code, 128 + SIGINT) << r.err;
  EXPECT_CONTAINS(r.err, "interrupted (SIGINT)");
  const nlohmann::json result = readJson(dir / "r.json");
  EXPECT_EQ(result["status"], "stopped");
  EXPECT_GT(result["steps"].get<long>(), 0);
  EXPECT_GT(result["time_s"].get<double>(), 0.0);
  EXPECT_LT(result["time_s"].get<double>(), 1000.0);
}

TEST(StopSignal, SigtermStopsADeploymentWithAValidResult) {
  const fs::path dir = scratch("stop_sigterm");
  const Exec r =
      interrupted({"run", scene("default.json"), "--headless", "--input", kSource + "/timelines/push-default.json",
                   "--duration", "1000", "--out", (dir / "r.json").string()},
                  SIGTERM, dir);
  EXPECT_EQ(r.code, 128 + SIGTERM) << r.err;
  EXPECT_CONTAINS(r.err, "terminated (SIGTERM)");
  const nlohmann::json result = readJson(dir / "r.json");
  EXPECT_EQ(result["status"], "stopped");
  EXPECT_GT(result["deployment"]["deployed_mm"].get<double>(), 0.0);
}

TEST(StopSignal, ARunBeyondTheStepBoundIsRefusedUpFront) {
  const fs::path dir = scratch("stop_bound");
  // The hour --duration allows, in steps of 10 us: 3.6e8 steps.
  nlohmann::json s = readJson(scene("helix-settling.json"));
  s["time_step_s"] = 1e-5;
  std::ofstream(dir / "fine.json") << s.dump();
  const Exec r = coilsim({"run", (dir / "fine.json").string(), "--headless", "--duration", "3600"}, dir);
  EXPECT_EQ(r.code, 2);
  EXPECT_CONTAINS(r.err, "--duration 3600 s in steps of 1e-05 s is more than 100000000 steps");
  EXPECT_EQ(r.out, "");  // nothing ran
}

}  // namespace
}  // namespace apptest
