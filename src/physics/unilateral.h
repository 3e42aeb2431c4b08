#pragma once
// Unilateral constraints on single nodes inside the one block-tridiagonal
// solve of a rod's implicit step (wall contacts held as constraints,
// docs/contact.md "Why a constraint per node against the wall").
//
// A constrained node's velocity change dv_i is split along the constraint
// normals N (3 x k, k <= 3 independent directions) and across them,
// dv_i = u_i + P_i y_i, with u_i fixing N^T dv_i to the targets and
// P_i = I - Q Q^T (Q an orthonormal basis of N) the free part. The system
// A dv = b then becomes (Pi A Pi + (I - Pi)) y = Pi (b - A u), a change of
// variables per node: every block stays where it was, so the matrix is
// still block tridiagonal, symmetric positive definite, and one O(n) block
// Cholesky solves it (the filtered system of Baraff and Witkin, SIGGRAPH
// 1998, solved directly instead of by conjugate gradients). The reaction
// (A dv - b)_i lies in the span of N; its components are the multipliers
// times h. Active set: a constraint is held while its multiplier pushes,
// released when it pulls (only once no node is carried past a constraint),
// and taken in when the solve carries its node past it; repeated until
// nothing changes (kMaxActiveSetPasses), else a Failure.
//
// Friction on a held node (NodeConstraint::friction) goes into the same
// solve, in the node's free directions P_i: a stick spring on the stretch
// the step ends with, implicit, or while sliding the secant of Coulomb's
// law through that stretch, mu_d lambda / |stretch|. Its cap is the node's
// multiplier from the same solve: the solve is repeated (a staggered
// normal / tangential fixed point, at most kMaxFrictionSolves times) until
// stick or slide, decided on that multiplier and on the stretch the solve
// gave, is what the solve assumed, and a sliding node's force is within
// kFrictionTolerance of mu_d lambda. When a held plane is released, the
// node's planes that rode along with it are released too.
#include <optional>
#include <vector>

#include "physics/block_tridiagonal.h"
#include "physics/effect.h"
#include "physics/failure.h"

namespace coilsim {

// Solves of one step at most before the active set is declared unsettled.
inline constexpr int kMaxActiveSetPasses = 16;
// A sliding node's friction is taken as found when the solve's multiplier
// and stretch give a force within this fraction of the one it assumed
// (the penalty's secant erred by 1 % at the start of a slide, response.h).
inline constexpr double kFrictionTolerance = 1e-2;
// Solves repeated for friction alone at most per call: a node on the edge
// of its cone can flip stick and slide on every solve; the last solve's
// friction then stands (regularised Coulomb: a creep of micrometres).
// Two leave a node that a step stops from sliding 8 % of its speed where
// the stick spring's exact answer leaves 1 % (three reach it, but cost more
// passes; docs/contact.md).
inline constexpr int kMaxFrictionSolves = 2;

// What the constrained solve keeps per rod; sized on first use, reused.
struct UnilateralScratch {
  using Normals = Eigen::Matrix<double, 3, Eigen::Dynamic, 0, 3, 3>;
  using Small = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, 3, 1>;
  // The held, independent constraints of one node: their normals, targets
  // (normal . dv, m/s) and indices.
  struct NodeSet {
    Normals n;
    Small target;
    int index[3] = {-1, -1, -1};
    int k = 0;
    int from = 0, to = 0;  // the node's constraints: order[from, to)
  };
  std::vector<NodeConstraint> constraints;  // this assembly's, in the order the effects gave them
  std::vector<char> active;                 // (constraints) held; kept over the step's Newton iterations
  std::vector<char> used;                   // (constraints) held and independent of the node's others
  std::vector<double> force;                // (constraints) multipliers of the last solve, N
  std::vector<double> target;               // (constraints) least normal . dv, m/s
  std::vector<int> order;                   // constraint indices sorted by node
  BlockTridiagonal free;                    // the system before the constraints
  std::vector<Vec6> freeRhs;
  std::vector<Vec3> known;                  // (nnode) u: the velocity change fixed along the normals
  std::vector<Mat3> projector;              // (nnode) P_i (identity for a free node)
  std::vector<NodeSet> sets;                // this solve's nodes with held constraints
  // One node's friction in this call: its constants, the memory the last
  // step left, the normal force and end-of-step stretch the next solve
  // assumes, and what the last solve assumed.
  struct NodeFrictionState {
    int node = -1;
    double muStatic = 0, muDynamic = 0, stiffness = 0, damping = 0;
    Vec3 start = Vec3::Zero();  // the stick spring's stretch at the step's start, m
    bool slidBefore = false;    // it slid at the last step: the dynamic cap holds it
    double force = 0;           // N
    Vec3 ahead = Vec3::Zero();  // m
    bool solved = false;        // `ahead` is a solve's, not the start velocity's prediction
    bool held = false;          // in this solve's active set, in at most two directions
    bool applied = false, stick = true;
    double appliedForce = 0, appliedAhead = 0;
  };
  std::vector<NodeFrictionState> friction;  // nodes with constraints that carry friction
  std::vector<int> frictionOf;              // (nnode) index into friction, or -1
  std::vector<double> nodeForce;            // (nnode) a node's multipliers summed, N; kept over the step's iterations
  // (nnode) the part of a held node's velocity change that carries it out
  // of a wall it started the step in (depth / h along the normals), m/s:
  // set on the step's first iteration, zero for nodes not held.
  std::vector<Vec3> recovery;
  int passes = 0;                           // solves in the last call
};

// Solves A dv = rhs (rhs becomes dv) for the leading n nodes with the
// constraints in s.constraints for a step of length h: constraint j asks
// normal . dv >= depth / h of its node, less normal . v on the step's
// first Newton iteration (`first`), whose positions are the start's and
// move by h (v + dv); the active set then starts from the nodes that
// velocity carries in, later iterations from the last one's. `velocity`
// is the iterate's (v, w) per node, whose positions are the start's plus
// h v; without it (nullptr) the targets are depth / h alone and friction
// is left out. Nodes with a prescribed translation (fixedMask bits 0-2)
// are not constrained. Writes each constraint's multiplier to *force (0
// when not held) and each friction's memory to its `end`. On failure (a
// matrix that does not factorise, an active set that does not settle)
// returns the Failure (kind SolverFailure; the step is then taken in
// substeps by the caller) and leaves rhs unusable.
std::optional<Failure> solveUnilateral(BlockTridiagonal& A, std::vector<Vec6>& rhs, int n, double h,
                                       const std::vector<Vec6>* velocity, bool first,
                                       const std::vector<unsigned>& fixedMask, BlockTridiagonalSolver& solver,
                                       UnilateralScratch& s);

}  // namespace coilsim
