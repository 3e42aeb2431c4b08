#pragma once
// Whether a run has wall forces, as planning asks the contact layer.
#include "planning/auto_deploy.h"

namespace coilsim::planning {

// True when the model has an enabled "wall_contact" effect, whose per-node
// wall forces (RodContacts::wallForce) and wall load (State::stats) the
// step keeps; the default WallForceCheck.
bool hasWallForces(const Model& model, const State& state);

}  // namespace coilsim::planning
