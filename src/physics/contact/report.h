#pragma once
// Contact read-outs for wall-load warnings, planning and drawing.
#include "physics/draw_data.h"
#include "physics/model.h"
#include "physics/state.h"

namespace coilsim {

struct ContactSummary {
  double maxWallForce = 0;      // largest normal force a node takes from the walls, N
  double totalWallForce = 0;    // sum over nodes, N
  double maxPenetration = 0;    // deepest wall penetration, m
  int wallContacts = 0, selfContacts = 0, rodContacts = 0;  // touching or within the margin
};
ContactSummary summarizeContacts(const State& state);

// Appends one DrawPoint per node with a contact force: at the node, its
// vector the normal force times `metresPerNewton`, yellow for walls, cyan
// for coil-coil.
void appendContactPoints(const State& state, double metresPerNewton, DrawData& out);

}  // namespace coilsim
