#include "physics/pair_coupling.h"

#include <cmath>

#include "physics/state.h"

namespace coilsim {
namespace {

// Conjugate gradients stop at this residual relative to the right-hand side's.
constexpr double kTolerance = 1e-10;
constexpr int kMaxIterations = 1000;

// Whether rod k's side of a coupling is the one that adds it: each pair
// contact sits in both sides' lists, and is added once.
bool addsIt(int k, const PairCoupling& c, std::span<const char> stepped) {
  const int j = c.otherRod;
  if (!stepped[size_t(j)]) return true;  // the other side is held where it is (asleep, inactive)
  if (j != k) return k < j;
  return c.segment < c.otherSegment;
}

// One row per direction of each coupling: its entries (fixed DOFs taken
// out, their prescribed increments moved to the right-hand side), its
// compliance, and in the first Newton iteration the h^2 K v term of the
// right-hand side, which needs both sides' velocities.
void buildRows(std::vector<RodState>& rods, std::span<const char> stepped, double h, bool firstIteration,
               PairSolveScratch& s) {
  s.entries.clear();
  s.rows.clear();
  s.touched.assign(rods.size(), 0);
  struct Side {
    int rod, node;
    double weight;
  };
  for (size_t k = 0; k < rods.size(); ++k) {
    if (!stepped[k]) continue;
    for (const PairCoupling& c : rods[k].work.pairs) {
      if (!addsIt(int(k), c, stepped)) continue;
      Side sides[4] = {{int(k), c.segment, 1 - c.s}, {int(k), c.segment + 1, c.s},
                       {c.otherRod, c.otherSegment, -(1 - c.otherS)}, {c.otherRod, c.otherSegment + 1, -c.otherS}};
      const int count = stepped[size_t(c.otherRod)] ? 4 : 2;
      // The normal, and the tangent plane's basis when friction is in the matrix.
      const Vec3& n = c.normal;
      const Vec3 t1 = (std::abs(n.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY()).cross(n).normalized();
      const Vec3 dirs[3] = {n, t1, n.cross(t1)};
      const double stiffness[3] = {c.normalStiffness, c.tangentStiffness, c.tangentStiffness};
      const double damping[3] = {c.normalDamping, c.tangentDamping, c.tangentDamping};
      for (int d = 0; d < 3; ++d) {
        const double q = h * h * stiffness[d] + h * damping[d];
        if (!(q > 0)) continue;
        PairSolveScratch::Row row;
        row.first = int(s.entries.size());
        row.compliance = 1 / q;
        double fixedPart = 0, relative = 0;
        for (int e = 0; e < count; ++e) {
          const Side& side = sides[e];
          if (side.weight == 0) continue;
          RodWorkspace& w = rods[size_t(side.rod)].work;
          Vec3 coeff = side.weight * dirs[d];
          if (firstIteration) relative += coeff.dot(rods[size_t(side.rod)].v[size_t(side.node)]);
          const unsigned mask = w.fixedMask[size_t(side.node)];
          for (int a = 0; a < 3; ++a)
            if (mask & (1u << a)) fixedPart += coeff[a] * w.rhs[size_t(side.node)][a], coeff[a] = 0;
          if (coeff.isZero(0.0)) continue;
          s.entries.push_back({side.rod, side.node, coeff});
          s.touched[size_t(side.rod)] = 1;
        }
        row.count = int(s.entries.size()) - row.first;
        if (row.count == 0) continue;
        // rhs -= h^2 k beta (beta . v) and the fixed increments' column q beta (beta_fixed . dv_fixed).
        const double shift = -(firstIteration ? h * h * stiffness[d] * relative : 0.0) - q * fixedPart;
        double diagonal = row.compliance;
        for (int e = row.first; e < row.first + row.count; ++e) {
          const PairSolveScratch::Entry& en = s.entries[size_t(e)];
          RodWorkspace& w = rods[size_t(en.rod)].work;
          w.rhs[size_t(en.node)].head<3>() += shift * en.coeff;
          // The compliance of the node alone (its diagonal block's
          // translation), a lower bound of what the whole rod gives.
          const Mat3 block = w.system.diag[size_t(en.node)].topLeftCorner<3, 3>();
          diagonal += en.coeff.dot(block.ldlt().solve(en.coeff));
        }
        row.diagonal = diagonal;
        s.rows.push_back(row);
      }
    }
  }
}

// work[k] = B^T p on the rods the rows touch.
void scatter(const PairSolveScratch& s, std::span<const double> p, std::vector<std::vector<Vec6>>& work,
             const std::vector<RodState>& rods) {
  for (size_t k = 0; k < rods.size(); ++k)
    if (s.touched[k]) std::fill(work[k].begin(), work[k].begin() + rods[k].activeNodes, Vec6::Zero());
  for (size_t r = 0; r < s.rows.size(); ++r) {
    const PairSolveScratch::Row& row = s.rows[r];
    for (int e = row.first; e < row.first + row.count; ++e) {
      const PairSolveScratch::Entry& en = s.entries[size_t(e)];
      work[size_t(en.rod)][size_t(en.node)].head<3>() += p[r] * en.coeff;
    }
  }
}

double gather(const PairSolveScratch& s, const PairSolveScratch::Row& row, const std::vector<std::vector<Vec6>>& v) {
  double sum = 0;
  for (int e = row.first; e < row.first + row.count; ++e) {
    const PairSolveScratch::Entry& en = s.entries[size_t(e)];
    sum += en.coeff.dot(v[size_t(en.rod)][size_t(en.node)].head<3>());
  }
  return sum;
}

// work[k] = A_k^-1 work[k] on the touched rods.
void backSubstitute(const PairSolveScratch& s, std::vector<RodState>& rods, std::vector<std::vector<Vec6>>& work) {
  for (size_t k = 0; k < rods.size(); ++k)
    if (s.touched[k]) rods[k].work.solver.solve(work[k]);
}

Failure solverFailure(const Model& model, int rod, std::string text) {
  Failure f = badRod(model.rods[size_t(rod)].name, std::move(text));
  f.kind = FailureKind::SolverFailure;
  return f;
}

}  // namespace

std::optional<Failure> solvePairsCoupled(const Model& model, std::vector<RodState>& rods, std::span<const char> stepped,
                                         double h, bool firstIteration, PairSolveScratch& s, PairSolveStats& stats) {
  buildRows(rods, stepped, h, firstIteration, s);
  for (size_t k = 0; k < rods.size(); ++k) {
    if (!stepped[k]) continue;
    RodWorkspace& w = rods[k].work;
    if (!w.solver.factorize(w.system, rods[k].activeNodes))
      return solverFailure(model, int(k), "implicit matrix is not positive definite");
    w.solver.solve(w.rhs);  // y = A^-1 rhs
  }
  const size_t m = s.rows.size();
  ++stats.solves;
  stats.rows += long(m);
  if (m == 0) return std::nullopt;
  s.work.resize(rods.size());
  for (size_t k = 0; k < rods.size(); ++k)
    if (s.touched[k] && s.work[k].size() < rods[k].x.size()) s.work[k].assign(rods[k].x.size(), Vec6::Zero());
  s.lambda.assign(m, 0.0);
  s.residual.resize(m), s.direction.resize(m), s.product.resize(m), s.precond.resize(m);
  // b = B y; lambda = 0, so the residual is b.
  double bNorm = 0;
  for (size_t r = 0; r < m; ++r) {
    double b = 0;
    const PairSolveScratch::Row& row = s.rows[r];
    for (int e = row.first; e < row.first + row.count; ++e) {
      const PairSolveScratch::Entry& en = s.entries[size_t(e)];
      b += en.coeff.dot(rods[size_t(en.rod)].work.rhs[size_t(en.node)].head<3>());
    }
    s.residual[r] = b;
    bNorm += b * b;
  }
  bNorm = std::sqrt(bNorm);
  if (!(bNorm > 0)) return std::nullopt;
  double rz = 0;
  for (size_t r = 0; r < m; ++r) {
    s.precond[r] = s.residual[r] / s.rows[r].diagonal;
    s.direction[r] = s.precond[r];
    rz += s.residual[r] * s.precond[r];
  }
  int it = 0;
  for (;; ++it) {
    double rr = 0;
    for (double v : s.residual) rr += v * v;
    if (std::sqrt(rr) <= kTolerance * bNorm) break;
    if (it == kMaxIterations || !std::isfinite(rr))
      return solverFailure(model, s.entries.front().rod,
                           "pair contacts: the coupled solve did not converge in " + std::to_string(kMaxIterations) +
                               " iterations");
    scatter(s, s.direction, s.work, rods);
    backSubstitute(s, rods, s.work);
    double pAp = 0;
    for (size_t r = 0; r < m; ++r) {
      s.product[r] = s.rows[r].compliance * s.direction[r] + gather(s, s.rows[r], s.work);
      pAp += s.direction[r] * s.product[r];
    }
    const double alpha = rz / pAp;
    double rzNew = 0;
    for (size_t r = 0; r < m; ++r) {
      s.lambda[r] += alpha * s.direction[r];
      s.residual[r] -= alpha * s.product[r];
      s.precond[r] = s.residual[r] / s.rows[r].diagonal;
      rzNew += s.residual[r] * s.precond[r];
    }
    const double beta = rzNew / rz;
    rz = rzNew;
    for (size_t r = 0; r < m; ++r) s.direction[r] = s.precond[r] + beta * s.direction[r];
  }
  stats.iterations += it;
  stats.maxIterations = std::max(stats.maxIterations, it);
  // dv = y - A^-1 B^T lambda.
  scatter(s, s.lambda, s.work, rods);
  backSubstitute(s, rods, s.work);
  for (size_t k = 0; k < rods.size(); ++k) {
    if (!s.touched[k]) continue;
    std::vector<Vec6>& rhs = rods[k].work.rhs;
    for (int i = 0; i < rods[k].activeNodes; ++i) rhs[size_t(i)] -= s.work[k][size_t(i)];
  }
  return std::nullopt;
}

}  // namespace coilsim
