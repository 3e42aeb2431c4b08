#include "physics/unilateral.h"

#include <algorithm>
#include <string>

namespace coilsim {
namespace {

using Normals = UnilateralScratch::Normals;
using Small = UnilateralScratch::Small;
using SmallSquare = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, 3, 3>;

// A node taken in when the solve carries it this far past its constraint, m:
// far below any contact skin, far above round-off.
constexpr double kPositionTolerance = 1e-9;
// A held constraint is released when its multiplier pulls by more than this, N.
constexpr double kPullTolerance = 1e-12;
// A normal within about 17 degrees of the span of a node's other held
// normals adds no direction of its own (two planes of one curved wall under
// one node): the most demanding of them is held, the others ride along.
constexpr double kIndependent = 0.3;

bool translationFixed(unsigned mask) { return (mask & 7u) != 0; }

void copyLeading(const BlockTridiagonal& from, BlockTridiagonal& to, int n) {
  std::copy(from.diag.begin(), from.diag.begin() + n, to.diag.begin());
  std::copy(from.lower.begin(), from.lower.begin() + std::max(0, n - 1), to.lower.begin());
}

}  // namespace

std::optional<Failure> solveUnilateral(BlockTridiagonal& A, std::vector<Vec6>& rhs, int n, double h,
                                       const std::vector<Vec6>* startVelocity, const std::vector<unsigned>& fixedMask,
                                       BlockTridiagonalSolver& solver, UnilateralScratch& s) {
  const std::vector<NodeConstraint>& c = s.constraints;
  const size_t m = c.size();
  if (s.free.size() < A.size()) s.free.resize(A.size());
  const size_t nodes = size_t(A.size());
  if (s.known.size() < nodes) s.known.resize(nodes), s.projector.resize(nodes);
  copyLeading(A, s.free, n);
  s.freeRhs.assign(rhs.begin(), rhs.begin() + n);
  // What each constraint asks of normal . dv: at the step's first iteration
  // the nodes are where they started and will move by h (v + dv); after
  // it, the iterate's positions already hold h v.
  s.target.resize(m);
  for (size_t j = 0; j < m; ++j) {
    s.target[j] = c[j].depth / h;
    if (startVelocity && c[j].node < n) s.target[j] -= c[j].normal.dot((*startVelocity)[c[j].node].head<3>());
  }
  if (startVelocity || s.active.size() != m) {
    s.active.assign(m, 0);
    for (size_t j = 0; j < m; ++j) s.active[j] = h * s.target[j] > -kPositionTolerance;
  }
  s.used.assign(m, 0);
  s.force.assign(m, 0.0);
  s.order.resize(m);
  for (size_t j = 0; j < m; ++j) s.order[j] = int(j);
  std::stable_sort(s.order.begin(), s.order.end(), [&](int a, int b) { return c[a].node < c[b].node; });
  for (size_t j = 0; j < m; ++j)
    if (c[j].node >= n || translationFixed(fixedMask[c[j].node])) s.active[j] = 0;

  std::vector<UnilateralScratch::NodeSet>& sets = s.sets;
  sets.clear();
  for (s.passes = 1; s.passes <= kMaxActiveSetPasses; ++s.passes) {
    // Back to the free system: only the last pass's constrained rows and columns changed.
    for (const UnilateralScratch::NodeSet& set : sets) {
      const int i = c[set.index[0]].node;
      A.diag[i] = s.free.diag[i];
      if (i > 0) A.lower[i - 1] = s.free.lower[i - 1];
      if (i + 1 < n) A.lower[i] = s.free.lower[i];
    }
    std::copy(s.freeRhs.begin(), s.freeRhs.end(), rhs.begin());
    std::fill(s.used.begin(), s.used.end(), 0);
    sets.clear();
    // Per node: the held constraints, most demanding first, made independent.
    for (size_t a = 0; a < m;) {
      const int node = c[s.order[a]].node;
      size_t b = a;
      while (b < m && c[s.order[b]].node == node) ++b;
      int held[8], count = 0;
      for (size_t q = a; q < b && count < 8; ++q)
        if (s.active[s.order[q]]) held[count++] = s.order[q];
      a = b;
      if (count == 0) continue;
      std::sort(held, held + count, [&](int x, int y) { return s.target[x] > s.target[y]; });
      UnilateralScratch::NodeSet set;
      set.n.resize(3, 0);
      set.target.resize(0);
      Normals q(3, 0);
      for (int i = 0; i < count && set.k < 3; ++i) {
        Vec3 rest = c[held[i]].normal;
        for (int j = 0; j < set.k; ++j) rest -= q.col(j).dot(rest) * q.col(j);
        if (rest.norm() < kIndependent) continue;
        set.n.conservativeResize(3, set.k + 1);
        q.conservativeResize(3, set.k + 1);
        set.target.conservativeResize(set.k + 1);
        set.n.col(set.k) = c[held[i]].normal;
        q.col(set.k) = rest.normalized();
        set.target[set.k] = s.target[held[i]];
        set.index[set.k++] = held[i];
        s.used[held[i]] = 1;
      }
      // dv = Q a + P y with N^T Q a = target.
      const SmallSquare nq = set.n.transpose() * q;
      const Small alpha = nq.partialPivLu().solve(set.target);
      s.known[node] = q * alpha;
      s.projector[node] = Mat3::Identity() - q * q.transpose();
      sets.push_back(set);
    }
    // Move the known parts to the right-hand side, then project rows and columns.
    for (const UnilateralScratch::NodeSet& set : sets) {
      const int i = c[set.index[0]].node;
      Vec6 u = Vec6::Zero();
      u.head<3>() = s.known[i];
      rhs[i] -= s.free.diag[i] * u;
      if (i > 0) rhs[i - 1] -= s.free.lower[i - 1].transpose() * u;
      if (i + 1 < n) rhs[i + 1] -= s.free.lower[i] * u;
    }
    for (const UnilateralScratch::NodeSet& set : sets) {
      const int i = c[set.index[0]].node;
      const Mat3& P = s.projector[i];
      Mat6& d = A.diag[i];
      d.topRows<3>() = P * d.topRows<3>();
      d.leftCols<3>() = d.leftCols<3>() * P;
      d.topLeftCorner<3, 3>() += Mat3::Identity() - P;
      rhs[i].head<3>() = P * rhs[i].head<3>();
      if (i > 0) A.lower[i - 1].topRows<3>() = P * A.lower[i - 1].topRows<3>();
      if (i + 1 < n) A.lower[i].leftCols<3>() = A.lower[i].leftCols<3>() * P;
    }
    if (!solver.factorize(A, n)) {
      Failure f = badRod("", "implicit matrix with wall constraints is not positive definite");
      f.kind = FailureKind::SolverFailure;
      return f;
    }
    solver.solve(rhs);
    for (const UnilateralScratch::NodeSet& set : sets) {
      const int i = c[set.index[0]].node;
      rhs[i].head<3>() += s.known[i];
    }
    // Nodes the solve carried past a constraint not held are taken in first;
    // only a solve that holds every node releases those that pull (doing
    // both at once lets coupled neighbours take turns for ever). After half
    // the passes nothing more is released: a node still pulling is held for
    // this step with no force (near-parallel planes of one node can hand the
    // hold to one another for ever), and taking in alone must settle.
    bool changed = false;
    for (size_t j = 0; j < m; ++j) {
      if (s.active[j] || c[j].node >= n || translationFixed(fixedMask[c[j].node])) continue;
      if (h * (s.target[j] - c[j].normal.dot(rhs[c[j].node].head<3>())) > kPositionTolerance) s.active[j] = 1, changed = true;
    }
    const bool release = !changed && s.passes <= kMaxActiveSetPasses / 2;
    // Multipliers from the reaction of the unconstrained rows: r = h N lambda.
    for (const UnilateralScratch::NodeSet& set : sets) {
      const int i = c[set.index[0]].node;
      Vec6 r = s.free.diag[i] * rhs[i] - s.freeRhs[i];
      if (i > 0) r += s.free.lower[i - 1] * rhs[i - 1];
      if (i + 1 < n) r += s.free.lower[i].transpose() * rhs[i + 1];
      const SmallSquare g = set.n.transpose() * set.n;
      const Small lambda = g.ldlt().solve(set.n.transpose() * r.head<3>()) / h;
      for (int j = 0; j < set.k; ++j) {
        s.force[set.index[j]] = lambda[j];
        if (release && lambda[j] < -kPullTolerance) s.active[set.index[j]] = 0, changed = true;
      }
    }
    if (!changed) {
      for (size_t j = 0; j < m; ++j)
        if (c[j].force) *c[j].force = s.used[j] ? std::max(0.0, s.force[j]) : 0.0;
      return std::nullopt;
    }
  }
  Failure f = badRod("", "wall constraints did not settle in " + std::to_string(kMaxActiveSetPasses) + " solves");
  f.kind = FailureKind::SolverFailure;
  return f;
}

}  // namespace coilsim
