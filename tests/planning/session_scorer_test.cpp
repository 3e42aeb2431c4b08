// One run, two front ends, one wall-load figure: the plan's automatic
// operator and a practice session replaying its commands report the same
// sustained wall load (physics/contact/wall_load.h), and so do the panel's
// live read-outs. The reference is the run itself: the same steps, so their
// figures must be equal bit for bit, whoever computes them. The window's
// ui::Session on the same run: session_scorer_window_test.cpp (a build with
// the ui layer). Then the score sheet's goal and verdicts.
#include "planning/session_scorer.h"

#include <gtest/gtest.h>

#include "planning/live_readouts.h"
#include "planning/practice.h"
#include "planning/wall_load_run.h"

namespace coilsim::planning {
namespace {

TEST_F(WallLoadFigure, PlanAndPracticeReportTheSameLoadForOneRun) {
  EXPECT_EQ(plan.wall.max, run.planState.stats.wallLoad.max);

  // Practice: the operator's commands replayed for as many steps.
  const double end = double(plan.steps) * run.model.timeStep;
  const ScoreSheet sheet = playSession(run.practiceCase, run.coil, plan.timeline, {}, end);
  ASSERT_TRUE(sheet.ok) << sheet.error;
  EXPECT_TRUE(sheet.wallForcesAvailable);
  EXPECT_EQ(sheet.maxWallForce, plan.wall.max);

  // The live read-outs the window's panel shows, on the plan's final state.
  LiveReadouts live(run.practiceCase, *run.model.device);
  live.lines(run.model, run.planState);
  EXPECT_EQ(live.wallLoadMax(), plan.wall.max);
  std::printf("[ measured ] largest sustained wall load %.4f mN (peak single-step node force %.4f mN) over %ld steps\n",
              plan.wall.max * 1e3, plan.wall.peak * 1e3, plan.steps);
}

TEST(ScoreSheet, StatesTheGoalItJudgedInPercentAndWhyItWasMissed) {
  const PracticeCase pc = loadCase(kWideNeckCase);
  PracticeSession session(pc, "finishing-2x10");
  for (int s = 0; s < 10; ++s) ASSERT_TRUE(session.step());
  const ScoreSheet sheet = session.finish();
  const nlohmann::ordered_json j = scoreJson(sheet);
  // The case's goal (25 % packing, no protrusion, 100 mN, detach in the sac), as the case file states it.
  EXPECT_DOUBLE_EQ(j["goal"]["min_packing_percent"].get<double>(), 100 * pc.goal.minPackingDensity);
  EXPECT_EQ(j["goal"]["no_protrusion"].get<bool>(), pc.goal.noProtrusion);
  EXPECT_DOUBLE_EQ(j["goal"]["max_wall_load_mN"].get<double>(), 1e3 * pc.goal.maxWallForce);
  EXPECT_DOUBLE_EQ(j["packing_percent"].get<double>(), 100 * sheet.packingDensity);
  EXPECT_FALSE(j.contains("packing_density"));
  // Nothing placed, nothing detached: the goal is missed, and the sheet says why.
  EXPECT_FALSE(j["goal_met"].get<bool>());
  ASSERT_GE(j["goal_missed"].size(), 2u);
  EXPECT_NE(j["goal_missed"][0].get<std::string>().find("packing"), std::string::npos);
  EXPECT_EQ(j["goal_missed"].back().get<std::string>(), "not detached");
}

}  // namespace
}  // namespace coilsim::planning
