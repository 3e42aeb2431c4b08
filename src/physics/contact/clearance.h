#pragma once
// How far a point is from the walls (the obstacles that take part in
// contact), and how deep a node presses on wire: for the device, which must
// not drive what it holds into a wall, nor a wire it pins against one.
#include "physics/math.h"
#include "physics/model.h"
#include "physics/state.h"

namespace coilsim {

// The least distance from `p` to a triangle of an obstacle with contact on,
// or `reach` when none is nearer than that (m).
double wallClearance(const Model& model, const Vec3& p, double reach);

// How deep node `node` of rod `rod` pins wire against a wall: of the pair
// contacts (self, or with another rod) that the node carries most of,
// whose other wire rests on a wall there (wall force at either node of its
// segment) and that moving the node by `move` would deepen, the deepest
// penetration now as a fraction of the pair's clearance (the two wires'
// radii), from the contacts of the last detection at the current
// positions; 0 when there is none.
double pinnedWireDepth(const State& state, int rod, int node, const Vec3& move);

}  // namespace coilsim
