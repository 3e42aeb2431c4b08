#include "physics/pair_coupling.h"

#include <Eigen/SparseCholesky>
#include <cmath>

#include "physics/state.h"

namespace coilsim {
namespace {


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
// stiffness q, and in the first Newton iteration the h^2 K v term of the
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
        row.stiffness = q;
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
        for (int e = row.first; e < row.first + row.count; ++e) {
          const PairSolveScratch::Entry& en = s.entries[size_t(e)];
          rods[size_t(en.rod)].work.rhs[size_t(en.node)].head<3>() += shift * en.coeff;
        }
        s.rows.push_back(row);
      }
    }
  }
}

Failure solverFailure(const Model& model, int rod, std::string text) {
  Failure f = badRod(model.rods[size_t(rod)].name, std::move(text));
  f.kind = FailureKind::SolverFailure;
  return f;
}

using Triplet = Eigen::Triplet<double>;

// The lower triangle of rod k's band, its unknowns from `first` on.
void addBand(const RodState& r, int first, std::vector<Triplet>& out) {
  const BlockTridiagonal& a = r.work.system;
  for (int i = 0; i < r.activeNodes; ++i) {
    const int at = first + 6 * i;
    for (int col = 0; col < 6; ++col)
      for (int row = col; row < 6; ++row)
        if (a.diag[size_t(i)](row, col) != 0) out.emplace_back(at + row, at + col, a.diag[size_t(i)](row, col));
    if (i + 1 < r.activeNodes)
      for (int col = 0; col < 6; ++col)
        for (int row = 0; row < 6; ++row)
          if (a.lower[size_t(i)](row, col) != 0) out.emplace_back(at + 6 + row, at + col, a.lower[size_t(i)](row, col));
  }
}

}  // namespace

std::optional<Failure> solvePairsCoupled(const Model& model, std::vector<RodState>& rods, std::span<const char> stepped,
                                         double h, bool firstIteration, PairSolveScratch& s, PairSolveStats& stats) {
  buildRows(rods, stepped, h, firstIteration, s);
  ++stats.solves;
  stats.rows += long(s.rows.size());
  // Rods no row touches: their own band, as a lumped step solves it.
  for (size_t k = 0; k < rods.size(); ++k) {
    if (!stepped[k] || s.touched[k]) continue;
    RodWorkspace& w = rods[k].work;
    if (!w.solver.factorize(w.system, rods[k].activeNodes))
      return solverFailure(model, int(k), "implicit matrix is not positive definite");
    w.solver.solve(w.rhs);
  }
  if (s.rows.empty()) return std::nullopt;
  // The touched rods one after another, each node's six unknowns together.
  s.offset.assign(rods.size(), -1);
  int unknowns = 0;
  for (size_t k = 0; k < rods.size(); ++k)
    if (s.touched[k]) s.offset[k] = unknowns, unknowns += 6 * rods[k].activeNodes;
  std::vector<Triplet> triplets;
  for (size_t k = 0; k < rods.size(); ++k)
    if (s.touched[k]) addBand(rods[k], s.offset[k], triplets);
  // Each row's q beta beta^T, lower triangle (its entries' translations).
  for (const PairSolveScratch::Row& row : s.rows)
    for (int e = row.first; e < row.first + row.count; ++e) {
      const PairSolveScratch::Entry& a = s.entries[size_t(e)];
      const int ia = s.offset[size_t(a.rod)] + 6 * a.node;
      for (int f = row.first; f < row.first + row.count; ++f) {
        const PairSolveScratch::Entry& b = s.entries[size_t(f)];
        const int ib = s.offset[size_t(b.rod)] + 6 * b.node;
        for (int i = 0; i < 3; ++i)
          for (int j = 0; j < 3; ++j)
            if (ia + i >= ib + j && a.coeff[i] * b.coeff[j] != 0)
              triplets.emplace_back(ia + i, ib + j, row.stiffness * a.coeff[i] * b.coeff[j]);
      }
    }
  Eigen::SparseMatrix<double> matrix(unknowns, unknowns);
  matrix.setFromTriplets(triplets.begin(), triplets.end());
  const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>, Eigen::Lower, Eigen::AMDOrdering<int>> factor(matrix);
  const int first = s.entries.front().rod;
  if (factor.info() != Eigen::Success || !(factor.vectorD().minCoeff() > 0))
    return solverFailure(model, first, "pair contacts: the coupled implicit matrix is not positive definite");
  Eigen::VectorXd rhs(unknowns);
  for (size_t k = 0; k < rods.size(); ++k)
    for (int i = 0; s.touched[k] && i < rods[k].activeNodes; ++i)
      rhs.segment<6>(s.offset[k] + 6 * i) = rods[k].work.rhs[size_t(i)];
  const Eigen::VectorXd dv = factor.solve(rhs);
  if (!dv.allFinite()) return solverFailure(model, first, "pair contacts: the coupled solve gave non-finite velocities");
  for (size_t k = 0; k < rods.size(); ++k)
    for (int i = 0; s.touched[k] && i < rods[k].activeNodes; ++i)
      rods[k].work.rhs[size_t(i)] = dv.segment<6>(s.offset[k] + 6 * i);
  return std::nullopt;
}

}  // namespace coilsim
