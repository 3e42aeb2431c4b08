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

// What the dynamic step wants of the elastic tangent: (h b + h^2) K written
// straight into its implicit matrix, and that matrix times the current
// velocities for its right-hand side, both in the one pass over the beams.
struct TangentRequest {
  BlockTridiagonal* matrix = nullptr;            // receives scale K
  double scale = 1.0;
  const std::vector<Vec6>* velocity = nullptr;   // (v, w) per node; if set,
  std::vector<Vec6>* product = nullptr;          // product = scale K velocity
};

// assembleRod with the tangent going where `tangent` says instead of
// work.stiffness, for a dynamic step of length h.
double assembleRodInto(const Model& model, int rodIndex, RodState& rod, double time, double h, double loadFactor,
                       const TangentRequest& tangent);

// For the static solver: forces at load factor `loadFactor` with the effects
// told it is a static solve (SolveKind::Static, RodForces::coupling set), no elastic tangent,
// and the effects' couplings between nodes collected in `coupling` (cleared
// first). Returns the elastic energy (J).
double assembleRodStatic(const Model& model, int rodIndex, RodState& rod, double loadFactor,
                         std::vector<NodeCoupling>& coupling);

// Rotational inertia of node i about global axes: R I_material R^T. Inline:
// the dynamic step calls it for every node.
inline Mat3 nodeInertiaGlobal(const RodState& rod, const Quat& q, int node) {
  const Vec3& d = rod.nodes[node].inertia;  // (t, d1, d2)
  // Round wire: R diag(It, I, I) R^T = I 1 + (It - I) t t^T, with t the
  // tangent; a fifth of the general product, and this runs for every node.
  if (d[1] == d[2]) {
    const Vec3 t = q * Vec3::UnitX();
    Mat3 out = (d[0] - d[1]) * (t * t.transpose());
    out.diagonal().array() += d[1];
    return out;
  }
  const Mat3 r = q.toRotationMatrix();
  return r * d.asDiagonal() * r.transpose();
}


// Marks the DOFs held by constraints in work.fixedMask (positions and
// rotations per DOF), so solvers can pin them.
void collectFixedDofs(const RodModel& model, RodState& rod);

}  // namespace coilsim
