#include "physics/pair_coupling.h"

#include <Eigen/OrderingMethods>
#include <Eigen/SparseCholesky>
#include <cmath>

#include "physics/state.h"

namespace coilsim {

using SparseMatrix = Eigen::SparseMatrix<double>;

// The matrix is assembled in elimination order (PairSolveScratch::slot),
// its upper triangle, so the factorisation takes it as it is.
struct PairFactorCache::Impl {
  std::vector<Eigen::Triplet<double>> triplets;
  SparseMatrix matrix;
  Eigen::SimplicialLDLT<SparseMatrix, Eigen::Upper, Eigen::NaturalOrdering<int>> factor;
  std::vector<int> outer, inner;  // the pattern the factor's symbolic analysis was made for (empty: none yet)
  SparseMatrix graph;  // the nodes' graph, for their ordering
  std::vector<Eigen::Triplet<double>> links;
  Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int> order;
  Eigen::VectorXd rhs, dv;
};

PairFactorCache::PairFactorCache() = default;
PairFactorCache::~PairFactorCache() = default;
PairFactorCache::PairFactorCache(const PairFactorCache&) {}
PairFactorCache& PairFactorCache::operator=(const PairFactorCache& other) {
  if (this != &other) impl_.reset();
  return *this;
}
PairFactorCache::PairFactorCache(PairFactorCache&&) noexcept = default;
PairFactorCache& PairFactorCache::operator=(PairFactorCache&&) noexcept = default;
PairFactorCache::Impl& PairFactorCache::impl() {
  if (!impl_) impl_ = std::make_unique<Impl>();
  return *impl_;
}

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

// Each node of the touched rods gets two places in the elimination order,
// one for its three translations and one for its three rotations
// (s.slot, indexed by 2 (s.firstNode[rod] + node) + part): a minimum-degree
// ordering of the graph of those parts, whose links are the bands'
// neighbours and every pair of nodes' translations that one row couples.
// The parts are kept apart because only translations take rows: with each
// node's six unknowns ordered together, the rotations were eliminated with
// the translations and filled in as densely (twice the factorisation's
// time in a packed sac). Returns the number of nodes.
int orderNodes(const std::vector<RodState>& rods, PairSolveScratch& s, PairFactorCache::Impl& c) {
  s.firstNode.assign(rods.size(), -1);
  int nodes = 0;
  for (size_t k = 0; k < rods.size(); ++k)
    if (s.touched[k]) s.firstNode[k] = nodes, nodes += rods[k].activeNodes;
  c.links.clear();
  const auto link = [&](int a, int b) {
    if (a != b) c.links.emplace_back(std::max(a, b), std::min(a, b), 1.0);
  };
  for (size_t k = 0; k < rods.size(); ++k)
    for (int i = 0; s.touched[k] && i < rods[k].activeNodes; ++i) {
      const int n = 2 * (s.firstNode[k] + i);
      // The diagonal too: Eigen's minimum-degree ordering returns the
      // identity for a graph without it.
      c.links.emplace_back(n, n, 1.0);
      c.links.emplace_back(n + 1, n + 1, 1.0);
      link(n, n + 1);
      if (i + 1 < rods[k].activeNodes)
        for (int a = 0; a < 2; ++a)
          for (int b = 0; b < 2; ++b) link(n + a, n + 2 + b);
    }
  for (const PairSolveScratch::Row& row : s.rows)
    for (int e = row.first; e < row.first + row.count; ++e)
      for (int f = row.first; f < e; ++f) {
        const PairSolveScratch::Entry &a = s.entries[size_t(e)], &b = s.entries[size_t(f)];
        link(2 * (s.firstNode[size_t(a.rod)] + a.node), 2 * (s.firstNode[size_t(b.rod)] + b.node));
      }
  c.graph.resize(2 * nodes, 2 * nodes);
  c.graph.setFromTriplets(c.links.begin(), c.links.end());
  // The ordering's permutation maps a place in the order to a part.
  Eigen::AMDOrdering<int>()(c.graph, c.order);
  s.slot.resize(size_t(2 * nodes));
  for (int place = 0; place < 2 * nodes; ++place) s.slot[size_t(c.order.indices()(place))] = place;
  return nodes;
}

// Unknown a (0-2 translations, 3-5 rotations) of node i of rod k, in the whole system.
int unknown(const PairSolveScratch& s, size_t k, int i, int a) {
  return 3 * s.slot[size_t(2 * (s.firstNode[k] + i) + a / 3)] + a % 3;
}

// Adds value at (i, j) of the symmetric matrix to its upper triangle.
void addUpper(std::vector<Triplet>& out, int i, int j, double value) {
  out.emplace_back(std::min(i, j), std::max(i, j), value);
}

// Rod k's band (both triangles' worth, each entry once).
void addBand(const RodState& r, size_t k, const PairSolveScratch& s, std::vector<Triplet>& out) {
  const BlockTridiagonal& a = r.work.system;
  for (int i = 0; i < r.activeNodes; ++i) {
    for (int col = 0; col < 6; ++col)
      for (int row = col; row < 6; ++row)
        if (a.diag[size_t(i)](row, col) != 0)
          addUpper(out, unknown(s, k, i, row), unknown(s, k, i, col), a.diag[size_t(i)](row, col));
    if (i + 1 < r.activeNodes)
      for (int col = 0; col < 6; ++col)
        for (int row = 0; row < 6; ++row)
          if (a.lower[size_t(i)](row, col) != 0)
            addUpper(out, unknown(s, k, i + 1, row), unknown(s, k, i, col), a.lower[size_t(i)](row, col));
  }
}

// Whether the matrix has the pattern the factor was analysed for.
bool samePattern(const PairFactorCache::Impl& c) {
  const SparseMatrix& m = c.matrix;
  return c.outer.size() == size_t(m.outerSize() + 1) && c.inner.size() == size_t(m.nonZeros()) &&
         std::equal(c.outer.begin(), c.outer.end(), m.outerIndexPtr()) &&
         std::equal(c.inner.begin(), c.inner.end(), m.innerIndexPtr());
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
  PairFactorCache::Impl& c = s.factor.impl();
  const int unknowns = 6 * orderNodes(rods, s, c);
  c.triplets.clear();
  for (size_t k = 0; k < rods.size(); ++k)
    if (s.touched[k]) addBand(rods[k], k, s, c.triplets);
  // Each row's q beta beta^T (its entries' translations), each pair of
  // unknowns once.
  for (const PairSolveScratch::Row& row : s.rows)
    for (int e = row.first; e < row.first + row.count; ++e) {
      const PairSolveScratch::Entry& a = s.entries[size_t(e)];
      for (int f = row.first; f < row.first + row.count; ++f) {
        const PairSolveScratch::Entry& b = s.entries[size_t(f)];
        for (int i = 0; i < 3; ++i)
          for (int j = 0; j < 3; ++j) {
            const int ia = unknown(s, size_t(a.rod), a.node, i), ib = unknown(s, size_t(b.rod), b.node, j);
            if (ia <= ib && a.coeff[i] * b.coeff[j] != 0)
              c.triplets.emplace_back(ia, ib, row.stiffness * a.coeff[i] * b.coeff[j]);
          }
      }
    }
  c.matrix.resize(unknowns, unknowns);
  c.matrix.setFromTriplets(c.triplets.begin(), c.triplets.end());
  if (!samePattern(c)) {
    c.factor.analyzePattern(c.matrix);
    c.outer.assign(c.matrix.outerIndexPtr(), c.matrix.outerIndexPtr() + c.matrix.outerSize() + 1);
    c.inner.assign(c.matrix.innerIndexPtr(), c.matrix.innerIndexPtr() + c.matrix.nonZeros());
  }
  c.factor.factorize(c.matrix);
  const int first = s.entries.front().rod;
  if (c.factor.info() != Eigen::Success || !(c.factor.vectorD().minCoeff() > 0))
    return solverFailure(model, first, "pair contacts: the coupled implicit matrix is not positive definite");
  c.rhs.resize(unknowns);
  for (size_t k = 0; k < rods.size(); ++k)
    for (int i = 0; s.touched[k] && i < rods[k].activeNodes; ++i) {
      c.rhs.segment<3>(unknown(s, k, i, 0)) = rods[k].work.rhs[size_t(i)].head<3>();
      c.rhs.segment<3>(unknown(s, k, i, 3)) = rods[k].work.rhs[size_t(i)].tail<3>();
    }
  c.dv = c.factor.solve(c.rhs);
  if (!c.dv.allFinite()) return solverFailure(model, first, "pair contacts: the coupled solve gave non-finite velocities");
  for (size_t k = 0; k < rods.size(); ++k)
    for (int i = 0; s.touched[k] && i < rods[k].activeNodes; ++i) {
      rods[k].work.rhs[size_t(i)].head<3>() = c.dv.segment<3>(unknown(s, k, i, 0));
      rods[k].work.rhs[size_t(i)].tail<3>() = c.dv.segment<3>(unknown(s, k, i, 3));
    }
  return std::nullopt;
}

}  // namespace coilsim
