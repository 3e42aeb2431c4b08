// The detach confirmation's logic (ui/deployment_panel.cpp, the D key and the
// Detach button): it asks only when physics' command() would take the
// detach, answering for the state as it is; a refusal is said at once and
// changes nothing. The reference is command() itself, called on a copy of
// the same state.
#include <gtest/gtest.h>

#include "physics/run.h"
#include "support/refusal.h"
#include "support/helix_deployment.h"
#include "ui/panel.h"
#include "ui/session.h"

namespace coilsim::ui {
namespace {

DeviceCommand detach() {
  DeviceCommand c;
  c.kind = DeviceCommand::Kind::Detach;
  return c;
}

TEST(DetachConfirmation, NotFullyOutIsRefusedWithoutAskingAndChangesNothing) {
  const test::HelixDeployment sc = test::makeHelixDeployment(40.0, 2.0);
  Session s(sc.model, sc.start);
  State copy = s.state();
  const std::string physics = coilsim::test::refusal(coilsim::command(s.model(), copy, detach()));
  ASSERT_FALSE(physics.empty());

  EXPECT_EQ(coilsim::test::refusal(s.wouldRefuse(detach())), physics);
  DeviceControls dc;
  EXPECT_FALSE(requestDetach(s, dc));
  EXPECT_FALSE(dc.confirmDetach);
  ASSERT_FALSE(s.deviceMessages().empty());
  EXPECT_NE(s.deviceMessages().back().find(physics), std::string::npos) << s.deviceMessages().back();
  EXPECT_FALSE(s.state().device.motion.pendingDetach);
  s.stepOnce();
  EXPECT_FALSE(s.state().device.detached);
}

TEST(DetachConfirmation, FullyOutAsksFirstAndDetachesOnlyWhenConfirmed) {
  const test::HelixDeployment sc = test::makeHelixDeployment(40.0, 40.0);
  Session s(sc.model, sc.start);
  State copy = s.state();
  ASSERT_EQ(coilsim::test::refusal(coilsim::command(s.model(), copy, detach())), "");

  EXPECT_EQ(coilsim::test::refusal(s.wouldRefuse(detach())), "");
  DeviceControls dc;
  EXPECT_TRUE(requestDetach(s, dc));
  EXPECT_TRUE(dc.confirmDetach);
  // Asking changed nothing: stepping on does not detach.
  EXPECT_FALSE(s.state().device.motion.pendingDetach);
  s.stepOnce();
  EXPECT_FALSE(s.state().device.detached);
  // Cancelling (Esc) is closing the question; confirming detaches at the next step.
  dc.confirmDetach = false;
  EXPECT_TRUE(requestDetach(s, dc));
  confirmDetach(s, dc);
  EXPECT_FALSE(dc.confirmDetach);
  s.stepOnce();
  EXPECT_TRUE(s.state().device.detached);
  // Once detached, a second D is refused at once: nothing to ask.
  EXPECT_FALSE(requestDetach(s, dc));
  EXPECT_FALSE(dc.confirmDetach);
}

}  // namespace
}  // namespace coilsim::ui
