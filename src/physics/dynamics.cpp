#include <chrono>
#include <cmath>

#include "physics/assembly.h"
#include "physics/integrator.h"

namespace coilsim {
namespace {

void saveStart(RodState& r) {
  RodWorkspace& w = r.work;
  w.x0 = r.x, w.q0 = r.q, w.v0 = r.v, w.w0 = r.w;
}

void restoreStart(RodState& r) {
  const RodWorkspace& w = r.work;
  r.x = w.x0, r.q = w.q0, r.v = w.v0, r.w = w.w0;
}

// Generalised velocity each constrained node must have to reach its target
// at the end of the step.
void prescribedVelocities(const RodModel& rm, RodState& r, double h) {
  RodWorkspace& w = r.work;
  for (size_t k = 0; k < rm.constraints.size(); ++k) {
    const int i = rm.constraints[k].node;
    const Pose& t = r.targets[k];
    w.fixedValue[i].head<3>() = (t.position - w.x0[i]) / h;
    w.fixedValue[i].tail<3>() = quatLog(t.rotation * w.q0[i].conjugate()) / h;
  }
}

// Poses at the end of the step for the current velocity guess.
void integratePoses(RodState& r, double h) {
  const RodWorkspace& w = r.work;
  for (size_t i = 0; i < r.x.size(); ++i) {
    r.x[i] = w.x0[i] + h * r.v[i];
    r.q[i] = (quatExp(h * r.w[i]) * w.q0[i]).normalized();
  }
}

StepReport stepRod(const Model& model, int rodIndex, RodState& r, double time, long& iterations) {
  const RodModel& rm = model.rods[rodIndex];
  RodWorkspace& w = r.work;
  const double h = model.timeStep, a = model.damping.massCoeff, b = model.damping.stiffnessCoeff;
  const int n = rm.nnode;
  collectFixedDofs(rm, r);
  prescribedVelocities(rm, r, h);

  for (int it = 0; it < model.newtonIterations; ++it) {
    ++iterations;
    assembleRod(model, rodIndex, r, time + h, 1.0, true);
    BlockTridiagonal& A = w.system;
    const BlockTridiagonal& K = w.stiffness;
    for (int i = 0; i < n; ++i) {
      Mat6 mass = Mat6::Zero();
      mass.topLeftCorner<3, 3>().diagonal().setConstant(rm.nodeMass[i]);
      mass.bottomRightCorner<3, 3>() = nodeInertiaGlobal(rm, w.q0[i], i);
      Vec6 vel;
      vel << r.v[i], r.w[i];
      w.velocity[i] = vel;
      const Mat6 kTotal = K.diag[i] + w.effectK[i];
      A.diag[i] = (1 + h * a) * mass + h * w.effectD[i] + (h * b + h * h) * K.diag[i] + h * h * w.effectK[i];
      // Damping force of the diagonal part; the off-diagonal stiffness part is added below.
      Vec6 rhs = w.force[i] - (a * mass + b * K.diag[i] + w.effectD[i]) * vel;
      if (it == 0) {
        rhs -= h * kTotal * vel;  // Baraff-Witkin: forces at x0 + h v1, linearised
      } else {
        Vec6 v0;
        v0 << w.v0[i], w.w0[i];
        rhs -= mass * (vel - v0) / h;
      }
      w.rhs[i] = h * rhs;
    }
    for (int e = 0; e + 1 < n; ++e) {
      A.lower[e] = (h * b + h * h) * K.lower[e];
      // Off-diagonal coupling: K(e+1,e) v_e acts on e+1, K(e,e+1) v_{e+1} on e.
      const double c = h * (b + (it == 0 ? h : 0.0));
      w.rhs[e + 1] -= c * K.lower[e] * w.velocity[e];
      w.rhs[e] -= c * K.lower[e].transpose() * w.velocity[e + 1];
    }
    for (int i = 0; i < n; ++i) {
      const unsigned m = w.fixedMask[i];
      if (!m) continue;
      for (int d = 0; d < 6; ++d)
        if (m & (1u << d)) applyDirichlet(A, w.rhs, i, d, w.fixedValue[i][d] - w.velocity[i][d]);
    }
    if (!w.solver.factorize(A))
      return {StepStatus::SolverFailure, "rod '" + rm.name + "': implicit matrix is not positive definite"};
    w.solver.solve(w.rhs);
    for (int i = 0; i < n; ++i) {
      r.v[i] += w.rhs[i].head<3>();
      r.w[i] += w.rhs[i].tail<3>();
    }
    integratePoses(r, h);
  }
  return {};
}

}  // namespace

void advanceTargets(const Model& model, State& state, double dt) {
  for (size_t k = 0; k < model.rods.size(); ++k) {
    const RodModel& rm = model.rods[k];
    for (size_t c = 0; c < rm.constraints.size(); ++c) {
      Pose& t = state.rods[k].targets[c];
      t.position += rm.constraints[c].velocity * dt;
      t.rotation = (quatExp(rm.constraints[c].angularVelocity * dt) * t.rotation).normalized();
    }
  }
}

StepReport step(const Model& model, State& state) {
  const auto start = std::chrono::steady_clock::now();
  for (RodState& r : state.rods) saveStart(r);
  advanceTargets(model, state, model.timeStep);
  StepReport report;
  long iterations = 0;
  for (size_t k = 0; k < model.rods.size() && report.ok(); ++k)
    report = stepRod(model, int(k), state.rods[k], state.time, iterations);
  if (report.ok()) {
    const std::string problem = checkHealth(model, state);
    if (!problem.empty()) report = {StepStatus::BlowUp, problem};
  }
  if (!report.ok()) {
    for (RodState& r : state.rods) restoreStart(r);
    advanceTargets(model, state, -model.timeStep);
    ++state.blowups;
    warnOnce(state, "step refused at t = " + std::to_string(state.time) + " s: " + report.message);
  } else {
    state.time += model.timeStep;
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  StepStats& s = state.stats;
  ++s.steps;
  s.newtonIterations += iterations;
  s.lastStepSeconds = seconds;
  s.totalStepSeconds += seconds;
  s.maxStepSeconds = std::max(s.maxStepSeconds, seconds);
  return report;
}

}  // namespace coilsim
