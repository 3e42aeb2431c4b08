#pragma once
// Symmetric positive definite block-tridiagonal systems with 6x6 blocks: the
// implicit matrix of a serial beam chain (node i couples only to i-1, i+1).
// Block Cholesky (block Thomas) solves it in O(n) with no heap allocation
// once sized; hand-written 6x6 kernels keep the sweep near its floor.
#include <vector>

#include "physics/math.h"

namespace coilsim {

struct BlockTridiagonal {
  std::vector<Mat6> diag;   // (n) blocks A(i, i)
  std::vector<Mat6> lower;  // (n-1) blocks A(i+1, i); A(i, i+1) is its transpose
  void resize(int n);
  void setZero();
  int size() const { return int(diag.size()); }
};

class BlockTridiagonalSolver {
 public:
  void resize(int n);
  // Factorizes A = L L^T. Returns false (and leaves the factor unusable) if a
  // pivot block is not positive definite, i.e. A is not SPD.
  // Only the leading n x n blocks take part (n < 0: all).
  bool factorize(const BlockTridiagonal& a, int n = -1);
  // Solves A x = b in place (b becomes x) for the size last factorized.
  void solve(std::vector<Vec6>& b) const;

 private:
  std::vector<Mat6> chol_;  // (n) inverses C_i^{-1} of the lower Cholesky factors of the Schur complements
  std::vector<Mat6> gain_;  // (n) G_i^T, G_i = C_{i-1}^{-1} A(i, i-1)^T; entry 0 unused
  int size_ = 0;            // leading blocks factorized
};

// Fixes DOF `dof` of node `node` at value `value`: moves its column to the
// right-hand side, then replaces its row and column by the identity.
// Only the leading n blocks are touched (n < 0: all).
void applyDirichlet(BlockTridiagonal& a, std::vector<Vec6>& b, int node, int dof, double value, int n = -1);

// Dense copy, for tests and for cross-checking with general solvers.
Eigen::MatrixXd toDense(const BlockTridiagonal& a);

}  // namespace coilsim
