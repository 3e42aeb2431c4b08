// Tests of the coupled pair-contact solve (src/physics/pair_coupling.cpp).
// Reference: the whole system (every rod's band plus each contact's rank-one
// terms q beta beta^T, the fixed DOFs eliminated) assembled densely here and
// solved by Eigen's dense LDLT, which shares nothing with the solver's
// sparse assembly, its fixed DOFs' elimination or its rows.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <random>

#include "physics/block_tridiagonal.h"
#include "physics/model.h"
#include "physics/pair_coupling.h"
#include "physics/state.h"

namespace coilsim {
namespace {

// A random SPD band A = L L^T, L block lower bidiagonal with a dominant diagonal.
BlockTridiagonal randomBand(int n, std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<Mat6> d(static_cast<size_t>(n)), l(static_cast<size_t>(n));
  for (int i = 0; i < n; ++i) {
    for (int r = 0; r < 6; ++r)
      for (int c = 0; c < 6; ++c) {
        d[size_t(i)](r, c) = c < r ? u(rng) : 0.0;
        l[size_t(i)](r, c) = 0.5 * u(rng);
      }
    d[size_t(i)].diagonal().array() = 2.0 + u(rng);
  }
  BlockTridiagonal a;
  a.resize(n);
  for (int i = 0; i < n; ++i) {
    a.diag[size_t(i)] = d[size_t(i)] * d[size_t(i)].transpose();
    if (i > 0) a.diag[size_t(i)] += l[size_t(i)] * l[size_t(i)].transpose();
    if (i + 1 < n) a.lower[size_t(i)] = l[size_t(i + 1)] * d[size_t(i)].transpose();
  }
  return a;
}

struct Problem {
  Model model;
  std::vector<RodState> rods;
  std::vector<char> stepped;
  Eigen::VectorXd expected;  // the whole system's velocity increment, rods one after another
  std::vector<int> offset;   // first DOF of each rod in `expected`
};

// `rods` rods of `nodes` nodes, `pairs` random contacts between them (and
// within one), some DOFs fixed, some rods not stepped (their side is held).
Problem makeProblem(int rodCount, int nodes, int pairs, bool withFixed, bool withHeldRod, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1, 1), unit(0, 1);
  const double h = 1e-3;
  Problem p;
  p.rods.resize(size_t(rodCount));
  p.stepped.assign(size_t(rodCount), 1);
  if (withHeldRod) p.stepped.back() = 0;
  for (int k = 0; k < rodCount; ++k) p.model.rods.push_back(RodModel{});
  std::vector<BlockTridiagonal> original;
  std::vector<std::vector<Vec6>> rhs0;
  int dofs = 0;
  for (int k = 0; k < rodCount; ++k) {
    RodState& r = p.rods[size_t(k)];
    r.activeNodes = nodes;
    r.x.assign(size_t(nodes), Vec3::Zero());
    r.v.resize(size_t(nodes));
    for (Vec3& v : r.v) v = Vec3(u(rng), u(rng), u(rng));
    r.work.system = randomBand(nodes, rng);
    original.push_back(r.work.system);
    r.work.rhs.resize(size_t(nodes));
    for (Vec6& b : r.work.rhs) b = Vec6::Random();
    rhs0.push_back(r.work.rhs);
    r.work.fixedMask.assign(size_t(nodes), 0u);
    r.work.solver.resize(nodes);
    p.offset.push_back(dofs);
    dofs += 6 * nodes;
  }
  // Fixed DOFs: node 0 of rod 0 clamped, one translation of a middle node of rod 1.
  std::vector<std::pair<int, int>> fixed;  // (rod, dof index within the rod)
  std::vector<double> fixedValue;
  if (withFixed) {
    for (int d = 0; d < 6; ++d) fixed.push_back({0, d});
    fixed.push_back({1 % rodCount, 6 * (nodes / 2) + 1});
    for (auto [k, dof] : fixed) {
      p.rods[size_t(k)].work.fixedMask[size_t(dof / 6)] |= 1u << (dof % 6);
      fixedValue.push_back(0.3 * u(rng));
    }
  }
  // Contacts: random segments, normals and laws; rod k's side of each.
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(dofs, dofs);
  Eigen::VectorXd b(dofs), v(dofs);
  for (int k = 0; k < rodCount; ++k) {
    A.block(p.offset[size_t(k)], p.offset[size_t(k)], 6 * nodes, 6 * nodes) = toDense(original[size_t(k)]);
    for (int i = 0; i < nodes; ++i) {
      b.segment<6>(p.offset[size_t(k)] + 6 * i) = rhs0[size_t(k)][size_t(i)];
      v.segment<6>(p.offset[size_t(k)] + 6 * i) << p.rods[size_t(k)].v[size_t(i)], Vec3::Zero();
    }
  }
  std::uniform_int_distribution<int> rodOf(0, rodCount - 1), segOf(0, nodes - 2);
  for (int c = 0; c < pairs; ++c) {
    int k = rodOf(rng), j = rodOf(rng);
    if (!p.stepped[size_t(k)]) std::swap(k, j);
    if (!p.stepped[size_t(k)]) continue;
    int sa = segOf(rng), sb = segOf(rng);
    if (j == k && std::abs(sa - sb) < 2) sb = (sa + nodes / 2) % (nodes - 1);
    PairCoupling pc;
    pc.otherRod = j, pc.segment = sa, pc.otherSegment = sb;
    pc.s = unit(rng), pc.otherS = c % 3 == 0 ? 0.0 : unit(rng);  // an end point too
    pc.normal = Vec3(u(rng), u(rng), u(rng)).normalized();
    pc.normalStiffness = 5e4 * (0.5 + unit(rng)), pc.normalDamping = 0.05 * unit(rng);
    if (c % 2) pc.tangentStiffness = 2e4 * unit(rng), pc.tangentDamping = 0.02 * unit(rng);
    // Both sides list the contact when both are stepped (as detection does); one adds it.
    p.rods[size_t(k)].work.pairs.push_back(pc);
    if (p.stepped[size_t(j)]) {
      PairCoupling other = pc;
      other.otherRod = k, other.segment = sb, other.otherSegment = sa, other.s = pc.otherS, other.otherS = pc.s;
      other.normal = -pc.normal;
      p.rods[size_t(j)].work.pairs.push_back(other);
    }
    // The reference: q beta beta^T in the matrix, -h^2 k beta (beta . v) in the right-hand side.
    const Vec3& n = pc.normal;
    const Eigen::Matrix3d tangent = Eigen::Matrix3d::Identity() - n * n.transpose();
    const Eigen::Matrix3d K = pc.normalStiffness * n * n.transpose() + pc.tangentStiffness * tangent;
    const Eigen::Matrix3d D = pc.normalDamping * n * n.transpose() + pc.tangentDamping * tangent;
    Eigen::MatrixXd beta = Eigen::MatrixXd::Zero(3, dofs);
    const auto put = [&](int rod, int node, double w) {
      if (p.stepped[size_t(rod)]) beta.block<3, 3>(0, p.offset[size_t(rod)] + 6 * node) += w * Eigen::Matrix3d::Identity();
    };
    put(k, sa, 1 - pc.s), put(k, sa + 1, pc.s), put(j, sb, -(1 - pc.otherS)), put(j, sb + 1, -pc.otherS);
    A += beta.transpose() * (h * h * K + h * D) * beta;
    b -= h * h * beta.transpose() * K * (beta * v);
  }
  // Eliminate the fixed DOFs and the held rod's, solve densely.
  std::vector<int> free;
  Eigen::VectorXd known = Eigen::VectorXd::Zero(dofs);
  std::vector<char> isFixed(size_t(dofs), 0);
  for (size_t f = 0; f < fixed.size(); ++f) {
    const int dof = p.offset[size_t(fixed[f].first)] + fixed[f].second;
    isFixed[size_t(dof)] = 1, known[dof] = fixedValue[f];
  }
  for (int k = 0; k < rodCount; ++k)
    if (!p.stepped[size_t(k)])
      for (int d = 0; d < 6 * nodes; ++d) isFixed[size_t(p.offset[size_t(k)] + d)] = 1;
  for (int d = 0; d < dofs; ++d)
    if (!isFixed[size_t(d)]) free.push_back(d);
  const Eigen::VectorXd reduced = b - A * known;
  Eigen::MatrixXd Aff(free.size(), free.size());
  Eigen::VectorXd bf(free.size());
  for (size_t i = 0; i < free.size(); ++i) {
    bf[Eigen::Index(i)] = reduced[free[i]];
    for (size_t j = 0; j < free.size(); ++j) Aff(Eigen::Index(i), Eigen::Index(j)) = A(free[i], free[j]);
  }
  const Eigen::VectorXd xf = Aff.ldlt().solve(bf);
  p.expected = known;
  for (size_t i = 0; i < free.size(); ++i) p.expected[free[i]] = xf[Eigen::Index(i)];
  // What the solver is given: each band with its fixed DOFs applied (dynamics.cpp does so).
  for (size_t f = 0; f < fixed.size(); ++f) {
    RodWorkspace& w = p.rods[size_t(fixed[f].first)].work;
    applyDirichlet(w.system, w.rhs, fixed[f].second / 6, fixed[f].second % 6, fixedValue[f], nodes);
  }
  return p;
}

double relativeError(const Problem& p) {
  Eigen::VectorXd got = p.expected;
  for (size_t k = 0; k < p.rods.size(); ++k) {
    if (!p.stepped[k]) continue;
    for (int i = 0; i < p.rods[k].activeNodes; ++i)
      got.segment<6>(p.offset[k] + 6 * i) = p.rods[k].work.rhs[size_t(i)];
  }
  return (got - p.expected).norm() / p.expected.norm();
}

TEST(PairCoupling, EqualsTheWholeSystemSolvedDensely) {
  for (unsigned seed = 1; seed <= 20; ++seed) {
    Problem p = makeProblem(3, 12, 15, false, false, seed);
    PairSolveScratch scratch;
    PairSolveStats stats;
    ASSERT_FALSE(solvePairsCoupled(p.model, p.rods, p.stepped, 1e-3, true, scratch, stats)) << seed;
    EXPECT_LT(relativeError(p), 1e-8) << "seed " << seed;
  }
}

TEST(PairCoupling, FixedDofsAndAHeldRodAreEliminatedAsTheWholeSystemDoes) {
  for (unsigned seed = 1; seed <= 20; ++seed) {
    Problem p = makeProblem(4, 10, 20, true, true, 100 + seed);
    PairSolveScratch scratch;
    PairSolveStats stats;
    ASSERT_FALSE(solvePairsCoupled(p.model, p.rods, p.stepped, 1e-3, true, scratch, stats)) << seed;
    EXPECT_LT(relativeError(p), 1e-8) << "seed " << seed;
  }
}

}  // namespace
}  // namespace coilsim
