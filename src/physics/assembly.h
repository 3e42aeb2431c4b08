#pragma once
// Generalised forces and tangent of one rod at its current poses: elastic
// beams, nodal loads and every enabled effect. Shared by the dynamic step and
// the static solver.
#include "physics/model.h"
#include "physics/state.h"

namespace coilsim {

// Fills rod.work.force (all forces, external ones scaled by loadFactor),
// rod.work.stiffness (elastic tangent, if withTangent), work.effectK and
// work.effectD. Returns the elastic energy (J).
double assembleRod(const Model& model, int rodIndex, RodState& rod, double time, double loadFactor, bool withTangent);

// Rotational inertia of node i about global axes: R I_material R^T.
Mat3 nodeInertiaGlobal(const RodState& rod, const Quat& q, int node);

// Marks the DOFs held by constraints in work.fixedMask (positions and
// rotations per DOF), so solvers can pin them.
void collectFixedDofs(const RodModel& model, RodState& rod);

}  // namespace coilsim
