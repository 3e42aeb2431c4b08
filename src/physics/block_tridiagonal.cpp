#include "physics/block_tridiagonal.h"

#include <cmath>
#if defined(__AVX2__) && defined(__FMA__)
#include <immintrin.h>
#endif

namespace coilsim {
namespace {

// C = sign * A B^T (+ C if accumulate), all 6x6 column-major. Both products
// of the factorisation have this form. Eigen vectorises a 6-row column with
// 2-wide packets only (6 is not a multiple of 4); with AVX2 a column is one
// 4-wide and one 2-wide FMA chain, a third fewer instructions in the sweep.
// Structure the factorisation knows is skipped: B lower triangular (B = C^{-1}:
// column j of A B^T sums A(:, k) B(j, k) over k <= j only, 21 terms of 36),
// and a symmetric result of which only the lower triangle is read (rows 0-3
// of columns 4 and 5 are left as they were).
template <bool accumulate, bool negate, bool lowerTriangularB, bool lowerHalfOfC>
inline void multiplyTransposed6(const Mat6& a, const Mat6& b, Mat6& c) {
#if defined(__AVX2__) && defined(__FMA__)
  const double* A = a.data();
  const double* B = b.data();
  double* C = c.data();
  __m256d colA[6];
  __m128d colB[6];
  for (int k = 0; k < 6; ++k) colA[k] = _mm256_loadu_pd(A + 6 * k), colB[k] = _mm_loadu_pd(A + 6 * k + 4);
  for (int j = 0; j < 6; ++j) {
    const bool upperRows = !lowerHalfOfC || j < 4;
    __m256d hi = accumulate ? _mm256_loadu_pd(C + 6 * j) : _mm256_setzero_pd();
    __m128d lo = accumulate ? _mm_loadu_pd(C + 6 * j + 4) : _mm_setzero_pd();
    const int kEnd = lowerTriangularB ? j + 1 : 6;
    for (int k = 0; k < kEnd; ++k) {
      const double bjk = negate ? -B[6 * k + j] : B[6 * k + j];  // B(j, k)
      if (upperRows) hi = _mm256_fmadd_pd(colA[k], _mm256_set1_pd(bjk), hi);
      lo = _mm_fmadd_pd(colB[k], _mm_set1_pd(bjk), lo);
    }
    if (upperRows) _mm256_storeu_pd(C + 6 * j, hi);
    _mm_storeu_pd(C + 6 * j + 4, lo);
  }
#else
  if (accumulate) {
    if (negate) c.noalias() -= a * b.transpose();
    else c.noalias() += a * b.transpose();
  } else {
    if (negate) c.noalias() = -(a * b.transpose());
    else c.noalias() = a * b.transpose();
  }
#endif
}

// Eigen's fixed 6x6 matrices are column-major: element (r, c) is at [c * 6 + r].
inline double& at(Mat6& m, int r, int c) { return m.data()[c * 6 + r]; }

// Inverse of the lower Cholesky factor of an SPD 6x6 block, computed in
// place: `a` becomes C^{-1} (lower triangular, strict upper part zero).
// Keeping the inverse turns every later triangular solve into a plain
// fixed-size product, which vectorises; divisions happen 6 times per block.
bool invertedCholesky6(Mat6& a) {
  // Row-major scratch so that the inner products run over contiguous memory;
  // every loop has a compile-time trip count once unrolled.
  double c[6][6] = {};
  double inv[6];
#pragma GCC unroll 6
  for (int j = 0; j < 6; ++j) {
    double d = at(a, j, j);
#pragma GCC unroll 6
    for (int k = 0; k < j; ++k) d -= c[j][k] * c[j][k];
    if (!(d > 0.0)) return false;
    const double ljj = std::sqrt(d);
    c[j][j] = ljj;
    inv[j] = 1.0 / ljj;
#pragma GCC unroll 6
    for (int i = j + 1; i < 6; ++i) {
      double s = at(a, i, j);
#pragma GCC unroll 6
      for (int k = 0; k < j; ++k) s -= c[i][k] * c[j][k];
      c[i][j] = s * inv[j];
    }
  }
  // Forward substitution C X = I; X is lower triangular like C, so row i
  // only has columns 0..i: X(i, j) = (delta_ij - sum_{k=j..i-1} C(i, k) X(k, j)) / C(i, i).
  double x[6][6] = {};
#pragma GCC unroll 6
  for (int i = 0; i < 6; ++i) {
#pragma GCC unroll 6
    for (int j = 0; j < i; ++j) {
      double sum = 0;
#pragma GCC unroll 6
      for (int k = j; k < i; ++k) sum += c[i][k] * x[k][j];
      x[i][j] = -sum * inv[i];
    }
    x[i][i] = inv[i];
  }
#pragma GCC unroll 6
  for (int r = 0; r < 6; ++r)
#pragma GCC unroll 6
    for (int col = 0; col < 6; ++col) at(a, r, col) = x[r][col];
  return true;
}

}  // namespace

void BlockTridiagonal::resize(int n) {
  diag.assign(n, Mat6::Zero());
  lower.assign(n > 0 ? n - 1 : 0, Mat6::Zero());
}

void BlockTridiagonal::setZero() {
  for (auto& d : diag) d.setZero();
  for (auto& l : lower) l.setZero();
}

void BlockTridiagonalSolver::resize(int n) {
  chol_.assign(n, Mat6::Zero());
  gain_.assign(n, Mat6::Zero());
}

bool BlockTridiagonalSolver::factorize(const BlockTridiagonal& a, int n) {
  if (n < 0) n = a.size();
  if (int(chol_.size()) < n) resize(n);
  size_ = n;
  for (int i = 0; i < n; ++i) {
    Mat6& s = chol_[i];
    s = a.diag[i];
    if (i > 0) {
      // G^T = A(i, i-1) C_{i-1}^{-T}, then the Schur complement A(i,i) - G^T G.
      multiplyTransposed6<false, false, true, false>(a.lower[i - 1], chol_[i - 1], gain_[i]);
      multiplyTransposed6<true, true, false, true>(gain_[i], gain_[i], s);
    }
    if (!invertedCholesky6(s)) return false;
  }
  return true;
}

void BlockTridiagonalSolver::solve(std::vector<Vec6>& b) const {
  const int n = size_;
  Vec6 t;
  for (int i = 0; i < n; ++i) {
    if (i > 0) b[i].noalias() -= gain_[i] * b[i - 1];
    t.noalias() = chol_[i] * b[i];
    b[i] = t;
  }
  for (int i = n - 1; i >= 0; --i) {
    if (i + 1 < n) b[i].noalias() -= gain_[i + 1].transpose() * b[i + 1];
    t.noalias() = chol_[i].transpose() * b[i];
    b[i] = t;
  }
}

void applyDirichlet(BlockTridiagonal& a, std::vector<Vec6>& b, int node, int dof, double value, int n) {
  if (n < 0) n = a.size();
  if (value != 0.0) {
    b[node] -= a.diag[node].col(dof) * value;
    if (node + 1 < n) b[node + 1] -= a.lower[node].col(dof) * value;
    if (node > 0) b[node - 1] -= a.lower[node - 1].row(dof).transpose() * value;
  }
  a.diag[node].row(dof).setZero();
  a.diag[node].col(dof).setZero();
  a.diag[node](dof, dof) = 1.0;
  if (node + 1 < n) a.lower[node].col(dof).setZero();
  if (node > 0) a.lower[node - 1].row(dof).setZero();
  b[node][dof] = value;
}

Eigen::MatrixXd toDense(const BlockTridiagonal& a) {
  const int n = a.size();
  Eigen::MatrixXd m = Eigen::MatrixXd::Zero(6 * n, 6 * n);
  for (int i = 0; i < n; ++i) {
    m.block<6, 6>(6 * i, 6 * i) = a.diag[i];
    if (i + 1 < n) {
      m.block<6, 6>(6 * (i + 1), 6 * i) = a.lower[i];
      m.block<6, 6>(6 * i, 6 * (i + 1)) = a.lower[i].transpose();
    }
  }
  return m;
}

}  // namespace coilsim
