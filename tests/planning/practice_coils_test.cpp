// Practice sessions of several coils (issue 16): the next coil goes in once
// the running one has detached, the detached ones stay in the sac as they
// were left (at rest), the sheet covers every coil, and the recording
// replays the session bit for bit.
#include <gtest/gtest.h>

#include <cmath>

#include "io/timeline.h"
#include "planning/practice.h"

namespace coilsim::planning {
namespace {

const std::string kCase = std::string(COILSIM_SOURCE_DIR) + "/scenes/cases/sphere-7mm-wide-neck.json";

DeviceCommand push(double mmPerS) { return {DeviceCommand::Kind::Push, mmPerS * 1e-3, 0}; }
DeviceCommand detach() { return {DeviceCommand::Kind::Detach, 0, 0}; }

double catalogueLengthMm(const PracticeCase& pc, const std::string& name) {
  for (const io::CoilSpec& c : pc.coils)
    if (c.name == name) return c.lengthMm;
  return -1;
}

TEST(PracticeCoils, CoilSequencesAreReadAndChecked) {
  const SessionCoils one = parseCoilSequence("finishing-2x10");
  EXPECT_EQ(one.first, "finishing-2x10");
  EXPECT_TRUE(one.next.empty());
  const SessionCoils three = parseCoilSequence("a+b+c");
  EXPECT_EQ(three.first, "a");
  ASSERT_EQ(three.next.size(), 2u);
  EXPECT_EQ(three.next[1].coil, "c");
  EXPECT_FALSE(three.next[0].time.has_value());
  const PracticeCase pc = loadCase(kCase);
  EXPECT_NO_THROW(checkCoils(pc, parseCoilSequence("finishing-2x10+finishing-3x40")));
  EXPECT_THROW(checkCoils(pc, parseCoilSequence("finishing-2x10+no-such-coil")), io::InputError);
}

TEST(PracticeCoils, NextCoilOnlyAfterADetachAndTheLeftCoilStaysAsItWasAtRest) {
  const PracticeCase pc = loadCase(kCase);
  PracticeSession s(pc, "finishing-2x10");
  const size_t rods = s.model().rods.size();
  EXPECT_NE(s.nextCoil("finishing-2x10"), "");  // not detached yet
  EXPECT_EQ(s.model().rods.size(), rods);
  ASSERT_EQ(s.command(push(10)), "");
  // 10 mm at 10 mm/s, and a step more.
  while (s.time() < 1.01) ASSERT_TRUE(s.step());
  ASSERT_EQ(s.command(detach()), "");
  ASSERT_TRUE(s.step());
  ASSERT_TRUE(s.deploymentState().detached);
  EXPECT_NE(s.nextCoil("no-such-coil"), "");
  const RodState left = s.state().rods[size_t(s.deployment().freeRod)];
  const double t = s.state().time;
  ASSERT_EQ(s.nextCoil("finishing-1.5x20"), "");
  // One rod more: the coil left, after the new deployment's rods, where it was, at rest.
  ASSERT_EQ(s.model().rods.size(), rods + 1);
  const RodState& placed = s.state().rods.back();
  EXPECT_EQ(placed.x, left.x);
  EXPECT_EQ(placed.q, left.q);
  for (const Vec3& v : placed.v) EXPECT_EQ(v, Vec3::Zero());
  EXPECT_FALSE(s.deploymentState().detached);
  EXPECT_EQ(s.deploymentState().deployed, 0.0);
  EXPECT_EQ(s.state().time, t);  // one session: the clock goes on
  EXPECT_EQ(s.model().rods.back().name, "finishing-2x10 (placed)");
}

// Two coils scripted (--coil a+b): the second goes in at the step after the
// first's detach (a detach acts at the first step at or after its time and
// takes that step); each is placed at its catalogue length; the replay of
// the recording writes the same sheet.
TEST(PracticeCoils, ScriptedSequenceRecordsTheChangeAndReplaysToTheSameSheet) {
  const PracticeCase pc = loadCase(kCase);
  const double dt = 1e-3;  // the case's time step
  const std::vector<TimedCommand> timeline{{0.0, push(10)}, {1.1, detach()}, {1.2, push(10)}, {3.3, detach()}};
  nlohmann::ordered_json recording;
  const ScoreSheet live =
      playSession(pc, parseCoilSequence("finishing-2x10+finishing-1.5x20"), timeline, {}, 3.5, &recording);
  ASSERT_TRUE(live.ok) << live.error;
  ASSERT_EQ(live.coils.size(), 2u);
  double total = 0;
  for (const CoilOutcome& c : live.coils) {
    EXPECT_TRUE(c.detached) << c.coil;
    EXPECT_NEAR(c.lengthPlaced * 1e3, catalogueLengthMm(pc, c.coil), 1e-9) << c.coil;
    total += catalogueLengthMm(pc, c.coil);
  }
  EXPECT_TRUE(live.detached);
  EXPECT_NEAR(live.coilLengthPlaced * 1e3, total, 1e-9);
  EXPECT_EQ(live.coil, "finishing-2x10 + finishing-1.5x20");
  ASSERT_TRUE(recording.contains("next_coils"));
  ASSERT_EQ(recording["next_coils"].size(), 1u);
  EXPECT_EQ(recording["next_coils"][0]["coil"], "finishing-1.5x20");
  EXPECT_NEAR(recording["next_coils"][0]["t_s"].get<double>(), (std::ceil(1.1 / dt - 1e-9) + 1) * dt, 1e-12);
  EXPECT_NEAR(live.coils[1].from, (std::ceil(1.1 / dt - 1e-9) + 1) * dt, 1e-12);

  const SessionRecording s = parseSession(nlohmann::json::parse(recording.dump()), "recording");
  ASSERT_EQ(s.nextCoils.size(), 1u);
  const ScoreSheet replayed = playSession(pc, SessionCoils(s.coil, s.nextCoils), s.timeline, s.views, s.end);
  EXPECT_EQ(scoreJson(replayed).dump(), scoreJson(live).dump());
}

}  // namespace
}  // namespace coilsim::planning
