#include <cmath>

#include "physics/assembly.h"
#include "physics/integrator.h"

namespace coilsim {
namespace {

// Puts constrained DOFs at their targets (position and, if all three
// rotations are held, rotation).
void snapToTargets(const RodModel& rm, RodState& r) {
  for (size_t k = 0; k < rm.constraints.size(); ++k) {
    const Constraint& c = rm.constraints[k];
    for (int d = 0; d < 3; ++d)
      if (c.mask & (1u << d)) r.x[c.node][d] = r.targets[k].position[d];
    if ((c.mask & kRotation) == kRotation) r.q[c.node] = r.targets[k].rotation;
  }
}

enum class NewtonResult { Converged, NotConverged, Singular, Unhealthy };

NewtonResult newton(const Model& model, int k, RodState& r, double lambda, const StaticOptions& o, int& iterations) {
  const RodModel& rm = model.rods[k];
  RodWorkspace& w = r.work;
  double length = 0;
  for (const BeamRest& b : rm.beams) length += b.length;
  for (int it = 0; it < o.maxIterations; ++it) {
    ++iterations;
    assembleRod(model, k, r, 0.0, lambda, true);
    BlockTridiagonal& A = w.system;
    for (int i = 0; i < rm.nnode; ++i) {
      A.diag[i] = w.stiffness.diag[i];
      if (w.effectsTouchedMatrix) A.diag[i] += w.effectK[i];
      w.rhs[i] = w.force[i];
    }
    for (int e = 0; e + 1 < rm.nnode; ++e) A.lower[e] = w.stiffness.lower[e];
    for (int i = 0; i < rm.nnode; ++i)
      for (int d = 0; d < 6; ++d)
        if (w.fixedMask[i] & (1u << d)) applyDirichlet(A, w.rhs, i, d, 0.0);
    if (!w.solver.factorize(A)) return NewtonResult::Singular;
    w.solver.solve(w.rhs);
    double dx = 0, dr = 0;
    for (int i = 0; i < rm.nnode; ++i) {
      r.x[i] += w.rhs[i].head<3>();
      r.q[i] = (quatExp(w.rhs[i].tail<3>()) * r.q[i]).normalized();
      dx = std::max(dx, w.rhs[i].head<3>().norm());
      dr = std::max(dr, w.rhs[i].tail<3>().norm());
    }
    if (!std::isfinite(dx) || !std::isfinite(dr)) return NewtonResult::Unhealthy;
    if (dx < o.positionTolerance * length && dr < o.rotationTolerance) return NewtonResult::Converged;
  }
  return NewtonResult::NotConverged;
}

}  // namespace

StaticReport solveStatic(const Model& model, State& state, const StaticOptions& o) {
  StaticReport rep;
  for (size_t k = 0; k < model.rods.size(); ++k) {
    const RodModel& rm = model.rods[k];
    RodState& r = state.rods[k];
    if (rm.constraints.empty()) {
      rep.message = "rod '" + rm.name + "' has no constraint: its static equilibrium is not defined";
      return rep;
    }
    std::fill(r.v.begin(), r.v.end(), Vec3::Zero());
    std::fill(r.w.begin(), r.w.end(), Vec3::Zero());
    collectFixedDofs(rm, r);
    snapToTargets(rm, r);
    double lambda = 0, increment = 1.0 / std::max(1, o.loadSteps);
    int bisections = 0;
    while (lambda < 1.0 - 1e-14) {
      const double next = std::min(1.0, lambda + increment);
      const std::vector<Vec3> x0 = r.x;
      const std::vector<Quat> q0 = r.q;
      const NewtonResult res = newton(model, int(k), r, next, o, rep.iterations);
      ++rep.increments;
      if (res == NewtonResult::Converged && checkHealth(model, state).empty()) {
        lambda = next;
        continue;
      }
      r.x = x0, r.q = q0;
      if (res == NewtonResult::Singular) {
        rep.message = "rod '" + rm.name + "': stiffness matrix is singular (is the rod held enough?)";
        return rep;
      }
      if (++bisections > o.maxBisections) {
        rep.message = "rod '" + rm.name + "': Newton did not converge at load factor " + std::to_string(next) +
                      " after " + std::to_string(o.maxBisections) + " bisections of the load increment";
        return rep;
      }
      increment *= 0.5;
    }
  }
  rep.converged = true;
  return rep;
}

}  // namespace coilsim
