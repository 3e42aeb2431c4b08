// Whether a run has wall forces to report (planning/contact_forces.h): the
// reference is the model's definition, an enabled "wall_contact" effect or not.
#include "planning/contact_forces.h"

#include <gtest/gtest.h>

#include "physics/effect.h"
#include "physics/model.h"
#include "support/rod_models.h"

namespace coilsim::planning {
namespace {

Model rodWith(const std::vector<std::string>& effects) {
  ModelDef def = test::modelOf({test::straightRod(10e-3, 10, test::platinum(),
                                                  circularSection(0.15e-3, test::kPlatinumPoisson))});
  for (const std::string& e : effects) def.effects.push_back(EffectRegistry::global().use(e));
  return compileModel(def);
}

TEST(HasWallForces, OnlyWithAnEnabledWallContact) {
  const Model none = rodWith({"gravity"});
  EXPECT_FALSE(hasWallForces(none, makeState(none)));
  const Model selfOnly = rodWith({"gravity", "self_contact"});
  EXPECT_FALSE(hasWallForces(selfOnly, makeState(selfOnly)));
  Model wall = rodWith({"gravity", "wall_contact"});
  EXPECT_TRUE(hasWallForces(wall, makeState(wall)));
  findEffect(wall, "wall_contact")->enabled = false;  // switched off in the panel: unavailable, not zero
  EXPECT_FALSE(hasWallForces(wall, makeState(wall)));
}

}  // namespace
}  // namespace coilsim::planning
