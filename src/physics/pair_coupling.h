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
// coupling carries a tangential law), is added to the rods' bands A, and the
// whole system
//   (A + B^T Q B) dv = rhs
// of the rods the contacts touch is factorised as one sparse matrix
// (Eigen's simplicial LDL^T), its unknowns ordered by a fill-reducing AMD
// ordering of the graph of its nodes' translations and rotations, three
// unknowns each (the bands are chains, the contacts a few hundred links
// between them; ordering the 9 times larger graph of the unknowns
// themselves cost more than the factorisation). Conjugate
// gradients on its Schur complement on the contacts, tried first, needed
// up to 1000 iterations in a packing: the contacts' compliance 1 / (h^2 k)
// is 20 /kg against 1e7 /kg for a free node, and rows sharing nodes leave
// the complement badly conditioned for any diagonal preconditioner
// (docs/contact.md). Rods no contact touches are solved by their own band.
#include <memory>
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
  // Where the normal spring is measured from, for the force the solve
  // applied (reportSolvedPairForces): the clearance r1 + r2, and the
  // penetration at the iterate the rows were built at if its spring was off
  // there (closing, held), whose force is then only what the stiffness
  // added over the step; 0 if it was on.
  double radius = 0, springFrom = 0;  // m
};

// The coupled system's sparse matrix and factorisation, kept between
// solves so that their storage is reused and, while the matrix keeps its
// sparsity pattern, its symbolic analysis too (the same arithmetic as a
// fresh factorisation, so a run's result does not depend on it). A copy
// (a State copied for a plan candidate, a fit or a snapshot) starts empty.
class PairFactorCache {
 public:
  PairFactorCache();
  ~PairFactorCache();
  PairFactorCache(const PairFactorCache&);
  PairFactorCache& operator=(const PairFactorCache&);
  PairFactorCache(PairFactorCache&&) noexcept;
  PairFactorCache& operator=(PairFactorCache&&) noexcept;

  struct Impl;
  Impl& impl();  // created on first use

 private:
  std::unique_ptr<Impl> impl_;
};

// Scratch of the coupled solve, sized by use and kept between steps.
struct PairSolveScratch {
  struct Entry {
    int rod = 0, node = 0;
    Vec3 coeff = Vec3::Zero();  // beta's translational part at this node (fixed components zero)
  };
  struct Row {
    int first = 0, count = 0;  // entries[first, first + count)
    double stiffness = 0;      // q = h^2 k + h c in the velocity form, kg
  };
  std::vector<Entry> entries;
  std::vector<Row> rows;
  std::vector<char> touched;  // (nrod) rods that some row touches
  std::vector<int> firstNode; // (nrod) a touched rod's first node in the whole system's node numbering
  std::vector<int> slot;      // (2 x nodes of the touched rods) each node's translations' and rotations' place in the elimination order
  std::vector<char> stepped;  // (nrod) rods the step integrates (dynamics.cpp)
  PairFactorCache factor;
};

// Counters of the coupled solves, for the bench and the tests.
struct PairSolveStats {
  long solves = 0, rows = 0;
};

// The coupled solve of one step's rods. Each stepped rod k (stepped[k])
// has its system in work.system / work.rhs with its fixed DOFs applied and
// its pair couplings in work.pairs; on return work.rhs holds each rod's
// velocity increment. `firstIteration`: the rhs still lacks the couplings'
// h^2 K v term (dynamics.cpp's first Newton iteration). A matrix that is
// not positive definite is a SolverFailure.
std::optional<Failure> solvePairsCoupled(const Model& model, std::vector<RodState>& rods, std::span<const char> stepped,
                                         double h, bool firstIteration, PairSolveScratch& scratch, PairSolveStats& stats);

}  // namespace coilsim
