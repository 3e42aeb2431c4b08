// The window's ui::Session on the run the plan and practice score
// (wall_load_run.h; session_scorer_test.cpp compares those two): playing the
// plan's commands as its timeline it reports the same sustained wall load,
// bit for bit (the same steps), in the state and the deployment panel's
// line; Reset clears it. tests/planning/CMakeLists.txt compiles this file
// only in a build with the ui layer.
#include <gtest/gtest.h>

#include "planning/live_readouts.h"
#include "planning/wall_load_run.h"
#include "ui/session.h"

namespace coilsim::planning {
namespace {

TEST_F(WallLoadFigure, TheWindowsSessionReportsThePlansLoadAndResetClearsIt) {
  // The window: the same commands as its timeline, stepped by ui::Session.
  ui::Session window(run.model, run.startState);
  window.setTimeline(plan.timeline);
  for (long s = 0; s < plan.steps; ++s) ASSERT_TRUE(window.stepOnce().ok()) << "step " << s;
  EXPECT_EQ(window.state().stats.wallLoad.max, plan.wall.max);
  EXPECT_EQ(window.contacts().wallLoadMax, plan.wall.max);  // the deployment panel's line
  // Reset goes back to the start: no load any more, in the state or the panel.
  window.reset();
  EXPECT_EQ(window.state().stats.wallLoad.max, 0.0);
  EXPECT_EQ(window.state().stats.wallLoad.peak, 0.0);
  EXPECT_EQ(window.contacts().wallLoadMax, 0.0);
  LiveReadouts afterReset(run.practiceCase, *run.model.device);
  afterReset.lines(window.model(), window.state());
  EXPECT_EQ(afterReset.wallLoadMax(), 0.0);
}

}  // namespace
}  // namespace coilsim::planning
