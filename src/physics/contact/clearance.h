#pragma once
// How far a point is from the walls (the obstacles that take part in
// contact): for the device, which must not drive what it holds into a wall.
#include "physics/math.h"
#include "physics/model.h"

namespace coilsim {

// The least distance from `p` to a triangle of an obstacle with contact on,
// or `reach` when none is nearer than that (m).
double wallClearance(const Model& model, const Vec3& p, double reach);

}  // namespace coilsim
