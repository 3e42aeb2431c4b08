#include "validation/spline.h"

#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace coilsim::validation {
namespace {

// Uniform cubic B-spline basis on one knot interval: the four functions that
// are non-zero there, and their derivatives with respect to u in [0, 1].
void basis(double u, double b[4], double d[4]) {
  const double v = 1 - u;
  b[0] = v * v * v / 6;
  b[1] = (3 * u * u * u - 6 * u * u + 4) / 6;
  b[2] = (-3 * u * u * u + 3 * u * u + 3 * u + 1) / 6;
  b[3] = u * u * u / 6;
  d[0] = -v * v / 2;
  d[1] = (3 * u * u - 4 * u) / 2;
  d[2] = (-3 * u * u + 2 * u + 1) / 2;
  d[3] = u * u / 2;
}

}  // namespace

double estimateNoise(const std::vector<Vec3>& p) {
  if (p.size() < 3) return 0;
  std::vector<double> t(p.size(), 0.0);
  for (size_t i = 1; i < p.size(); ++i) t[i] = t[i - 1] + (p[i] - p[i - 1]).norm();
  double sum = 0;
  int n = 0;
  for (size_t i = 1; i + 1 < p.size(); ++i) {
    const double span = t[i + 1] - t[i - 1];
    if (!(span > 0)) continue;
    const double a = (t[i + 1] - t[i]) / span, b = (t[i] - t[i - 1]) / span;
    const Vec3 r = p[i] - (a * p[i - 1] + b * p[i + 1]);
    // r = e_i - a e_{i-1} - b e_{i+1}: variance sigma^2 (1 + a^2 + b^2) per
    // coordinate across the curve; along it the chord parameter follows the
    // noise, so only the two normal coordinates count.
    sum += r.squaredNorm() / (2 * (1 + a * a + b * b));
    ++n;
  }
  return n ? std::sqrt(sum / n) : 0.0;
}

SmoothingSpline::SmoothingSpline(const std::vector<Vec3>& points, const SplineOptions& o) {
  std::vector<Vec3> y;
  for (const Vec3& p : points)
    if (y.empty() || (p - y.back()).norm() > 1e-12) y.push_back(p);
  if (y.size() < 2) throw std::invalid_argument("a centre line needs at least 2 distinct points");
  sigma_ = o.sigma > 0 ? o.sigma : estimateNoise(y);
  const int n = int(y.size());
  intervals_ = std::clamp(n / 2, 1, std::max(1, o.maxIntervals));
  std::vector<double> t(n, 0.0);
  for (int i = 1; i < n; ++i) t[i] = t[i - 1] + (y[i] - y[i - 1]).norm();
  for (int pass = 0; pass <= o.reparameterisations; ++pass) {
    fit(t, y, sigma_);
    buildArcTable();
    if (pass == o.reparameterisations) break;
    // Chord lengths of noisy points overstate the arc length; the fitted
    // curve's own arc length at each point's foot does not.
    // Each point projects near where it was, not onto a neighbouring loop.
    std::vector<double> s(n);
    for (int i = 0; i < n; ++i) s[i] = projectNear(y[i], t[i]);
    for (int i = 1; i < n; ++i) s[i] = std::max(s[i], s[i - 1] + 1e-9);
    t = s;
  }
}

void SmoothingSpline::fit(const std::vector<double>& t, const std::vector<Vec3>& y, double sigma) {
  const int n = int(y.size()), K = intervals_, nb = K + 3;
  t0_ = t.front(), t1_ = t.back();
  h_ = (t1_ - t0_) / K;
  Eigen::MatrixXd BtB = Eigen::MatrixXd::Zero(nb, nb), Bty = Eigen::MatrixXd::Zero(nb, 3);
  for (int i = 0; i < n; ++i) {
    const double x = (t[i] - t0_) / h_;
    const int j = std::clamp(int(std::floor(x)), 0, K - 1);
    double b[4], d[4];
    basis(x - j, b, d);
    for (int a = 0; a < 4; ++a) {
      Bty.row(j + a) += b[a] * y[i].transpose();
      for (int c = 0; c < 4; ++c) BtB(j + a, j + c) += b[a] * b[c];
    }
  }
  Eigen::MatrixXd DtD = Eigen::MatrixXd::Zero(nb, nb);  // second differences of the coefficients
  for (int k = 0; k + 2 < nb; ++k) {
    const double w[3] = {1, -2, 1};
    for (int a = 0; a < 3; ++a)
      for (int c = 0; c < 3; ++c) DtD(k + a, k + c) += w[a] * w[c];
  }
  // Returns the noise SD the residual implies: rss / (2 (n - edf)), with
  // edf = trace of the hat matrix (the fit's effective parameters), so the
  // target is the unbiased one (the plain RSS = n sigma^2 rule of the
  // discrepancy principle over-smooths, shrinking loops and arc length).
  auto solve = [&](double lambda, Eigen::MatrixXd& c) {
    // A tiny ridge keeps the system regular where knots hold no data.
    Eigen::MatrixXd A = BtB + lambda * DtD + 1e-12 * BtB.trace() / nb * Eigen::MatrixXd::Identity(nb, nb);
    const Eigen::LDLT<Eigen::MatrixXd> ldlt(A);
    c = ldlt.solve(Bty);
    const double edf = ldlt.solve(BtB).trace();
    edf_ = edf, points_ = n;
    double rss = 0;
    for (int i = 0; i < n; ++i) {
      const double x = (t[i] - t0_) / h_;
      const int j = std::clamp(int(std::floor(x)), 0, K - 1);
      double b[4], d[4];
      basis(x - j, b, d);
      Eigen::RowVector3d p = Eigen::RowVector3d::Zero();
      for (int a = 0; a < 4; ++a) p += b[a] * c.row(j + a);
      rss += (p - y[i].transpose()).squaredNorm();
    }
    // After re-parameterisation the residuals are normal to the curve: two
    // coordinates per point carry the noise.
    return std::sqrt(rss / (2.0 * std::max(1.0, n - edf)));
  };
  Eigen::MatrixXd c;
  // The residual grows with lambda: bisect log(lambda) for residual = sigma.
  double lo = -12, hi = 12;
  double rms = solve(std::pow(10.0, lo), c);
  if (sigma > 0 && rms < sigma) {
    for (int it = 0; it < 40; ++it) {
      const double mid = 0.5 * (lo + hi);
      (solve(std::pow(10.0, mid), c) < sigma ? lo : hi) = mid;
    }
    lambda_ = std::pow(10.0, lo);
  } else {
    lambda_ = std::pow(10.0, lo);
  }
  residualRms_ = solve(lambda_, c);
  coef_.resize(nb);
  for (int k = 0; k < nb; ++k) coef_[k] = c.row(k).transpose();
}

Vec3 SmoothingSpline::eval(double t, int derivative) const {
  const double x = (t - t0_) / h_;
  const int j = std::clamp(int(std::floor(x)), 0, intervals_ - 1);
  double b[4], d[4];
  basis(std::clamp(x - j, 0.0, 1.0), b, d);
  Vec3 p = Vec3::Zero();
  for (int a = 0; a < 4; ++a) p += (derivative ? d[a] / h_ : b[a]) * coef_[j + a];
  return p;
}

void SmoothingSpline::buildArcTable() {
  const int m = 40 * intervals_;
  tTable_.resize(m + 1);
  arc_.assign(m + 1, 0.0);
  for (int k = 0; k <= m; ++k) tTable_[k] = t0_ + (t1_ - t0_) * k / m;
  // Simpson on each table step: the speed is smooth within a knot interval.
  for (int k = 1; k <= m; ++k) {
    const double a = tTable_[k - 1], b = tTable_[k];
    arc_[k] = arc_[k - 1] + (b - a) / 6 *
                                (eval(a, 1).norm() + 4 * eval(0.5 * (a + b), 1).norm() + eval(b, 1).norm());
  }
}

double SmoothingSpline::tAtArc(double s) const {
  const auto it = std::lower_bound(arc_.begin(), arc_.end(), s);
  if (it == arc_.begin()) return tTable_.front();
  if (it == arc_.end()) return tTable_.back();
  const size_t k = size_t(it - arc_.begin());
  const double f = (s - arc_[k - 1]) / std::max(arc_[k] - arc_[k - 1], 1e-300);
  return tTable_[k - 1] + f * (tTable_[k] - tTable_[k - 1]);
}

Vec3 SmoothingSpline::at(double s) const {
  if (s < 0) return eval(t0_, 0) + s * tangentAt(0);
  if (s > length()) return eval(t1_, 0) + (s - length()) * tangentAt(length());
  return eval(tAtArc(s), 0);
}

Vec3 SmoothingSpline::tangentAt(double s) const {
  return eval(tAtArc(std::clamp(s, 0.0, length())), 1).normalized();
}

double SmoothingSpline::projectNear(const Vec3& p, double t) const {
  // Newton on the foot-point condition (c(t) - p) . c'(t) = 0 from t, within +-1 knot interval.
  const double lo = std::max(t0_, t - h_), hi = std::min(t1_, t + h_);
  t = std::clamp(t, t0_, t1_);
  for (int it = 0; it < 8; ++it) {
    const Vec3 r = eval(t, 0) - p, d1 = eval(t, 1);
    const double gp = d1.squaredNorm();
    if (!(gp > 0)) break;
    t = std::clamp(t - r.dot(d1) / gp, lo, hi);
  }
  return arcAt(t);
}

double SmoothingSpline::arcAt(double t) const {
  const auto it = std::lower_bound(tTable_.begin(), tTable_.end(), t);
  if (it == tTable_.begin()) return 0;
  if (it == tTable_.end()) return arc_.back();
  const size_t k = size_t(it - tTable_.begin());
  const double f = (t - tTable_[k - 1]) / (tTable_[k] - tTable_[k - 1]);
  return arc_[k - 1] + f * (arc_[k] - arc_[k - 1]);
}

double SmoothingSpline::project(const Vec3& p, double maxArc) const {
  size_t best = 0;
  double bestD = INFINITY;
  for (size_t k = 0; k < tTable_.size() && arc_[k] <= maxArc; k += 4) {
    const double d = (eval(tTable_[k], 0) - p).squaredNorm();
    if (d < bestD) bestD = d, best = k;
  }
  // Refine on the neighbouring table entries by golden-section-free scanning.
  const size_t lo = best >= 4 ? best - 4 : 0, hi = std::min(tTable_.size() - 1, best + 4);
  for (size_t k = lo; k <= hi && arc_[k] <= maxArc; ++k) {
    const double d = (eval(tTable_[k], 0) - p).squaredNorm();
    if (d < bestD) bestD = d, best = k;
  }
  // Newton on the foot-point condition (c(t) - p) . c'(t) = 0 within one table step.
  double t = tTable_[best];
  for (int it = 0; it < 5; ++it) {
    const Vec3 r = eval(t, 0) - p, d1 = eval(t, 1);
    const double g = r.dot(d1), gp = d1.squaredNorm();
    if (!(gp > 0)) break;
    t = std::clamp(t - g / gp, t0_, t1_);
  }
  return arcAt(t);
}

}  // namespace coilsim::validation
