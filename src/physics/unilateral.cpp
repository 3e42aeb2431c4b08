#include "physics/unilateral.h"

#include <algorithm>
#include <cmath>
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
// The cosine within which a plane rides along with another: its normal's
// part across the other's is below kIndependent.
const double kRidesAlong = std::sqrt(1 - kIndependent * kIndependent);

bool translationFixed(unsigned mask) { return (mask & 7u) != 0; }

// Keeps the blocks a constraint on node i can change (row and column i:
// diag i, lower i - 1 and i) of the leading n nodes, once per node
// (`byNode`: constraint indices sorted by node); the solve reads and
// restores no others, so the rest of the band is not copied.
void keepConstrainedBlocks(const BlockTridiagonal& from, BlockTridiagonal& to, int n,
                           const std::vector<NodeConstraint>& c, const std::vector<int>& byNode) {
  int last = -1;
  for (const int j : byNode) {
    const int i = c[j].node;
    if (i >= n || i == last) continue;
    last = i;
    to.diag[i] = from.diag[i];
    if (i > 0) to.lower[i - 1] = from.lower[i - 1];
    if (i + 1 < n) to.lower[i] = from.lower[i];
  }
}

using Friction = UnilateralScratch::NodeFrictionState;

// One entry per node whose constraints carry friction: the largest of
// their constants, the longest remembered stretch (a contact new this step
// remembers none) and the force the first solve assumes, the last step's
// on the step's first iteration, the last iteration's after it.
void gatherFriction(int n, bool first, const std::vector<unsigned>& fixedMask, UnilateralScratch& s) {
  s.friction.clear();
  if (s.frictionOf.size() < s.known.size()) s.frictionOf.resize(s.known.size()), s.nodeForce.resize(s.known.size());
  std::fill(s.frictionOf.begin(), s.frictionOf.begin() + n, -1);
  for (const int j : s.order) {
    const NodeConstraint& c = s.constraints[j];
    if (c.node >= n || translationFixed(fixedMask[c.node]) || !c.friction.any()) continue;
    if (s.frictionOf[c.node] < 0) {
      s.frictionOf[c.node] = int(s.friction.size());
      s.friction.push_back({});
      s.friction.back().node = c.node;
      if (!first) s.friction.back().force = s.nodeForce[c.node];
    }
    Friction& f = s.friction[s.frictionOf[c.node]];
    const NodeFriction& g = c.friction;
    f.muStatic = std::max(f.muStatic, g.muStatic), f.muDynamic = std::max(f.muDynamic, g.muDynamic);
    f.stiffness = std::max(f.stiffness, g.stiffness), f.damping = std::max(f.damping, g.damping);
    if (g.start.stretch.squaredNorm() > f.start.squaredNorm()) f.start = g.start.stretch;
    f.slidBefore = f.slidBefore || g.start.sliding;
    if (first) f.force = std::max(f.force, g.start.force);
  }
}

// Adds node i's friction, for the normal force and end-of-step stretch
// assumed, to its projected rows: the force at the step's end is linear in
// dv, f = -k_t P (s0 + h (v + dv)) - c_t P (v + dv) while sticking, or
// -sigma P (s0 + h (v + dv)) with sigma = mu_d lambda / |stretch| while
// sliding; -df/d(dv) goes to the matrix (times h), f at dv = 0 to the
// right-hand side (times h). Both lie in P's range, so the projection keeps them.
void addFriction(Friction& f, const Mat3& P, const Vec3& v, double h, BlockTridiagonal& A, Vec6& rhs) {
  const Vec3 base = P * (f.start + h * v);
  const Vec3 ahead = f.solved ? f.ahead : base;
  const double limit = (f.slidBefore ? f.muDynamic : f.muStatic) * f.force;
  f.stick = f.stiffness * ahead.norm() <= limit * (1 + 1e-9);
  f.applied = true, f.appliedForce = f.force, f.appliedAhead = ahead.norm();
  if (f.stick) {
    A.diag[f.node].topLeftCorner<3, 3>() += (h * h * f.stiffness + h * f.damping) * P;
    rhs.head<3>() -= h * (f.stiffness * base + f.damping * (P * v));
  } else {
    const double sigma = f.muDynamic * f.force / ahead.norm();
    A.diag[f.node].topLeftCorner<3, 3>() += h * h * sigma * P;
    rhs.head<3>() -= h * sigma * base;
  }
}

// Whether the solve's normal force and stretch agree with what its
// friction assumed (then it stands), updating what the next solve assumes.
bool frictionSettled(Friction& f, double force, const Vec3& stretch) {
  f.force = force;
  // A solve without this node's friction (no normal force assumed yet, as
  // at a contact's first step) says nothing of the stretch friction will
  // allow: the next one predicts it from the start velocity again.
  if (!f.applied) return !(force > 0);
  f.ahead = stretch, f.solved = true;
  if (!(force > 0)) return false;
  const double limit = (f.slidBefore ? f.muDynamic : f.muStatic) * force;
  const bool stick = f.stiffness * stretch.norm() <= limit * (1 + 1e-9);
  if (stick != f.stick) return false;
  if (stick) return true;
  const double assumed = f.appliedForce / std::max(f.appliedAhead, 1e-300), found = force / stretch.norm();
  return std::abs(assumed - found) <= kFrictionTolerance * found;
}

// What the step leaves a node's friction: its stretch, cut to the dynamic
// cone while sliding, its normal force and whether it slid.
NodeFrictionMemory memoryOf(const Friction& f) {
  NodeFrictionMemory m;
  if (!(f.force > 0)) return m;
  m.force = f.force;
  m.stretch = f.ahead;
  const double limit = (f.slidBefore ? f.muDynamic : f.muStatic) * f.force;
  m.sliding = f.stiffness * f.ahead.norm() > limit * (1 + 1e-9);
  if (m.sliding) m.stretch *= f.muDynamic * f.force / (f.stiffness * f.ahead.norm());
  return m;
}

}  // namespace

std::optional<Failure> solveUnilateral(BlockTridiagonal& A, std::vector<Vec6>& rhs, int n, double h,
                                       const std::vector<Vec6>* velocity, bool first,
                                       const std::vector<unsigned>& fixedMask, BlockTridiagonalSolver& solver,
                                       UnilateralScratch& s) {
  const std::vector<Vec6>* startVelocity = first ? velocity : nullptr;
  const std::vector<NodeConstraint>& c = s.constraints;
  const size_t m = c.size();
  if (s.free.size() < A.size()) s.free.resize(A.size());
  const size_t nodes = size_t(A.size());
  if (s.known.size() < nodes) s.known.resize(nodes), s.projector.resize(nodes);
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
  keepConstrainedBlocks(A, s.free, n, c, s.order);
  for (size_t j = 0; j < m; ++j)
    if (c[j].node >= n || translationFixed(fixedMask[c[j].node])) s.active[j] = 0;
  s.friction.clear();
  if (velocity) gatherFriction(n, first, fixedMask, s);
  if (first) {
    if (s.recovery.size() < nodes) s.recovery.resize(nodes);
    std::fill(s.recovery.begin(), s.recovery.begin() + n, Vec3::Zero());
  }

  std::vector<UnilateralScratch::NodeSet>& sets = s.sets;
  sets.clear();
  int resolvedForFriction = 0;
  for (s.passes = 1; s.passes <= kMaxActiveSetPasses; ++s.passes) {
    // Back to the free system: only the last pass's constrained rows and columns changed.
    for (const UnilateralScratch::NodeSet& set : sets) {
      const int i = c[set.index[0]].node;
      A.diag[i] = s.free.diag[i];
      if (i > 0) A.lower[i - 1] = s.free.lower[i - 1];
      if (i + 1 < n) A.lower[i] = s.free.lower[i];
    }
    std::copy(s.freeRhs.begin(), s.freeRhs.end(), rhs.begin());
    if (first)
      for (const UnilateralScratch::NodeSet& set : sets) s.recovery[c[set.index[0]].node].setZero();
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
      const size_t from = a;
      a = b;
      if (count == 0) continue;
      std::sort(held, held + count, [&](int x, int y) { return s.target[x] > s.target[y]; });
      UnilateralScratch::NodeSet set;
      set.from = int(from), set.to = int(b);
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
      const auto lu = nq.partialPivLu();
      const Small alpha = lu.solve(set.target);
      s.known[node] = q * alpha;
      if (first) {
        Small depth(set.k);
        for (int j = 0; j < set.k; ++j) depth[j] = std::max(0.0, c[set.index[j]].depth) / h;
        s.recovery[node] = q * lu.solve(depth);
      }
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
    // Friction on the held nodes, for the force and stretch the last solve gave.
    for (Friction& f : s.friction) f.applied = f.held = false;
    for (const UnilateralScratch::NodeSet& set : sets) {
      const int i = c[set.index[0]].node;
      if (s.friction.empty() || s.frictionOf[i] < 0 || set.k == 3) continue;
      Friction& f = s.friction[s.frictionOf[i]];
      f.held = true;
      if (f.force > 0) addFriction(f, s.projector[i], (*velocity)[i].head<3>(), h, A, rhs[i]);
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
        if (!release || !(lambda[j] < -kPullTolerance)) continue;
        s.active[set.index[j]] = 0, changed = true;
        // The planes that rode along with it go too: held, the next solve
        // would hand the hold to one of them, which pulls as it did, and
        // the node's planes would take turns until releasing stops.
        const Vec3& nj = c[set.index[j]].normal;
        for (int q = set.from; q < set.to; ++q) {
          const int o = s.order[q];
          if (s.active[o] && !s.used[o] && c[o].normal.dot(nj) > kRidesAlong) s.active[o] = 0;
        }
      }
    }
    // Friction against the multipliers just found; while the active set
    // still settles, a friction that disagrees takes another solve.
    if (!s.friction.empty()) {
      for (const Friction& f : s.friction) s.nodeForce[f.node] = 0;
      for (const UnilateralScratch::NodeSet& set : sets)
        for (int j = 0; j < set.k; ++j) s.nodeForce[c[set.index[j]].node] += std::max(0.0, s.force[set.index[j]]);
      bool settled = true;
      for (Friction& f : s.friction) {
        if (!f.held) {
          settled = !f.applied && settled;
          f.force = 0, f.solved = false;
          continue;
        }
        const Vec3 v = (*velocity)[f.node].head<3>() + rhs[f.node].head<3>();
        settled = frictionSettled(f, s.nodeForce[f.node], s.projector[f.node] * (f.start + h * v)) && settled;
      }
      if (!changed && !settled && resolvedForFriction < kMaxFrictionSolves && s.passes <= kMaxActiveSetPasses / 2)
        changed = true, ++resolvedForFriction;
    }
    if (!changed) {
      for (size_t j = 0; j < m; ++j)
        if (c[j].force) *c[j].force = s.used[j] ? std::max(0.0, s.force[j]) : 0.0;
      if (!s.friction.empty())
        for (const NodeConstraint& k : c)
          if (k.friction.end && k.node < n && s.frictionOf[k.node] >= 0)
            *k.friction.end = memoryOf(s.friction[s.frictionOf[k.node]]);
      return std::nullopt;
    }
  }
  Failure f = badRod("", "wall constraints did not settle in " + std::to_string(kMaxActiveSetPasses) + " solves");
  f.kind = FailureKind::SolverFailure;
  return f;
}

}  // namespace coilsim
