// Tests of the block-tridiagonal Cholesky solver (src/physics/block_tridiagonal.cpp).
// Reference: Eigen's SparseLU (a general sparse LU with partial pivoting,
// independent of our block sweep) on the same matrix, built here from the
// blocks by triplets; the Dirichlet elimination is checked against the
// reduced system of the free unknowns solved by SparseLU.
// Error bound: for a backward-stable solve, |x - x_ref| / |x| <~ c n
// cond(A) eps (Golub & Van Loan, Matrix Computations, 4th ed., sec. 4.2.7 for
// Cholesky, 3.4.6 for LU).
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <Eigen/Sparse>
#include <Eigen/SparseLU>
#include <random>

#include "physics/block_tridiagonal.h"
#include "support/rod_models.h"
#include "support/tolerance.h"

namespace coilsim::test {
namespace {

using SparseMatrix = Eigen::SparseMatrix<double>;

SparseMatrix sparseFromBlocks(const BlockTridiagonal& a) {
  std::vector<Eigen::Triplet<double>> t;
  const int n = a.size();
  for (int i = 0; i < n; ++i)
    for (int r = 0; r < 6; ++r)
      for (int c = 0; c < 6; ++c) {
        t.emplace_back(6 * i + r, 6 * i + c, a.diag[i](r, c));
        if (i + 1 < n) {
          t.emplace_back(6 * (i + 1) + r, 6 * i + c, a.lower[i](r, c));
          t.emplace_back(6 * i + c, 6 * (i + 1) + r, a.lower[i](r, c));  // upper = lower^T
        }
      }
  SparseMatrix m(6 * n, 6 * n);
  m.setFromTriplets(t.begin(), t.end());
  return m;
}

Eigen::VectorXd flatten(const std::vector<Vec6>& b) {
  Eigen::VectorXd v(6 * b.size());
  for (size_t i = 0; i < b.size(); ++i) v.segment<6>(6 * i) = b[i];
  return v;
}

Eigen::VectorXd sparseLuSolve(const SparseMatrix& a, const Eigen::VectorXd& b) {
  Eigen::SparseLU<SparseMatrix> lu;
  lu.analyzePattern(a);
  lu.factorize(a);
  EXPECT_EQ(lu.info(), Eigen::Success);
  return lu.solve(b);
}

// A = B B^T with B block lower bidiagonal (diagonal blocks lower triangular
// with positive diagonal): SPD and block tridiagonal by construction, with a
// condition number set by `spread` (diagonal of B in [1, spread]).
BlockTridiagonal randomSpd(int n, double spread, std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1, 1), d(1, spread);
  std::vector<Mat6> diagB(n), lowerB(n > 0 ? n - 1 : 0);
  for (int i = 0; i < n; ++i) {
    diagB[i] = Mat6::Zero();
    for (int r = 0; r < 6; ++r)
      for (int c = 0; c <= r; ++c) diagB[i](r, c) = r == c ? d(rng) : 0.5 * u(rng);
  }
  for (auto& l : lowerB) l = Mat6::NullaryExpr([&](Eigen::Index, Eigen::Index) { return 0.5 * u(rng); });
  BlockTridiagonal a;
  a.resize(n);
  for (int i = 0; i < n; ++i) {
    a.diag[i] = diagB[i] * diagB[i].transpose();
    if (i > 0) a.diag[i] += lowerB[i - 1] * lowerB[i - 1].transpose();
    if (i + 1 < n) a.lower[i] = lowerB[i] * diagB[i].transpose();
  }
  return a;
}

std::vector<Vec6> randomRhs(int n, std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<Vec6> b(n);
  for (auto& v : b) v = Vec6::NullaryExpr([&](Eigen::Index) { return u(rng); });
  return b;
}

// Condition number of the diagonally scaled matrix D^-1/2 A D^-1/2: the one
// that bounds Cholesky's error (van der Sluis 1969; Higham, Accuracy and
// Stability of Numerical Algorithms, sec. 10.1), robust to the units mixing
// kg, kg m^2 and identity rows in one matrix.
double conditionNumber(const BlockTridiagonal& a) {
  const Eigen::MatrixXd dense = toDense(a);
  const Eigen::VectorXd s = dense.diagonal().cwiseSqrt().cwiseInverse();
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(s.asDiagonal() * dense * s.asDiagonal());
  return es.eigenvalues().maxCoeff() / es.eigenvalues().minCoeff();
}

// The bound c n cond eps of a backward-stable solve, with c = 10.
Tolerance stableSolve(int unknowns, double cond) {
  return {10.0 * unknowns * cond * kEpsilon, "backward-stable solve: 10 n cond(A) eps"};
}

TEST(BlockTridiagonalTest, ToDenseMatchesTheBlocks) {
  std::mt19937 rng(1);
  const BlockTridiagonal a = randomSpd(5, 3.0, rng);
  const Eigen::MatrixXd dense = toDense(a), fromTriplets = Eigen::MatrixXd(sparseFromBlocks(a));
  EXPECT_TRUE(small("toDense minus triplet matrix", (dense - fromTriplets).cwiseAbs().maxCoeff(),
                    {0.0, "a copy: exactly equal"}));
}

TEST(BlockTridiagonalTest, SolvesRandomSpdSystemsLikeSparseLu) {
  std::mt19937 rng(42);
  for (const int n : {1, 2, 7, 60}) {
    for (const double spread : {2.0, 30.0}) {
      const BlockTridiagonal a = randomSpd(n, spread, rng);
      const std::vector<Vec6> b = randomRhs(n, rng);
      std::vector<Vec6> x = b;
      BlockTridiagonalSolver solver;
      ASSERT_TRUE(solver.factorize(a));
      solver.solve(x);
      const Eigen::VectorXd ref = sparseLuSolve(sparseFromBlocks(a), flatten(b));
      const double err = (flatten(x) - ref).norm() / ref.norm();
      EXPECT_TRUE(small("block solve vs SparseLU, n=" + std::to_string(n) + " spread=" + std::to_string(int(spread)),
                        err, stableSolve(6 * n, conditionNumber(a))));
    }
  }
}

TEST(BlockTridiagonalTest, RefusesMatricesThatAreNotPositiveDefinite) {
  std::mt19937 rng(3);
  BlockTridiagonal a = randomSpd(6, 2.0, rng);
  a.diag[4](2, 2) = -1.0;  // a negative diagonal entry: not SPD
  BlockTridiagonalSolver solver;
  EXPECT_FALSE(solver.factorize(a));
}

// The implicit matrix of a real rod: (1 + h a) M + (h b + h^2) K of a
// deformed helix coil, clamped at node 0 by applyDirichlet.
struct ImplicitSystem {
  BlockTridiagonal a;
  std::vector<Vec6> b;
};

ImplicitSystem helixImplicitSystem(double h, double alpha, double beta) {
  const double length = 0.02;
  const int beams = 40;
  RodDef r = clamped(rodWithRest(makeHelix(length, beams, 0.007, 0.001, true), length, beams, platinum(),
                                 circularSection(1.8e-4, kPlatinumPoisson)));
  const Model m = compileModel(modelOf({r}));
  State s = makeState(m);
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int i = 1; i <= beams; ++i) {
    s.rods[0].x[i] += 1e-5 * Vec3(u(rng), u(rng), u(rng));
    s.rods[0].q[i] = (quatExp(0.05 * Vec3(u(rng), u(rng), u(rng))) * s.rods[0].q[i]).normalized();
  }
  assembleAt(m, s);
  const RodModel& rm = m.rods[0];
  ImplicitSystem sys;
  sys.a = s.rods[0].work.stiffness;
  for (int i = 0; i <= beams; ++i) {
    Mat6 mass = Mat6::Zero();
    mass.topLeftCorner<3, 3>() = rm.nodeMass[i] * Mat3::Identity();
    mass.bottomRightCorner<3, 3>() = globalInertia(rm, s.rods[0].q[i], i);
    sys.a.diag[i] = (1 + h * alpha) * mass + (h * beta + h * h) * sys.a.diag[i];
    if (i < beams) sys.a.lower[i] *= (h * beta + h * h);
  }
  sys.b = s.rods[0].work.force;
  for (auto& v : sys.b) v *= h;
  return sys;
}

TEST(BlockTridiagonalTest, SolvesTheAssembledImplicitMatrixLikeSparseLu) {
  ImplicitSystem sys = helixImplicitSystem(1e-3, 1.0, 1e-4);
  for (int d = 0; d < 6; ++d) applyDirichlet(sys.a, sys.b, 0, d, 0.0);
  std::vector<Vec6> x = sys.b;
  BlockTridiagonalSolver solver;
  ASSERT_TRUE(solver.factorize(sys.a));
  solver.solve(x);
  const Eigen::VectorXd ref = sparseLuSolve(sparseFromBlocks(sys.a), flatten(sys.b));
  EXPECT_TRUE(small("implicit helix system, block solve vs SparseLU", (flatten(x) - ref).norm() / ref.norm(),
                    stableSolve(6 * sys.a.size(), conditionNumber(sys.a))));
}

TEST(BlockTridiagonalTest, DirichletRowsGiveTheReducedSystemSolution) {
  // Prescribe some DOFs at non-zero values (a moving clamp and a pinned end).
  ImplicitSystem sys = helixImplicitSystem(1e-3, 0.0, 0.0);
  const int n = sys.a.size();
  struct Fixed {
    int node, dof;
    double value;
  };
  const Fixed fixed[] = {{0, 0, 1e-4}, {0, 1, -2e-4}, {0, 2, 0.5e-4}, {0, 3, 0.01}, {0, 4, 0.0}, {0, 5, -0.02},
                         {n - 1, 0, 3e-5}, {n - 1, 1, 0.0}, {n - 1, 2, -1e-5}, {n / 2, 4, 0.003}};
  const SparseMatrix full = sparseFromBlocks(sys.a);
  const Eigen::VectorXd fullRhs = flatten(sys.b);

  // Reference: unknowns split into free (f) and fixed (c); A_ff x_f = b_f - A_fc x_c.
  std::vector<int> isFixed(6 * n, -1);
  Eigen::VectorXd xc = Eigen::VectorXd::Zero(6 * n);
  for (int k = 0; k < int(std::size(fixed)); ++k) {
    isFixed[6 * fixed[k].node + fixed[k].dof] = k;
    xc[6 * fixed[k].node + fixed[k].dof] = fixed[k].value;
  }
  std::vector<int> freeIndex;
  for (int i = 0; i < 6 * n; ++i)
    if (isFixed[i] < 0) freeIndex.push_back(i);
  const Eigen::MatrixXd dense(full);
  const int nf = int(freeIndex.size());
  Eigen::MatrixXd aff(nf, nf);
  Eigen::VectorXd bf(nf);
  const Eigen::VectorXd axc = dense * xc;
  for (int r = 0; r < nf; ++r) {
    bf[r] = fullRhs[freeIndex[r]] - axc[freeIndex[r]];
    for (int c = 0; c < nf; ++c) aff(r, c) = dense(freeIndex[r], freeIndex[c]);
  }
  const Eigen::VectorXd xf = sparseLuSolve(aff.sparseView(), bf);
  Eigen::VectorXd ref = xc;
  for (int r = 0; r < nf; ++r) ref[freeIndex[r]] = xf[r];

  for (const Fixed& f : fixed) applyDirichlet(sys.a, sys.b, f.node, f.dof, f.value);
  std::vector<Vec6> x = sys.b;
  BlockTridiagonalSolver solver;
  ASSERT_TRUE(solver.factorize(sys.a));
  solver.solve(x);
  const Eigen::VectorXd got = flatten(x);
  for (const Fixed& f : fixed)
    EXPECT_TRUE(nearAbs("prescribed value node " + std::to_string(f.node) + " dof " + std::to_string(f.dof),
                        got[6 * f.node + f.dof], f.value, roundoff(std::abs(f.value) + 1e-300, 4, "identity row")));
  EXPECT_TRUE(small("Dirichlet block solve vs reduced SparseLU", (got - ref).norm() / ref.norm(),
                    stableSolve(6 * n, conditionNumber(sys.a))));
}

}  // namespace
}  // namespace coilsim::test
