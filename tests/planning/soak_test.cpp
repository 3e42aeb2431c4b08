// A soak of the practice path: random device commands at the device's limits
// (fastest push and pull, fastest twists, retraction, detach attempts, stops)
// for many simulated seconds on a case with contacts. What must hold however
// the inputs come: every refused command or refused step is reported (score
// sheet), the wire goes no deeper into the wall than its contact skin is thick, and
// memory does not grow with simulated time.
#include <fstream>
#include <random>
#include <string>

#include <gtest/gtest.h>
#ifdef __SANITIZE_ADDRESS__
// The ASan runtime's own (sanitizer/allocator_interface.h, which GCC does not ship).
extern "C" size_t __sanitizer_get_current_allocated_bytes();
#endif

#include "physics/contact/detect.h"
#include "physics/run.h"
#include "planning/practice.h"

namespace coilsim::planning {
namespace {

const std::string kCase = std::string(COILSIM_SOURCE_DIR) + "/scenes/cases/sphere-7mm-wide-neck.json";

// The memory the run holds, bytes: the resident set size of this process
// (Linux /proc). Under AddressSanitizer the live heap instead: the resident
// set there also holds the quarantine of freed blocks (256 MB by default),
// which fills during the run without anything being kept.
#ifdef __SANITIZE_ADDRESS__
long heldBytes() { return long(__sanitizer_get_current_allocated_bytes()); }
#else
long heldBytes() {
  std::ifstream f("/proc/self/statm");
  long pages = 0, resident = 0;
  f >> pages >> resident;
  return resident * 4096;
}
#endif

// One random command at or near the device's limits.
DeviceCommand randomCommand(std::mt19937& rng, const Deployment& dep) {
  using K = DeviceCommand::Kind;
  std::uniform_int_distribution<int> kind(0, 9);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  switch (kind(rng)) {
    case 0: case 1: case 2: return {K::Push, dep.maxPushSpeed, 0};             // the fastest push, unlimited
    case 3: return {K::Push, dep.maxPushSpeed * unit(rng), 5e-3 * unit(rng)};
    case 4: return {K::Pull, dep.maxPushSpeed, 3e-3 * unit(rng)};
    case 5: return {K::Twist, (unit(rng) < 0.5 ? -1 : 1) * dep.maxTwistRate, M_PI * unit(rng)};
    case 6: return {K::Retract, dep.maxPushSpeed * unit(rng), 1e-3 * unit(rng)};
    case 7: return {K::Detach, 0, 0};
    case 8: return {K::Stop, 0, 0};
    default: return {K::Push, 2 * dep.maxPushSpeed, 0};  // beyond the limit: must be refused, and said
  }
}

TEST(Soak, RandomCommandsAtTheLimitsAreAllAccountedForAndStayOutOfTheWall) {
  const PracticeCase pc = loadCase(kCase);
  PracticeSession session(pc, "finishing-3x40");
  const Deployment& dep = session.deployment();
  std::mt19937 rng(20261124);
  const double dt = session.model().timeStep, end = 8.0;
  const long steps = long(end / dt), every = long(0.15 / dt);
  long refusedCommands = 0, rssAfterWarmUp = 0;
  bool stepRefused = false;
  for (long s = 0; s < steps; ++s) {
    if (s % every == 0 && !session.command(randomCommand(rng, dep)).empty()) ++refusedCommands;
    if (!session.step()) {
      stepRefused = true;
      break;
    }
    if (s == steps / 4) rssAfterWarmUp = heldBytes();
  }
  const ScoreSheet sheet = session.finish();
  // Every refusal is in the sheet (commands refused at once, and those the
  // device refuses when it acts: a detach before the coil is out).
  EXPECT_GE(long(sheet.deviceMessages.size()), refusedCommands);
  // A refused step ends the session with its reason, never silently.
  EXPECT_EQ(stepRefused, !sheet.ok);
  if (stepRefused) {
    EXPECT_FALSE(sheet.error.empty());
  }
  // The wire itself goes no deeper past the wall's faces than its contact skin is thick.
  const StepStats& st = session.state().stats;
  std::printf("[ measured ] %zu device messages (%ld refused at once), deepest wall penetration %.3g um = %.3g of r, "
              "%s\n", sheet.deviceMessages.size(), refusedCommands, st.maxWallPenetration * 1e6,
              st.maxWallPenetrationOfRadius, sheet.ok ? "no step refused" : sheet.error.c_str());
  EXPECT_LT(st.maxWallPenetrationOfRadius, kWallSkin);
  EXPECT_GT(refusedCommands, 0) << "the soak never met a limit: it proves nothing about refusals";
  // Memory flat: the last three quarters of the run add at most 8 MB.
  const long grown = heldBytes() - rssAfterWarmUp;
  EXPECT_LT(grown, 8L << 20) << "resident memory grew by " << grown << " bytes";
}

}  // namespace
}  // namespace coilsim::planning
