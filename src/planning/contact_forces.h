#pragma once
// Wall forces per node as planning reads them from the contact layer.
#include "planning/auto_deploy.h"

namespace coilsim::planning {

// Reads RodContacts::wallForce of every rod (normal force from walls per
// node, N); false when the model has no enabled "wall_contact" effect.
bool wallContactForces(const Model& model, const State& state, std::vector<std::vector<double>>& out);

}  // namespace coilsim::planning
