// The render benchmark runs and reports sane numbers (a tiny, fast run).
#include "ui/render_bench.h"

#include <gtest/gtest.h>

#include "scenes.h"

namespace coilsim::ui {
namespace {

TEST(RenderBench, ReportsFramesPerSecondAndShares) {
  const Model m = testing::helixModel();
  RenderBenchOptions o;
  o.width = 160;
  o.height = 120;
  o.frames = 3;
  o.warmupFrames = 1;
  o.stepsPerFrame = 2;
  o.addDrawData = testing::decorateHelix;
  RenderBenchResult r;
  std::string error;
  ASSERT_TRUE(benchRender(m, makeState(m), o, r, error)) << error;
  EXPECT_GT(r.fps3d, 0);
  EXPECT_GT(r.fpsXRay, 0);
  EXPECT_GT(r.fpsBiplane, 0);
  EXPECT_EQ(r.stepsPerFrame, 2);
  EXPECT_NEAR(r.physicsShare + r.renderShare, 1.0, 1e-9);
  EXPECT_GT(r.physicsShare, 0);
  EXPECT_EQ(r.refusedSteps, 0);
  EXPECT_FALSE(r.gl.empty());
}

}  // namespace
}  // namespace coilsim::ui
