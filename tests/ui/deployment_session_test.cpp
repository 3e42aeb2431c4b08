// The window's deployment (ui::Session): a timeline played in the window
// reaches the state the headless runner reaches (runTimeline, its own loop),
// bit for bit; commands from the panel, keys and gamepad move the coil by
// speed x time; refusals carry the controller's reason.
#include <gtest/gtest.h>

#include <cmath>

#include "physics/effect.h"
#include "ui/device_input.h"
#include "ui/session.h"
#include "support/helix_deployment.h"
#include "support/refusal.h"

namespace coilsim::ui {
namespace {

// A 40 mm platinum helix (5 mm loops) pushed out of a rigid catheter at the
// origin along +x, under gravity.
using Scene = test::HelixDeployment;

Scene makeScene(double initialMm = 2.0) { return test::makeHelixDeployment(40.0, initialMm); }

DeviceCommand cmd(DeviceCommand::Kind k, double rate, double amount = 0) {
  DeviceCommand c;
  c.kind = k;
  c.rate = rate;
  c.amount = amount;
  return c;
}

bool anyMessageHas(const Session& s, const std::string& text) {
  for (const std::string& m : s.deviceMessages())
    if (m.find(text) != std::string::npos) return true;
  return false;
}

TEST(SessionDeployment, TimelineInTheWindowMatchesTheHeadlessRunBitForBit) {
  const Scene sc = makeScene();
  using K = DeviceCommand::Kind;
  const std::vector<TimedCommand> timeline = {
      {0.0, cmd(K::Push, 0.02, 0.006)},        // 6 mm at 20 mm/s
      {0.05, cmd(K::Push, 1.0)},               // too fast: refused
      {0.1005, cmd(K::Twist, 2.0, 0.3)},       // between step starts: starts at the next one
      {0.32, cmd(K::Pull, 0.01, 0.002)},      // after the push has ended at 0.3 s
      {0.35, cmd(K::Retract, 0.005, 0.001)}};  // while pulling
  const double duration = 0.6;

  State headless = sc.start;
  const TimelineRun run = runTimeline(sc.model, headless, timeline, duration);
  const DeviceState& dsHeadless = headless.device;
  ASSERT_TRUE(run.ok()) << run.failure->message();

  Session s(sc.model, sc.start);
  s.setTimeline(timeline);
  // Half the run frame by frame through the real-time loop, half step by step.
  s.setPlaying(true);
  s.setStopTime(0.2);
  double clock = 0;
  while (s.playing()) s.advance(1.0 / 60.0, [&] { return clock; });
  while (s.state().time < duration - 0.5 * sc.model.timeStep) ASSERT_TRUE(s.stepOnce().ok());

  EXPECT_EQ(s.stepsTaken(), run.steps);
  EXPECT_EQ(s.deploymentState().deployed, dsHeadless.deployed);
  EXPECT_EQ(s.deploymentState().twist, dsHeadless.twist);
  EXPECT_EQ(s.deploymentState().tipOffset, dsHeadless.tipOffset);
  const RodState &a = s.state().rods[sc.dep.chainRod], &b = headless.rods[sc.dep.chainRod];
  ASSERT_EQ(a.activeNodes, b.activeNodes);
  for (int i = 0; i < a.activeNodes; ++i) {
    EXPECT_EQ(a.x[i], b.x[i]) << "node " << i;
    EXPECT_EQ(a.q[i].coeffs(), b.q[i].coeffs()) << "node " << i;
  }
  // Kinematics: 2 + 6 - 2 mm pushed/pulled, plus the 1 mm the retraction unsheathes; 0.3 rad of twist.
  EXPECT_NEAR(s.deploymentState().deployed, 0.007, 1e-12);
  EXPECT_NEAR(s.deploymentState().twist, 0.3, 1e-12);
  EXPECT_TRUE(anyMessageHas(s, "/commands/1: refused: push/pull speed")) << s.deviceMessages().back();
}

TEST(SessionDeployment, ResetRestartsTheDeploymentAndTheTimeline) {
  const Scene sc = makeScene();
  Session s(sc.model, sc.start);
  s.setTimeline({{0.0, cmd(DeviceCommand::Kind::Push, 0.01)}});
  for (int i = 0; i < 100; ++i) ASSERT_TRUE(s.stepOnce().ok());
  EXPECT_NEAR(s.deploymentState().deployed, 0.002 + 100 * 1e-3 * 0.01, 1e-12);
  s.reset();
  EXPECT_EQ(s.deploymentState().deployed, sc.start.device.deployed);
  EXPECT_EQ(s.timelineCursor(), 0u);
  EXPECT_TRUE(s.deviceMessages().empty());
  s.stepOnce();  // the timeline plays again from t = 0
  EXPECT_NEAR(s.deploymentState().deployed, 0.002 + 1e-3 * 0.01, 1e-12);
}

TEST(SessionDeployment, RefusedCommandsSayWhy) {
  const Scene sc = makeScene();
  Model noDevice = sc.model;
  noDevice.device.reset();
  const std::optional<Failure> none = Session(noDevice, sc.start).command(cmd(DeviceCommand::Kind::Push, 0.01));
  ASSERT_TRUE(none);
  EXPECT_EQ(none->kind, FailureKind::DeviceRefusal);
  EXPECT_NE(describe(*none).find("no deployment"), std::string::npos) << describe(*none);
  Session s(sc.model, sc.start);
  const std::string why = coilsim::test::refusal(s.command(cmd(DeviceCommand::Kind::Detach, 0)));
  EXPECT_NE(why.find("not fully out"), std::string::npos) << why;
  EXPECT_TRUE(anyMessageHas(s, "not fully out"));
  // Nothing moved: the refusal changes nothing.
  s.stepOnce();
  EXPECT_EQ(s.deploymentState().deployed, sc.start.device.deployed);
  EXPECT_FALSE(s.deploymentState().detached);
}

TEST(SessionDeployment, PushedToTheEndThenDetached) {
  const Scene sc = makeScene(38.0);
  Session s(sc.model, sc.start);
  EXPECT_EQ(coilsim::test::refusal(s.command(cmd(DeviceCommand::Kind::Push, 0.05))), "");
  for (int i = 0; i < 60 && !s.deviceMessages().size(); ++i) ASSERT_TRUE(s.stepOnce().ok());
  EXPECT_TRUE(anyMessageHas(s, "fully deployed"));
  EXPECT_EQ(s.deploymentState().deployed, sc.dep.coilLength);
  EXPECT_EQ(coilsim::test::refusal(s.command(cmd(DeviceCommand::Kind::Detach, 0))), "");
  ASSERT_TRUE(s.stepOnce().ok());
  EXPECT_TRUE(s.deploymentState().detached);
  EXPECT_NE(coilsim::test::refusal(s.command(cmd(DeviceCommand::Kind::Push, 0.01))).find("detached"), std::string::npos);
}

// Held keys and gamepad levers: the coil moves at lever x panel speed while
// held (deployed length = v t), stops when let go, one command per change.
TEST(DeviceInput, LeversPushPullAndTwistAtThePanelSpeed) {
  const Scene sc = makeScene(10.0);
  Session s(sc.model, sc.start);
  DeviceControls controls;
  controls.pushSpeedMmS = 4.0;
  controls.twistRateDegS = 90.0;
  DeviceInput in;
  const double dt = sc.model.timeStep;
  for (int i = 0; i < 50; ++i) {
    in.update(s, controls, 1.0, 0.0);  // push held
    ASSERT_TRUE(s.stepOnce().ok());
  }
  EXPECT_NEAR(s.deploymentState().deployed, 0.010 + 50 * dt * 0.004, 1e-12);
  in.update(s, controls, 0.0, 0.0);  // let go
  for (int i = 0; i < 20; ++i) ASSERT_TRUE(s.stepOnce().ok());
  EXPECT_NEAR(s.deploymentState().deployed, 0.010 + 50 * dt * 0.004, 1e-12);
  // Half a pull lever with the twist lever fully right.
  for (int i = 0; i < 40; ++i) {
    in.update(s, controls, -0.5, 1.0);
    ASSERT_TRUE(s.stepOnce().ok());
  }
  EXPECT_NEAR(s.deploymentState().deployed, 0.010 + 50 * dt * 0.004 - 40 * dt * 0.002, 1e-12);
  EXPECT_NEAR(s.deploymentState().twist, 40 * dt * M_PI / 2, 1e-12);
  // Letting go of the pull keeps the twist going.
  in.update(s, controls, 0.0, 1.0);
  const double d = s.deploymentState().deployed;
  for (int i = 0; i < 10; ++i) ASSERT_TRUE(s.stepOnce().ok());
  EXPECT_EQ(s.deploymentState().deployed, d);
  EXPECT_NEAR(s.deploymentState().twist, 50 * dt * M_PI / 2, 1e-12);
  EXPECT_TRUE(s.deviceMessages().empty());  // nothing was refused
}

TEST(DeviceInput, AHeldLeverAgainstALimitIsRefusedOnce) {
  const Scene sc = makeScene(0.0);
  Session s(sc.model, sc.start);
  DeviceInput in;
  for (int i = 0; i < 30; ++i) in.update(s, DeviceControls{}, -1.0, 0.0);  // pull with nothing out
  ASSERT_EQ(s.deviceMessages().size(), 1u);
  EXPECT_NE(s.deviceMessages().front().find("fully inside"), std::string::npos) << s.deviceMessages().front();
}

}  // namespace
}  // namespace coilsim::ui
