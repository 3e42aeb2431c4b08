#include <Eigen/LU>
#include <Eigen/SparseCore>
#include <Eigen/SparseLU>
#include <cmath>

#include "physics/assembly.h"
#include "physics/beam.h"
#include "physics/integrator.h"

namespace coilsim {
namespace {

// Puts constrained DOFs at their targets (position and, if all three
// rotations are held, rotation).
void snapToTargets(const RodModel& rm, RodState& r) {
  for (size_t k = 0; k < rm.constraints.size(); ++k) {
    const Constraint& c = rm.constraints[k];
    if (c.node >= r.activeNodes) continue;
    for (int d = 0; d < 3; ++d)
      if (c.mask & (1u << d)) r.x[c.node][d] = r.targets[k].position[d];
    if ((c.mask & kRotation) == kRotation) r.q[c.node] = r.targets[k].rotation;
  }
}

enum class NewtonResult { Converged, NotConverged, Singular, Unhealthy };

// A general (non-symmetric) block-tridiagonal matrix and its block LU.
// The consistent tangent of co-rotational forces is not symmetric away from
// equilibrium, and symmetrising it costs Newton its quadratic convergence.
struct GeneralTridiagonal {
  std::vector<Mat6> diag, lower, upper;  // A(i,i), A(i+1,i), A(i,i+1)
  std::vector<Eigen::PartialPivLU<Mat6>> pivots;
  std::vector<Vec6> rhs;
  void resize(int n) {
    diag.assign(n, Mat6::Zero());
    lower.assign(std::max(0, n - 1), Mat6::Zero());
    upper.assign(std::max(0, n - 1), Mat6::Zero());
    pivots.resize(n);
    rhs.assign(n, Vec6::Zero());
  }
  // Holds DOF d of node i at zero increment.
  void fix(int i, int d) {
    diag[i].row(d).setZero();
    diag[i].col(d).setZero();
    diag[i](d, d) = 1;
    if (i + 1 < int(diag.size())) lower[i].col(d).setZero(), upper[i].row(d).setZero();
    if (i > 0) lower[i - 1].row(d).setZero(), upper[i - 1].col(d).setZero();
    rhs[i][d] = 0;
  }
  // Solves in place (rhs becomes the solution); false if a pivot block is singular.
  bool solve(int n) {
    for (int i = 0; i < n; ++i) {
      if (i > 0) {
        const Mat6 l = lower[i - 1] * pivots[i - 1].inverse();  // A(i,i-1) S^{-1}
        diag[i].noalias() -= l * upper[i - 1];
        rhs[i].noalias() -= l * rhs[i - 1];
      }
      pivots[i].compute(diag[i]);
      if (!(std::abs(pivots[i].determinant()) > 0) || !std::isfinite(pivots[i].determinant())) return false;
    }
    for (int i = n - 1; i >= 0; --i) {
      if (i + 1 < n) rhs[i].noalias() -= upper[i] * rhs[i + 1];
      rhs[i] = pivots[i].solve(rhs[i]);
    }
    return rhs[0].allFinite();
  }
};

// The consistent (geometric) tangent of the elastic forces, element by
// element, by forward differences of evalBeam in the same increments the
// update uses (x += dx, q = exp(dtheta) q). The analytic
// co-rotational tangent T K T^T lacks the geometric stiffness of the turning
// element frames; with it Newton diverges once loads rotate the rod a lot
// (an end-loaded cantilever from P L^2 / EI ~ 3 on). Statics only: the cost
// is 13 element evaluations per element and iteration.
void consistentTangent(const RodState& r, GeneralTridiagonal& K) {
  for (int i = 0; i < r.activeNodes; ++i) K.diag[i].setZero();
  for (int e = 0; e + 1 < r.activeNodes; ++e) K.lower[e].setZero(), K.upper[e].setZero();
  BeamEval ev;
  Eigen::Matrix<double, 12, 1> f;
  Eigen::Matrix<double, 12, 12> k;
  for (int e = 0; e + 1 < r.activeNodes; ++e) {
    const BeamRest& b = r.beams[e];
    const Vec3 xa = r.x[e], xb = r.x[e + 1];
    const Quat qa = r.q[e], qb = r.q[e + 1];
    for (int j = 0; j < 12; ++j) {
      const int node = j / 6, dof = j % 6;
      const double eps = dof < 3 ? 1e-6 * b.length : 1e-6;
      // Central differences: second-order accurate, so Newton stays quadratic.
      for (const double sign : {1.0, -1.0}) {
        Vec3 pa = xa, pb = xb;
        Quat ra = qa, rb = qb;
        Vec3 delta = Vec3::Zero();
        delta[dof % 3] = sign * eps;
        if (dof < 3) (node == 0 ? pa : pb) += delta;
        else (node == 0 ? ra : rb) = quatExp(delta) * (node == 0 ? qa : qb);
        evalBeam(b, pa, ra, pb, rb, false, ev);
        f << ev.forceA, ev.forceB;
        if (sign > 0) k.col(j) = f;
        else k.col(j) = -(k.col(j) - f) / (2 * eps);
      }
    }
    K.diag[e] += k.topLeftCorner<6, 6>();
    K.diag[e + 1] += k.bottomRightCorner<6, 6>();
    K.lower[e] += k.bottomLeftCorner<6, 6>();
    K.upper[e] += k.topRightCorner<6, 6>();
  }
}

// Solves K dx = rhs with the effects' couplings between distant nodes (a
// coil's loops pressing on each other), which the block-tridiagonal LU
// cannot hold: a general sparse LU of the whole rod. Statics only, where a
// Newton iteration without the coupling moves two loops in contact as if
// each leant on a fixed wall, so a stack of loops could not sag together
// (kStaticSelfContactDiverges in tests/support/known_bugs.h). K must be
// filled and its fixed DOFs applied; the solution goes to K.rhs.
bool solveCoupled(GeneralTridiagonal& K, const std::vector<NodeCoupling>& coupling, const std::vector<unsigned>& fixed,
                  int n) {
  std::vector<Eigen::Triplet<double>> t;
  t.reserve(size_t(n) * 36 * 3 + coupling.size() * 9);
  const auto block = [&](int bi, int bj, const auto& m, int size) {
    for (int a = 0; a < size; ++a)
      for (int b = 0; b < size; ++b)
        if (m(a, b) != 0) t.emplace_back(6 * bi + a, 6 * bj + b, m(a, b));
  };
  for (int i = 0; i < n; ++i) block(i, i, K.diag[i], 6);
  for (int i = 0; i + 1 < n; ++i) block(i + 1, i, K.lower[i], 6), block(i, i + 1, K.upper[i], 6);
  for (const NodeCoupling& c : coupling) {
    if (c.row >= n || c.col >= n) continue;
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b)
        if (!(fixed[c.row] & (1u << a)) && !(fixed[c.col] & (1u << b)) && c.stiffness(a, b) != 0)
          t.emplace_back(6 * c.row + a, 6 * c.col + b, c.stiffness(a, b));
  }
  Eigen::SparseMatrix<double> A(6 * n, 6 * n);
  A.setFromTriplets(t.begin(), t.end());
  Eigen::SparseLU<Eigen::SparseMatrix<double>, Eigen::COLAMDOrdering<int>> lu;
  lu.compute(A);
  if (lu.info() != Eigen::Success) return false;
  Eigen::VectorXd b(6 * n);
  for (int i = 0; i < n; ++i) b.segment<6>(6 * i) = K.rhs[i];
  const Eigen::VectorXd x = lu.solve(b);
  if (lu.info() != Eigen::Success || !x.allFinite()) return false;
  for (int i = 0; i < n; ++i) K.rhs[i] = x.segment<6>(6 * i);
  return true;
}

// Forces at the current poses, the effects' per-step preparation (contact
// detection) done first: a contact's plane and partner point must be where
// the other surface is now, or two loops pressing on each other each push
// against where the other was.
void assembleAt(const Model& model, int k, State& state, double lambda, std::vector<NodeCoupling>& coupling) {
  for (const EffectUse& u : model.effects)
    if (u.enabled) u.effect->beginStep(model, u.values, state, model.timeStep);
  assembleRodStatic(model, k, state.rods[k], lambda, coupling);
}

// Newton iterations at load factor lambda on the consistent tangent; an
// indefinite or singular tangent is shifted towards its diagonal.
NewtonResult newton(const Model& model, int k, State& state, double lambda, const StaticOptions& o, int& iterations) {
  RodState& r = state.rods[k];
  RodWorkspace& w = r.work;
  const int n = r.activeNodes;
  double length = 0;
  for (int e = 0; e + 1 < n; ++e) length += r.beams[e].length;
  std::vector<Vec3> xStart(n), dx(n);
  std::vector<Quat> qStart(n);
  std::vector<NodeCoupling> coupling;
  GeneralTridiagonal K;
  K.resize(n);
  for (int it = 0; it < o.maxIterations; ++it) {
    ++iterations;
    assembleAt(model, k, state, lambda, coupling);
    bool solved = false;
    // An indefinite or singular tangent is shifted towards its diagonal.
    for (double shift = 0; !solved && shift <= 1e6; shift = shift == 0 ? 1e-6 : shift * 10) {
      consistentTangent(r, K);
      for (int i = 0; i < n; ++i) {
        if (w.effectsTouchedMatrix) K.diag[i] += w.effectK[i];
        K.diag[i].diagonal() += shift * K.diag[i].diagonal().cwiseAbs();
        K.rhs[i] = w.force[i];
        for (int d = 0; d < 6; ++d)
          if (w.fixedMask[i] & (1u << d)) K.fix(i, d);
      }
      solved = coupling.empty() ? K.solve(n) : solveCoupled(K, coupling, w.fixedMask, n);
    }
    if (!solved) return NewtonResult::Singular;
    for (int i = 0; i < n; ++i) w.rhs[i] = K.rhs[i];
    for (int i = 0; i < n; ++i) xStart[i] = r.x[i], qStart[i] = r.q[i];
    double dxMax = 0, dr = 0;
    for (int i = 0; i < n; ++i) {
      dxMax = std::max(dxMax, w.rhs[i].head<3>().norm());
      dr = std::max(dr, w.rhs[i].tail<3>().norm());
    }
    if (!std::isfinite(dxMax) || !std::isfinite(dr)) return NewtonResult::Unhealthy;
    // Full Newton steps: a residual-based line search would reject them,
    // since a linearised step stretches a slender rod to second order and
    // the next iteration, not a shorter step, removes that. Only steps that
    // would turn a node by more than half a radian are scaled down, and
    // those that would carry one segment through another (contacts).
    double alpha = std::min(1.0, 0.5 / std::max(dr, 1e-300));
    for (int i = 0; i < n; ++i) dx[i] = alpha * w.rhs[i].head<3>();
    double contactFraction = 1.0;
    for (const EffectUse& u : model.effects)
      if (u.enabled) contactFraction = std::min(contactFraction, u.effect->limitStaticUpdate(model, u.values, state, k, dx));
    alpha *= contactFraction;
    for (int i = 0; i < n; ++i) {
      r.x[i] = xStart[i] + alpha * w.rhs[i].head<3>();
      r.q[i] = (quatExp(alpha * w.rhs[i].tail<3>()) * qStart[i]).normalized();
    }
    if (alpha * dxMax < o.positionTolerance * length && alpha * dr < o.rotationTolerance) return NewtonResult::Converged;
  }
  return NewtonResult::NotConverged;
}

// A rod left short of equilibrium: the load factor it was left at, of 1.
Failure notConverged(const std::string& rod, std::string text, double loadFactor) {
  Failure f;
  f.kind = FailureKind::NotConverged;
  f.rod = rod;
  f.quantity = "load factor";
  f.value = loadFactor;
  f.limit = 1;
  f.text = std::move(text);
  return f;
}

}  // namespace

StaticReport solveStatic(const Model& model, State& state, const StaticOptions& o) {
  StaticReport rep;
  // Refusals that need no solve come before any rod is touched, so that a
  // refused solve leaves the whole State as it was (not the rods before the
  // bad one solved and their velocities zeroed).
  for (size_t k = 0; k < model.rods.size(); ++k)
    if (state.rods[k].active && model.rods[k].constraints.empty()) {
      rep.failure = notConverged(model.rods[k].name, "no constraint holds it, so its static equilibrium is not defined", 0);
      return rep;
    }
  for (size_t k = 0; k < model.rods.size(); ++k) {
    const RodModel& rm = model.rods[k];
    RodState& r = state.rods[k];
    if (!r.active) continue;
    rep.loadFactor = 0;
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
      const NewtonResult res = newton(model, int(k), state, next, o, rep.iterations);
      ++rep.increments;
      if (res == NewtonResult::Converged && !checkHealth(model, state)) {
        lambda = next;
        rep.loadFactor = lambda;
        continue;
      }
      r.x = x0, r.q = q0;
      const std::string kept = "; it is left at load factor " + std::to_string(lambda);
      if (res == NewtonResult::Singular) {
        rep.failure = notConverged(rm.name, "stiffness matrix is singular (is the rod held enough?)" + kept, lambda);
        return rep;
      }
      if (++bisections > o.maxBisections) {
        rep.failure = notConverged(rm.name,
                                   "Newton did not converge at load factor " + std::to_string(next) + " after " +
                                       std::to_string(o.maxBisections) + " bisections of the load increment" + kept,
                                   lambda);
        return rep;
      }
      increment *= 0.5;
    }
  }
  rep.loadFactor = 1;
  return rep;
}

}  // namespace coilsim
