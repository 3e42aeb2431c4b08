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

// Starts coilsim in the background, sends `signal` after `delay` s, and
// returns its exit code and streams. timeout(1) ends a run that ignores the
// signal, so the test cannot hang.
Exec interrupted(const std::vector<std::string>& args, int signal, double delay, const fs::path& dir) {
  std::string cmd = "env -u DISPLAY -u WAYLAND_DISPLAY timeout 120 " + quote(COILSIM_BINARY);
  for (const std::string& a : args) cmd.append(" ").append(quote(a));
  const std::string shell = cmd + " >" + quote((dir / "stdout.txt").string()) + " 2>" +
                            quote((dir / "stderr.txt").string()) + " & pid=$!; sleep " + std::to_string(delay) +
                            "; kill -" + std::to_string(signal) + " $pid; wait $pid; echo $? >" +
                            quote((dir / "code.txt").string());
  std::system(("bash -c " + quote(shell)).c_str());
  Exec r;
  r.code = std::stoi(slurp(dir / "code.txt"));
  r.out = slurp(dir / "stdout.txt");
  r.err = slurp(dir / "stderr.txt");
  return r;
}

TEST(StopSignal, SigintStopsADynamicRunWithAValidResult) {
  const fs::path dir = scratch("stop_sigint");
  const Exec r = interrupted(
      {"run", scene("helix-settling.json"), "--headless", "--duration", "1000", "--out", (dir / "r.json").string()},
      SIGINT, 1.5, dir);
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
                  SIGTERM, 1.5, dir);
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
