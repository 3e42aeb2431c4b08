#include "physics/block_tridiagonal.h"

#include <cmath>

namespace coilsim {
namespace {

// Eigen's fixed 6x6 matrices are column-major: element (r, c) is at [c * 6 + r].
inline double& at(Mat6& m, int r, int c) { return m.data()[c * 6 + r]; }
inline double at(const Mat6& m, int r, int c) { return m.data()[c * 6 + r]; }

// In-place lower Cholesky of an SPD 6x6 block; the strict upper part is left
// as garbage and never read. Returns false on a non-positive pivot.
bool cholesky6(Mat6& a) {
  for (int j = 0; j < 6; ++j) {
    double d = at(a, j, j);
    for (int k = 0; k < j; ++k) d -= at(a, j, k) * at(a, j, k);
    if (!(d > 0.0)) return false;
    const double ljj = std::sqrt(d);
    at(a, j, j) = ljj;
    const double inv = 1.0 / ljj;
    for (int i = j + 1; i < 6; ++i) {
      double s = at(a, i, j);
      for (int k = 0; k < j; ++k) s -= at(a, i, k) * at(a, j, k);
      at(a, i, j) = s * inv;
    }
  }
  return true;
}

// out = C^{-1} B^T for lower-triangular C (forward substitution, 6 columns).
void forwardTransposed(const Mat6& c, const Mat6& b, Mat6& out) {
  for (int col = 0; col < 6; ++col) {
    for (int i = 0; i < 6; ++i) {
      double s = at(b, col, i);  // (B^T)(i, col)
      for (int k = 0; k < i; ++k) s -= at(c, i, k) * at(out, k, col);
      at(out, i, col) = s / at(c, i, i);
    }
  }
}

// a -= G^T G (symmetric update of the Schur complement).
void subtractGramian(const Mat6& g, Mat6& a) {
  for (int i = 0; i < 6; ++i) {
    for (int j = 0; j <= i; ++j) {
      double s = 0;
      for (int k = 0; k < 6; ++k) s += at(g, k, i) * at(g, k, j);
      at(a, i, j) -= s;
      if (i != j) at(a, j, i) -= s;
    }
  }
}

void forwardSolve(const Mat6& c, Vec6& x) {
  for (int i = 0; i < 6; ++i) {
    double s = x[i];
    for (int k = 0; k < i; ++k) s -= at(c, i, k) * x[k];
    x[i] = s / at(c, i, i);
  }
}

void backwardSolveTransposed(const Mat6& c, Vec6& x) {
  for (int i = 5; i >= 0; --i) {
    double s = x[i];
    for (int k = i + 1; k < 6; ++k) s -= at(c, k, i) * x[k];
    x[i] = s / at(c, i, i);
  }
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

bool BlockTridiagonalSolver::factorize(const BlockTridiagonal& a) {
  const int n = a.size();
  if (int(chol_.size()) != n) resize(n);
  for (int i = 0; i < n; ++i) {
    chol_[i] = a.diag[i];
    if (i > 0) {
      forwardTransposed(chol_[i - 1], a.lower[i - 1], gain_[i]);
      subtractGramian(gain_[i], chol_[i]);
    }
    if (!cholesky6(chol_[i])) return false;
  }
  return true;
}

void BlockTridiagonalSolver::solve(std::vector<Vec6>& b) const {
  const int n = int(chol_.size());
  for (int i = 0; i < n; ++i) {
    if (i > 0) b[i].noalias() -= gain_[i].transpose() * b[i - 1];
    forwardSolve(chol_[i], b[i]);
  }
  for (int i = n - 1; i >= 0; --i) {
    if (i + 1 < n) b[i].noalias() -= gain_[i + 1] * b[i + 1];
    backwardSolveTransposed(chol_[i], b[i]);
  }
}

void applyDirichlet(BlockTridiagonal& a, std::vector<Vec6>& b, int node, int dof, double value) {
  const int n = a.size();
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
