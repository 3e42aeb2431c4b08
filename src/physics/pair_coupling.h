#pragma once
// Self and rod contacts solved with both sides moving in one implicit step.
//
// A pair contact presses two segments (of one rod, or of two) apart. Its
// stiffness couples nodes that no rod's block-tridiagonal band holds. Lumped
// onto each side's diagonal (ContactLaw::implicitScale = 2, each side
// holding the other at its start), it acts as a drag of 2 k h on every
// side's own motion: a packing creeps instead of coming to rest, its wall
// carries 1.8-1.9 times its weight, and it erupts when round-off takes a
// contact out of the solve (docs/contact.md, "Why a settled packing creeps
// and erupts"). Here each contact's exact linearisation, a rank-one term
// per direction,
//   q beta beta^T,  beta = ((1 - s) d, s d, -(1 - t) d, -t d) on its four nodes,
// with q = h^2 k + h c along the normal d = n (and across it when a
// coupling carries a tangential law), is added to the rods' bands A and the whole system
//   (A + B^T Q B) dv = rhs
// is solved through its Schur complement on the contacts (Woodbury):
//   (Q^-1 + B A^-1 B^T) lambda = B A^-1 rhs,   dv = A^-1 (rhs - B^T lambda),
// by conjugate gradients, each product one back-substitution of every rod's
// own O(n) factorisation. Common motion of touching sides lies in B's null
// space: it no longer meets the penalty, only the rods' own inertia and
// stiffness (which is why the system on the contacts is well conditioned,
// where conjugate gradients on the whole system faced k against m / h^2).
#include <optional>
#include <span>
#include <vector>

#include "physics/failure.h"
#include "physics/math.h"

namespace coilsim {

struct Model;
struct RodState;

// One pair contact's coupling as its side's effect left it (response.cpp):
// this side's nodes a, a + 1 (weights 1 - s, s), the other side's b, b + 1
// (weights -(1 - t), -t), the normal pushing this side, and the law's
// stiffness and damping along it and across it (across: friction's, which
// the contact effects leave at 0 for now, their friction lumped).
struct PairCoupling {
  int otherRod = 0;
  int segment = 0, otherSegment = 0;
  double s = 0, otherS = 0;
  Vec3 normal = Vec3::UnitZ();
  double normalStiffness = 0, normalDamping = 0;    // N/m, N s/m
  double tangentStiffness = 0, tangentDamping = 0;  // N/m, N s/m
};

// Scratch of the coupled solve, sized by use and kept between steps.
struct PairSolveScratch {
  struct Entry {
    int rod = 0, node = 0;
    Vec3 coeff = Vec3::Zero();  // beta's translational part at this node (fixed components zero)
  };
  struct Row {
    int first = 0, count = 0;   // entries[first, first + count)
    double compliance = 0;      // 1 / q, 1/kg (q = h^2 k + h c in the velocity form)
    double diagonal = 0;        // the preconditioner's estimate of the Schur complement's diagonal
  };
  std::vector<Entry> entries;
  std::vector<Row> rows;
  std::vector<double> lambda, residual, direction, product, precond;
  std::vector<std::vector<Vec6>> work;  // (nrod) one back-substitution's right-hand side per rod
  std::vector<char> touched;            // (nrod) rods that some row touches
  std::vector<char> stepped;            // (nrod) rods the step integrates (dynamics.cpp)
};

// Counters of the coupled solves, for the bench and the tests.
struct PairSolveStats {
  long solves = 0, rows = 0, iterations = 0;
  int maxIterations = 0;
};

// The coupled solve of one step's rods. Each stepped rod k (stepped[k])
// has its system in work.system / work.rhs with its fixed DOFs applied and
// its pair couplings in work.pairs; on return work.rhs holds each rod's
// velocity increment. `firstIteration`: the rhs still lacks the couplings'
// h^2 K v term (dynamics.cpp's first Newton iteration). A rod whose matrix
// is not positive definite, or conjugate gradients that do not converge,
// is a SolverFailure.
std::optional<Failure> solvePairsCoupled(const Model& model, std::vector<RodState>& rods, std::span<const char> stepped,
                                         double h, bool firstIteration, PairSolveScratch& scratch, PairSolveStats& stats);

}  // namespace coilsim
