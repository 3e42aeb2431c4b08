// Whether the contact layer keeps wall forces for a run.
#include "planning/contact_forces.h"

namespace coilsim::planning {

bool hasWallForces(const Model& model, const State&) {
  const EffectUse* wall = findEffect(model, "wall_contact");
  return wall && wall->enabled;
}

}  // namespace coilsim::planning
