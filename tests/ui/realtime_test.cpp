// The real-time loop: fixed steps from an accumulator, a wall-time budget
// that slows simulated time instead of freezing, refusals stop the frame.
#include "ui/realtime.h"

#include <gtest/gtest.h>

namespace coilsim::ui {
namespace {

// A fake wall clock advanced by the fake step function.
struct FakeClock {
  double t = 0;
  double now() const { return t; }
};

TEST(RealTimeLoop, KeepsUpWithCheapSteps) {
  RealTimeConfig c;
  c.timeStep = 1e-3;
  RealTimeLoop loop(c);
  FakeClock clock;
  int steps = 0;
  for (int frame = 0; frame < 120; ++frame) {
    const FrameAdvance f = loop.advance(1.0 / 60.0, [&] { ++steps; clock.t += 1e-6; return true; },
                                        [&] { return clock.now(); });
    EXPECT_FALSE(f.droppedTime);
  }
  // Two seconds of real time are two thousand steps of 1 ms, give or take one.
  EXPECT_NEAR(steps, 2000, 1);
  EXPECT_NEAR(loop.realTimeFactor(), 1.0, 0.05);
  EXPECT_FALSE(loop.behind());
}

TEST(RealTimeLoop, SlowsSimulatedTimeWhenStepsAreTooSlow) {
  RealTimeConfig c;
  c.timeStep = 1e-3;
  c.frameBudget = 0.010;
  RealTimeLoop loop(c);
  FakeClock clock;
  int steps = 0;
  // Each step costs 2 ms of wall time: at most about 5 fit into a 10 ms budget.
  for (int frame = 0; frame < 60; ++frame) {
    const FrameAdvance f = loop.advance(1.0 / 60.0, [&] { ++steps; clock.t += 2e-3; return true; },
                                        [&] { return clock.now(); });
    EXPECT_GE(f.steps, 1);  // never frozen
    EXPECT_LE(f.steps, 6);
    EXPECT_TRUE(f.droppedTime);
  }
  EXPECT_TRUE(loop.behind());
  EXPECT_LT(loop.realTimeFactor(), 0.5);
  EXPECT_GT(loop.realTimeFactor(), 0.2);
}

TEST(RealTimeLoop, AlwaysTakesOneStepEvenIfOneStepExceedsTheBudget) {
  RealTimeConfig c;
  c.timeStep = 1e-3;
  c.frameBudget = 0.001;
  RealTimeLoop loop(c);
  FakeClock clock;
  const FrameAdvance f = loop.advance(0.02, [&] { clock.t += 0.05; return true; }, [&] { return clock.now(); });
  EXPECT_EQ(f.steps, 1);
  EXPECT_TRUE(f.droppedTime);
}

TEST(RealTimeLoop, LongPausesAreNotCaughtUp) {
  RealTimeConfig c;
  c.timeStep = 1e-3;
  c.maxFrameTime = 0.1;
  RealTimeLoop loop(c);
  int steps = 0;
  loop.advance(5.0, [&] { ++steps; return true; }, [] { return 0.0; });
  EXPECT_EQ(steps, 100);
}

TEST(RealTimeLoop, RefusedStepEndsTheFrame) {
  RealTimeLoop loop(RealTimeConfig{});
  int calls = 0;
  const FrameAdvance f = loop.advance(0.05, [&] { return ++calls < 3; }, [] { return 0.0; });
  EXPECT_TRUE(f.refused);
  EXPECT_EQ(f.steps, 2);
  EXPECT_EQ(calls, 3);
}

}  // namespace
}  // namespace coilsim::ui
