#include "validation/compare.h"

namespace coilsim::validation {
namespace {

// Arc length on the measured curve where the catheter tip is: 0 when the
// centre line starts at the tip; the tip's distance along the exit
// direction before the first point when sampling starts further out.
// Otherwise the tip lies near the curve's start (the first point is off it
// by noise): it is projected onto the start only, arc length at most twice
// its distance from the first point, because loops stacked over the tip
// (or crossing back past it) pass closer to it further along the curve.
double tipOffset(const SmoothingSpline& sp, const Measurement& m) {
  const double along = (sp.at(0) - m.tip.position).dot(m.tip.direction);
  if (along > 0) return -along;
  return sp.project(m.tip.position, 2 * (sp.at(0) - m.tip.position).norm() + 1e-4);
}

// The arc length of a measured curve is biased: noise lengthens it, the
// smoothing that removes the noise cuts its bends and shortens it, each by
// about 1 % for 0.1 mm noise on 1 mm sampling of 8 mm loops, which at 75 mm
// from the tip is 0.75 mm, several times the noise. So the measured arc
// length is calibrated per stage by the one factor lambda that best matches
// the simulated nodes, x_meas(s) = spline(lambda s): a bias of the
// measurement, not of the model (a coil does not stretch measurably).
double arcScale(const SmoothingSpline& sp, const StageSim& sim, double s0) {
  auto cost = [&](double lambda) {
    double c = 0;
    for (size_t i = 0; i < sim.x.size(); ++i) c += (sim.x[i] - sp.at(lambda * sim.s[i] + s0)).squaredNorm();
    return c;
  };
  // Golden section on [1 - kArcScaleRange, 1 + kArcScaleRange] (unimodal: the
  // largest shift, 5 % of the deployed length, is well below a loop).
  constexpr double g = 0.6180339887498949;
  double a = 1 - kArcScaleRange, b = 1 + kArcScaleRange;
  double x1 = b - g * (b - a), x2 = a + g * (b - a), f1 = cost(x1), f2 = cost(x2);
  for (int it = 0; it < 40 && b - a > 1e-7; ++it) {
    if (f1 < f2) b = x2, x2 = x1, f2 = f1, x1 = b - g * (b - a), f1 = cost(x1);
    else a = x1, x1 = x2, f1 = f2, x2 = a + g * (b - a), f2 = cost(x2);
  }
  return 0.5 * (a + b);
}

}  // namespace

Comparison::Comparison(const Measurement& m) : m_(m) {
  for (const Stage& st : m.stages) {
    SplineOptions o;
    o.sigma = st.pointSigma;
    splines_.emplace_back(st.centerline, o);
    sigma_.push_back(st.pointSigma > 0 ? st.pointSigma : splines_.back().sigmaUsed());
  }
  expectedNodes_.assign(m.stages.size(), 0);
}

std::vector<StageComparison> Comparison::compare(const std::vector<StageSim>& sims) const {
  std::vector<StageComparison> out(sims.size());
  for (size_t k = 0; k < sims.size(); ++k) {
    StageComparison& c = out[k];
    c.sigma = sigma_[k];
    if (!sims[k].ok()) {
      c.failure = sims[k].failure;
      continue;
    }
    const double s0 = tipOffset(splines_[k], m_);
    c.arcScale = arcScale(splines_[k], sims[k], s0);
    for (size_t i = 0; i < sims[k].x.size(); ++i) {
      const double s = sims[k].s[i];
      c.s.push_back(s);
      c.sim.push_back(sims[k].x[i]);
      c.meas.push_back(splines_[k].at(c.arcScale * s + s0));
      c.ref.push_back(m_.tip.position + s * m_.tip.direction);
    }
    c.metrics = computeMetrics(c.sim, c.meas, c.ref);
  }
  return out;
}

Eigen::VectorXd Comparison::residuals(const std::vector<StageSim>& sims) const {
  // Node counts depend on the stage only: a failed stage takes the count
  // of its last success.
  std::vector<double> out;
  const auto comps = compare(sims);
  for (size_t k = 0; k < comps.size(); ++k) {
    if (comps[k].ok()) {
      expectedNodes_[k] = comps[k].sim.size();
      for (size_t i = 0; i < comps[k].sim.size(); ++i)
        for (int d = 0; d < 3; ++d) out.push_back(comps[k].sim[i][d] - comps[k].meas[i][d]);
    } else {
      const size_t nodes = expectedNodes_[k];
      out.insert(out.end(), 3 * nodes, 0.1);
    }
  }
  return Eigen::Map<Eigen::VectorXd>(out.data(), Eigen::Index(out.size()));
}

Eigen::VectorXd Comparison::sigmas(const std::vector<StageSim>& sims) const {
  std::vector<double> out;
  for (size_t k = 0; k < sims.size(); ++k) {
    const size_t nodes = sims[k].ok() ? sims[k].x.size() : expectedNodes_[k];
    out.insert(out.end(), 3 * nodes, sigma_[k]);
  }
  return Eigen::Map<Eigen::VectorXd>(out.data(), Eigen::Index(out.size()));
}

}  // namespace coilsim::validation
