// One run, three front ends, one wall-load figure: the plan's automatic
// operator, a practice session replaying its commands and the window's
// ui::Session playing them as a timeline report the same sustained wall load
// (physics/contact/wall_load.h), and the window's Reset clears it. The
// reference is the run itself: the three are the same steps, so their
// figures must be equal bit for bit, whoever computes them.
#include "planning/session_scorer.h"

#include <gtest/gtest.h>

#include "planning/auto_deploy.h"
#include "planning/live_readouts.h"
#include "planning/practice.h"

#ifdef COILSIM_HAVE_UI
#include "ui/session.h"
#endif

namespace coilsim::planning {
namespace {

const std::string kCase = std::string(COILSIM_SOURCE_DIR) + "/scenes/cases/sphere-7mm-wide-neck.json";

TEST(WallLoadFigure, PlanPracticeAndWindowReportTheSameLoadForOneRun) {
  const PracticeCase pc = loadCase(kCase);
  const std::string coil = "finishing-2x20";  // short, so three runs of it stay a small test
  // The plan's operator on the practice model (the same contacts: addRunContacts).
  const PracticeSession start(pc, coil);
  Model model = start.model();
  State planState = start.state();
  AutoDeployOptions o;
  o.pushSpeed = 20e-3;  // the case's fastest push, to load the wall within a short test
  o.settle = 0.1;
  const AutoDeployResult plan = autoDeploy(model, planState, o, wallContactForces);
  ASSERT_TRUE(plan.ok) << plan.error;
  ASSERT_TRUE(plan.wallForcesAvailable);
  ASSERT_GT(plan.wall.max, 0.0) << "the coil never pressed on the wall: the comparison would prove nothing";
  EXPECT_EQ(plan.wall.max, planState.stats.wallLoad.max);

  // Practice: the operator's commands replayed for as many steps.
  const double end = double(plan.steps) * model.timeStep;
  const ScoreSheet sheet = playSession(pc, coil, plan.timeline, {}, end);
  ASSERT_TRUE(sheet.ok) << sheet.error;
  EXPECT_TRUE(sheet.wallForcesAvailable);
  EXPECT_EQ(sheet.maxWallForce, plan.wall.max);

  // The live read-outs the window's panel shows, on the plan's final state.
  LiveReadouts live(pc, *model.device);
  live.lines(model, planState);
  EXPECT_EQ(live.wallLoadMax(), plan.wall.max);
  std::printf("[ measured ] largest sustained wall load %.4f mN (peak single-step node force %.4f mN) over %ld steps\n",
              plan.wall.max * 1e3, plan.wall.peak * 1e3, plan.steps);

#ifdef COILSIM_HAVE_UI
  // The window: the same commands as its timeline, stepped by ui::Session.
  ui::Session window(start.model(), start.state());
  window.setTimeline(plan.timeline);
  for (long s = 0; s < plan.steps; ++s) ASSERT_TRUE(window.stepOnce().ok()) << "step " << s;
  EXPECT_EQ(window.state().stats.wallLoad.max, plan.wall.max);
  EXPECT_EQ(window.contacts().wallLoadMax, plan.wall.max);  // the deployment panel's line
  // Reset goes back to the start: no load any more, in the state or the panel.
  window.reset();
  EXPECT_EQ(window.state().stats.wallLoad.max, 0.0);
  EXPECT_EQ(window.state().stats.wallLoad.peak, 0.0);
  EXPECT_EQ(window.contacts().wallLoadMax, 0.0);
  LiveReadouts afterReset(pc, *model.device);
  afterReset.lines(window.model(), window.state());
  EXPECT_EQ(afterReset.wallLoadMax(), 0.0);
#endif
}

TEST(ScoreSheet, StatesTheGoalItJudgedInPercentAndWhyItWasMissed) {
  const PracticeCase pc = loadCase(kCase);
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
