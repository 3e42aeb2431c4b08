// The session behind the window: its own Model copy for effect switches,
// reset to the initial state, blow-ups halt and are never drawn.
#include "ui/session.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <vector>

#include "scenes.h"

namespace coilsim::ui {
namespace {

TEST(Session, StepsResetsAndKeepsItsOwnModel) {
  const Model model = testing::helixModel();
  const State start = makeState(model);
  Session s(model, start);
  ASSERT_FALSE(s.drawData().tubes.empty());
  const Vec3 tip0 = s.state().rods[0].x.back();
  for (int i = 0; i < 20; ++i) ASSERT_TRUE(s.stepOnce().ok());
  EXPECT_NEAR(s.state().time, 20 * model.timeStep, 1e-12);
  EXPECT_GT((s.state().rods[0].x.back() - tip0).norm(), 0.0);  // gravity moved the free end
  // The draw data follows the state.
  EXPECT_EQ(s.drawData().tubes[0].centre.back(), s.state().rods[0].x.back());

  // Switching gravity off changes the session's copy, not the caller's model.
  EffectUse* g = findEffect(s.model(), "gravity");
  ASSERT_NE(g, nullptr);
  g->enabled = false;
  EXPECT_TRUE(findEffect(model, "gravity")->enabled);

  s.reset();
  EXPECT_EQ(s.state().time, 0.0);
  EXPECT_EQ(s.state().rods[0].x.back(), tip0);
  EXPECT_FALSE(findEffect(s.model(), "gravity")->enabled);  // switches survive a reset
}

TEST(Session, BlowUpHaltsAndKeepsTheLastGoodPicture) {
  Model model = testing::straightRodModel();
  // A huge time step with an enormous load makes the step fail its checks.
  model.rods[0].loads.push_back({20, Vec3(0, 0, 1e9), Vec3::Zero()});
  model.timeStep = 0.05;
  const State start = makeState(model);
  Session s(model, start);
  s.setPlaying(true);
  const DrawData before = s.drawData();
  const StepReport r = s.stepOnce();
  EXPECT_FALSE(r.ok());
  EXPECT_FALSE(s.playing());
  EXPECT_NE(s.haltMessage().find("step refused"), std::string::npos) << s.haltMessage();
  EXPECT_EQ(s.state().blowups, 1);
  // step() restored the state, so the picture is the last good one.
  for (const Vec3& p : s.drawData().tubes[0].centre) EXPECT_TRUE(p.allFinite());
  EXPECT_EQ(s.drawData().tubes[0].centre, before.tubes[0].centre);
}

// The observer is handed the refused step's report itself: the Failure that
// stepOnce returns and the halt holds (a blow-up, by the load's
// construction), not a line to parse.
TEST(Session, TheObserverGetsTheRefusedStepsFailure) {
  Model model = testing::straightRodModel();
  model.rods[0].loads.push_back({20, Vec3(0, 0, 1e9), Vec3::Zero()});
  model.timeStep = 0.05;
  struct Reports : RunObserver {
    std::vector<StepReport> seen;
    void afterStep(const Model&, const State&, const StepReport& r) override { seen.push_back(r); }
  };
  auto reports = std::make_shared<Reports>();
  Session s(model, makeState(model));
  s.setObserver(reports);
  const StepReport r = s.stepOnce();
  ASSERT_EQ(reports->seen.size(), 1u);
  ASSERT_FALSE(reports->seen[0].ok());
  EXPECT_EQ(reports->seen[0].failure->kind, FailureKind::BlowUp);
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.message(), reports->seen[0].message());
  ASSERT_TRUE(s.haltReason());
  EXPECT_EQ(s.haltMessage(), describe(*reports->seen[0].failure));
  EXPECT_EQ(s.haltReason()->rod, model.rods[0].name);
}

TEST(Session, AdvanceOnlyWhilePlaying) {
  const Model model = testing::straightRodModel();
  Session s(model, makeState(model));
  double clock = 0;
  auto now = [&] { return clock; };
  EXPECT_EQ(s.advance(0.01, now).steps, 0);
  s.setPlaying(true);
  EXPECT_EQ(s.advance(0.01, now).steps, 10);
  EXPECT_NEAR(s.state().time, 0.01, 1e-12);
}

TEST(Session, StopsExactlyAtTheStopTime) {
  const Model model = testing::straightRodModel();
  Session s(model, makeState(model));
  s.setStopTime(0.025);
  s.setPlaying(true);
  double clock = 0;
  for (int frame = 0; frame < 10; ++frame) s.advance(1.0 / 60.0, [&] { return clock; });
  EXPECT_TRUE(s.reachedStopTime());
  EXPECT_FALSE(s.playing());
  EXPECT_NEAR(s.state().time, 0.025, 1e-9);
  EXPECT_TRUE(s.haltMessage().empty());
}

TEST(Session, HookAddsMeshesOnce) {
  const Model model = testing::helixModel();
  Session s(model, makeState(model), testing::decorateHelix);
  const size_t meshes = s.drawData().meshes.size(), points = s.drawData().points.size();
  EXPECT_EQ(meshes, 2u);
  EXPECT_EQ(points, 2u);
  s.stepOnce();
  s.stepOnce();
  EXPECT_EQ(s.drawData().meshes.size(), meshes);
  EXPECT_EQ(s.drawData().points.size(), points);
}

}  // namespace
}  // namespace coilsim::ui
