// Planning's contacts (run_contacts.h): the same contact law as a scene's
// window run (reference: the registry's wall_contact, which a scene that
// lists the effect with no parameters gets).
#include "planning/run_contacts.h"

#include <gtest/gtest.h>

#include "planning/practice.h"

namespace coilsim::planning {
namespace {

const std::string kCase = std::string(COILSIM_SOURCE_DIR) + "/scenes/cases/sphere-7mm-wide-neck.json";

TEST(RunContacts, PlanningRunsTheWallAScenesWindowRuns) {
  // The registered wall_contact parameters, nothing of planning's own.
  const PracticeCase pc = loadCase(kCase);
  const PracticeSession session(pc, "finishing-3x40");
  const EffectUse registered = EffectRegistry::global().use("wall_contact");
  const EffectUse* used = findEffect(session.model(), "wall_contact");
  ASSERT_NE(used, nullptr);
  EXPECT_EQ(used->values, registered.values);
}

}  // namespace
}  // namespace coilsim::planning
