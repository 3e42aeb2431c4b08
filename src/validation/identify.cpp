#include "validation/identify.h"

#include <nlopt.hpp>

#include <Eigen/Eigenvalues>
#include <Eigen/LU>
#include <Eigen/QR>
#include <algorithm>
#include <cmath>
#include <set>

namespace coilsim::validation {
namespace {

// The optimiser's variable for a parameter: log(value) on wide positive
// ranges, value / (hi - lo) otherwise, so every variable moves on a scale of 1.
double toVar(const FitParam& f, double v) { return f.logScale ? std::log(v) : v / (f.hi - f.lo); }
double fromVar(const FitParam& f, double z) { return f.logScale ? std::exp(z) : z * (f.hi - f.lo); }

struct Problem {
  std::vector<FitMember> members;
  std::vector<FitParam> fit;
  const FitOptions* options = nullptr;
  int evaluations = 0;
  double best = INFINITY;
  std::vector<double> bestZ;
  std::vector<double> history;
  size_t residualSize = 0;
  bool stopped = false;
};

double objective(const std::vector<double>& z, std::vector<double>& grad, void* data) {
  auto& P = *static_cast<Problem*>(data);
  (void)grad;  // derivative-free
  if (P.options->stop && P.options->stop()) {
    P.stopped = true;
    throw nlopt::forced_stop();
  }
  Eigen::VectorXd r, s;
  for (const FitMember& mb : P.members) {
    ModelParams p = mb.start;
    for (size_t k = 0; k < z.size(); ++k) setParam(p, P.fit[k].name, fromVar(P.fit[k], z[k]));
    const auto sims = mb.sim->run(p, true);
    const Eigen::VectorXd ri = mb.cmp->residuals(sims), si = mb.cmp->sigmas(sims);
    Eigen::VectorXd r2(r.size() + ri.size()), s2(s.size() + si.size());
    r2 << r, ri;
    s2 << s, si;
    r.swap(r2), s.swap(s2);
  }
  ++P.evaluations;
  double chi2 = 1e30;
  if (r.size() == Eigen::Index(P.residualSize) && r.allFinite()) chi2 = r.cwiseQuotient(s).squaredNorm();

  const double rms = r.size() ? std::sqrt(r.squaredNorm() / double(r.size())) : 0.0;
  P.history.push_back(rms);
  if (chi2 < P.best) P.best = chi2, P.bestZ = z;
  if (P.options->progress) P.options->progress(P.evaluations, rms);
  return chi2;
}

}  // namespace

Eigen::VectorXd evaluateResiduals(StageSimulator& sim, const Comparison& cmp, const ModelParams& p, bool warm) {
  return cmp.residuals(sim.run(p, warm));
}

namespace {

// Stacked residuals of every member with the members' models `ps`.
Eigen::VectorXd stacked(const std::vector<FitMember>& members, const std::vector<ModelParams>& ps, bool warm,
                        Eigen::VectorXd* sigmas = nullptr) {
  Eigen::VectorXd r, s;
  for (size_t i = 0; i < members.size(); ++i) {
    const auto sims = members[i].sim->run(ps[i], warm);
    const Eigen::VectorXd ri = members[i].cmp->residuals(sims), si = members[i].cmp->sigmas(sims);
    Eigen::VectorXd r2(r.size() + ri.size()), s2(s.size() + si.size());
    r2 << r, ri;
    s2 << s, si;
    r.swap(r2), s.swap(s2);
  }
  if (sigmas) *sigmas = s;
  return r;
}

Eigen::MatrixXd jointJacobian(const std::vector<FitMember>& members, const std::vector<ModelParams>& ps,
                              const std::vector<FitParam>& params) {
  Eigen::MatrixXd J;
  for (size_t k = 0; k < params.size(); ++k) {
    const FitParam& f = params[k];
    const double v = getParam(ps[0], f.name);
    auto column = [&](double h, Eigen::VectorXd& col) {
      const double up = std::min(v + h, f.hi), down = std::max(v - h, f.lo);
      std::vector<ModelParams> a = ps, b = ps;
      for (auto& x : a) setParam(x, f.name, up);
      for (auto& x : b) setParam(x, f.name, down);
      const Eigen::VectorXd ra = stacked(members, a, true), rb = stacked(members, b, true);
      if (ra.size() != rb.size()) return false;
      col = (ra - rb) / (up - down);
      return true;
    };
    // A step of 1e-3 of the variable's scale, kept inside the bounds; where
    // the residual is not smooth at that scale (contacts that switch, as
    // loops land on one another in a dynamic stage), the difference across
    // a jump is not a derivative and would make sigma tiny, so the step
    // grows tenfold (up to 1e-1) until two successive steps agree to 10 %.
    double h = f.logScale ? 1e-3 * v : 1e-3 * (f.hi - f.lo);
    Eigen::VectorXd col, wider;
    if (!column(h, col)) return {};
    for (int grow = 0; grow < 2; ++grow) {
      if (!column(10 * h, wider) || wider.size() != col.size()) return {};
      if ((wider - col).norm() <= 0.1 * wider.norm()) break;
      col = wider, h *= 10;
    }
    if (J.size() == 0) J.resize(col.size(), Eigen::Index(params.size()));
    if (col.size() != J.rows()) return {};
    J.col(Eigen::Index(k)) = col;
  }
  return J;
}

}  // namespace

Eigen::MatrixXd residualJacobian(StageSimulator& sim, const Comparison& cmp, const ModelParams& p,
                                 const std::vector<FitParam>& params) {
  Eigen::MatrixXd J;
  for (size_t k = 0; k < params.size(); ++k) {
    const FitParam& f = params[k];
    const double v = getParam(p, f.name);
    // A step of 1e-3 of the variable's scale, kept inside the bounds.
    double h = f.logScale ? 1e-3 * v : 1e-3 * (f.hi - f.lo);
    const double up = std::min(v + h, f.hi), down = std::max(v - h, f.lo);
    ModelParams a = p, b = p;
    setParam(a, f.name, up);
    setParam(b, f.name, down);
    const Eigen::VectorXd ra = evaluateResiduals(sim, cmp, a, true), rb = evaluateResiduals(sim, cmp, b, true);
    if (J.size() == 0) J.resize(ra.size(), Eigen::Index(params.size()));
    if (ra.size() != J.rows() || rb.size() != J.rows()) return {};
    J.col(Eigen::Index(k)) = (ra - rb) / (up - down);
  }
  return J;
}

FitResult identify(StageSimulator& sim, const Comparison& cmp, const ModelParams& start, const FitOptions& options) {
  return identifyJoint({{&sim, &cmp, start}}, options);
}

FitResult identifyJoint(const std::vector<FitMember>& members, const FitOptions& options) {
  FitResult res;
  if (members.empty()) {
    res.message = "no measurement to fit";
    return res;
  }
  const ModelParams& start = members[0].start;
  res.params = start;
  Problem P;
  P.members = members, P.options = &options;
  for (const std::string& name : options.params) {
    std::string why;
    for (const FitMember& mb : members) {
      const auto f = describeParam(name, mb.start, mb.cmp->measurement(), why);
      if (!f) {
        res.message = why;
        return res;
      }
      if (&mb != &members[0]) continue;
      FitParam fp = *f;
      if (options.regularised && fp.prior.known)
        fp.lo = std::max(fp.lo, fp.prior.low), fp.hi = std::min(fp.hi, fp.prior.high);
      P.fit.push_back(fp);
    }
  }
  // A cold evaluation (push from zero) fixes the equilibrium branch the warm starts follow.
  Eigen::VectorXd r0;
  for (const FitMember& mb : members) {
    const auto sims0 = mb.sim->run(mb.start, false);
    const Eigen::VectorXd ri = mb.cmp->residuals(sims0);
    for (const auto& s : sims0)
      if (!s.ok()) {
        res.message = "the start model fails: " + s.message();
        res.failure = s.failure;
        res.residual = ri;
        return res;
      }
    Eigen::VectorXd r2(r0.size() + ri.size());
    r2 << r0, ri;
    r0.swap(r2);
  }
  P.residualSize = size_t(r0.size());
  const size_t n = P.fit.size();
  std::vector<double> zBest;
  if (n > 0) {
    std::vector<double> z(n), lo(n), hi(n);
    for (size_t k = 0; k < n; ++k) {
      const FitParam& f = P.fit[k];
      const double v = std::clamp(getParam(start, f.name), f.lo, f.hi);
      z[k] = toVar(f, v), lo[k] = toVar(f, f.lo), hi[k] = toVar(f, f.hi);
    }
    nlopt::opt opt(nlopt::LN_BOBYQA, unsigned(n));
    opt.set_lower_bounds(lo);
    opt.set_upper_bounds(hi);
    opt.set_min_objective(objective, &P);
    opt.set_ftol_abs(options.chi2Tolerance);
    opt.set_xtol_rel(1e-7);
    opt.set_maxeval(options.maxEvaluations);
    std::vector<double> step(n);
    for (size_t k = 0; k < n; ++k) step[k] = std::min(0.1, 0.25 * (hi[k] - lo[k]));  // 10 % of E for log variables
    opt.set_initial_step(step);
    double f = 0;
    try {
      opt.optimize(z, f);
    } catch (const std::exception& e) {
      // Roundoff-limited and max-evaluation stops still leave the best point.
      if (P.stopped) {
        res.message = "stopped";
        res.history = P.history;
        res.evaluations = P.evaluations;
        return res;
      }
      if (P.bestZ.empty()) {
        res.message = std::string("optimiser failed: ") + e.what();
        return res;
      }
    }
    if (!P.bestZ.empty()) z = P.bestZ;
    for (size_t k = 0; k < n; ++k) setParam(res.params, P.fit[k].name, fromVar(P.fit[k], z[k]));
    zBest = z;
  }
  res.memberParams.clear();
  for (const FitMember& mb : members) {
    ModelParams p = mb.start;
    for (size_t k = 0; k < n; ++k) setParam(p, P.fit[k].name, fromVar(P.fit[k], zBest[k]));
    res.memberParams.push_back(p);
  }
  res.evaluations = P.evaluations;
  res.history = P.history;
  Eigen::VectorXd sig;
  res.residual = stacked(members, res.memberParams, true, &sig);
  res.rss = res.residual.squaredNorm();
  res.chi2 = res.residual.cwiseQuotient(sig).squaredNorm();
  const double m = double(res.residual.size());
  std::set<size_t> unseen;  // parameters the data do not see
  if (n > 0) {
    res.jacobian = jointJacobian(members, res.memberParams, P.fit);
    const double s2 = res.rss / std::max(1.0, m - double(n));
    if (res.jacobian.size()) {
      // In scaled variables (each column times its parameter's magnitude),
      // so a modulus in Pa and an angle in rad do not ruin the conditioning.
      Eigen::VectorXd scale = Eigen::VectorXd::Zero(Eigen::Index(n));
      for (size_t k = 0; k < n; ++k)
        scale[Eigen::Index(k)] = std::max(std::abs(getParam(res.params, P.fit[k].name)), 1e-6 * (P.fit[k].hi - P.fit[k].lo));
      const Eigen::MatrixXd Js = res.jacobian * scale.asDiagonal();
      const Eigen::MatrixXd JtJ = Js.transpose() * Js;
      const Eigen::MatrixXd inv = JtJ.completeOrthogonalDecomposition().pseudoInverse();
      res.covariance = s2 * scale.asDiagonal() * inv * scale.asDiagonal();
      // The pseudo-inverse gives a null direction zero variance, as if the
      // data pinned it exactly: they do not see it at all.
      const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(JtJ);
      const double largest = std::max(eig.eigenvalues().maxCoeff(), 0.0);
      for (Eigen::Index i = 0; i < eig.eigenvalues().size(); ++i)
        if (!(eig.eigenvalues()[i] > 1e-12 * largest) || largest == 0)
          for (Eigen::Index k = 0; k < Eigen::Index(n); ++k)
            if (std::abs(eig.eigenvectors()(k, i)) > 1e-6) unseen.insert(size_t(k));
    }
  }
  for (size_t k = 0; k < n; ++k) {
    FittedValue v;
    v.name = P.fit[k].name;
    v.unit = P.fit[k].unit;
    v.toSI = P.fit[k].toSI;
    v.value = getParam(res.params, v.name);
    v.sigma = res.covariance.size() ? std::sqrt(std::max(0.0, res.covariance(Eigen::Index(k), Eigen::Index(k)))) : NAN;
    if (unseen.count(k)) v.identifiable = false, v.sigma = INFINITY;
    v.prior = P.fit[k].prior;
    v.priorDeviation = priorDeviation(P.fit[k], v.value);
    v.plausible = !v.prior.known || (v.value >= v.prior.low && v.value <= v.prior.high);
    res.fitted.push_back(v);
  }
  res.regularised = options.regularised;
  res.ok = true;
  return res;
}

}  // namespace coilsim::validation
