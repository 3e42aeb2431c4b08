#pragma once
// Time stepping and static equilibrium. Both take a Model and a State and
// change only the State. A refused step leaves the rods as they were before
// it; a static solve that fails leaves the last converged load increment
// (what a user wants to look at), and its report says so (solveStatic).
#include <optional>
#include <string>

#include "physics/failure.h"
#include "physics/model.h"
#include "physics/state.h"

namespace coilsim {

struct StepReport {
  std::optional<Failure> failure;  // why the step was refused (BlowUp, SolverFailure, MissedContact), with its time
  bool ok() const { return !failure; }
  std::string message() const { return failure ? failure->message() : std::string(); }
};

// One implicit Euler step of length model.timeStep (Baraff & Witkin 1998
// linearisation, plus model.newtonIterations - 1 further Newton iterations):
//   [(1 + h a) M + h D_eff + (h b + h^2) K] dv = h (f - (a M + b K + D_eff) v - h K v)
// with Rayleigh damping a M + b K, solved per rod by the O(n) block
// tridiagonal Cholesky. Constrained DOFs move to their targets. A step that
// leaves an element stretched by more than 5 % (a linearised step turns an
// element along a chord, not an arc) or whose result is unhealthy is taken
// again in 2, 4 ... 64 substeps (state.substepped counts it). If the result
// is still not finite, too fast or too strained, the step is refused: the
// State is restored, state.blowups is counted and a warning is recorded once.
StepReport step(const Model& model, State& state);

// Advances every constraint target of the model's prescribed motion by dt.
void advanceTargets(const Model& model, State& state, double dt);

struct StaticOptions {
  int loadSteps = 10;          // equal load increments from 0 to full load
  int maxIterations = 60;      // Newton iterations per increment
  int maxBisections = 10;      // halvings of a failed increment
  double positionTolerance = 1e-10;  // relative to rod length, per iteration update
  double rotationTolerance = 1e-9;   // rad
};

struct StaticReport {
  int increments = 0;   // load increments taken (including bisected ones)
  int iterations = 0;   // Newton iterations in all
  double loadFactor = 0;  // of the last rod solved: the last converged increment (1 when converged)
  std::optional<Failure> failure;  // why it failed (NotConverged): the rod, and where it was left
  bool converged() const { return !failure; }
  std::string message() const { return failure ? failure->message() : std::string(); }
};

// Static equilibrium under the full load (gravity, loads, effects), reached
// by load stepping with Newton iterations on the co-rotational tangent;
// failing increments are bisected. Velocities are zeroed. Contacts are
// detected again before every Newton iteration and act frictionless, with
// their stiffness between distant nodes (a general sparse solve then) and a
// penalty smoothed over a thousandth of the contact distance (contact/
// response.cpp); no iteration carries a segment through another.
// On failure: a model it cannot solve (a rod without constraint) is refused
// before anything changes, so the State is as it was; a rod whose Newton
// iterations fail keeps its last converged increment (report.loadFactor),
// the rods before it their equilibrium, those after it their old poses,
// and the message names the rod and the load factor it was left at.
StaticReport solveStatic(const Model& model, State& state, const StaticOptions& options = {});

struct Energy {
  double kinetic = 0, elastic = 0, potential = 0;  // J
  double total() const { return kinetic + elastic + potential; }
};
Energy computeEnergy(const Model& model, const State& state);

// Nothing when the state is healthy, else what is wrong (a BlowUp naming the
// rod, node or beam, the quantity, its value and the limit).
std::optional<Failure> checkHealth(const Model& model, const State& state);

}  // namespace coilsim
