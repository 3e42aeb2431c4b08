#pragma once
// Identification: the named parameters minimising the sum of squared node
// residuals (compare.h), within bounds, by NLopt.
//
// Why NLopt rather than Ceres: the problem has 1 to 6 parameters, each
// residual evaluation is a full static continuation whose derivatives we
// only have by finite differences, and every parameter has physical bounds.
// NLopt offers bound-constrained derivative-free algorithms (BOBYQA: a
// quadratic model of the objective built from its own evaluations, the
// right tool for a smooth least-squares cost with no analytic gradient) and
// gradient ones (SLSQP, LBFGS) behind one small C library that Debian ships
// (libnlopt); Ceres would bring glog, gflags and SuiteSparse for a solver
// designed for thousands of parameters with automatic derivatives we cannot
// provide through the beam solver.
//
// Stopping rule tied to the noise: the cost is chi^2 = sum (r / sigma)^2
// with sigma the stage's point_sigma; the search stops when an iteration
// improves chi^2 by less than 0.01, since a parameter change that moves
// chi^2 by 1 is a one-sigma change, so further digits are below the noise.
// Uncertainties: cov = s^2 (J^T J)^-1 with J the central-difference
// Jacobian of the residuals at the optimum and s^2 = RSS / (m - p); a
// parameter in a null direction of J^T J is reported as not identifiable.
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "validation/compare.h"
#include "validation/params.h"

namespace coilsim::validation {

struct FitOptions {
  std::vector<std::string> params;  // names (params.h); empty: nothing fitted, only evaluated
  int maxEvaluations = 120;
  double chi2Tolerance = 0.01;
  // Regularised least squares: each parameter with a prior is held to its
  // plausible band (params.h), the MAP estimate under a prior that is flat
  // inside the band and zero outside. A soft wall (a quadratic penalty
  // beyond the band) was tried first: the node residuals' chi^2 counts
  // thousands of correlated terms, and it bought its way through any such
  // wall (E held at 4.3x its nominal instead of 2x on the self-contact
  // reference file).
  bool regularised = false;
  // Called after each evaluation (evaluation count, RMS residual per coordinate in m).
  std::function<void(int, double)> progress;
  // Asked before each evaluation (a window's Stop button); true ends the fit
  // at once: ok = false, message "stopped", no uncertainties.
  std::function<bool()> stop;
};

struct FittedValue {
  std::string name, unit;
  double value = 0, sigma = 0;  // SI
  double toSI = 1;              // edge = SI / toSI
  // False when the data do not move with this parameter (its column of the
  // Jacobian, or a combination with others, is zero: an effect that never
  // acts in these stages); sigma is then infinite, not the pseudo-inverse's 0.
  bool identifiable = true;
  // The prior (params.h): where the value lies in its plausible band (0 at
  // the nominal, +-1 at the edges) and whether it is inside.
  Prior prior;
  double priorDeviation = 0;
  bool plausible = true;
};

struct FitResult {
  bool ok = false;
  std::string message;                // why not ok (an unknown parameter, "stopped", the optimiser...)
  std::optional<Failure> failure;     // when a simulation is why: that stage's Failure (physics/failure.h)
  ModelParams params;                 // the fitted model (of the first file in a joint fit)
  std::vector<ModelParams> memberParams;  // (files) each file's fitted model in a joint fit
  std::vector<FittedValue> fitted;    // one per FitOptions::params
  Eigen::VectorXd residual;           // at the optimum, m
  Eigen::MatrixXd jacobian;           // d residual / d parameter (SI), at the optimum
  Eigen::MatrixXd covariance;         // SI
  double rss = 0;                     // m^2
  double chi2 = 0;
  bool regularised = false;
  int evaluations = 0;
  std::vector<double> history;        // RMS residual per coordinate (m) after each evaluation
};

// Fits `options.params` starting from `start` (which must have every named
// effect switched on). Fails (ok = false, message) on an unknown parameter
// or when no simulation succeeds.
FitResult identify(StageSimulator& sim, const Comparison& cmp, const ModelParams& start, const FitOptions& options);

// One file of a joint fit: its simulator, its comparison and its start
// model (its own setup: medium, effects' values from that setup).
struct FitMember {
  StageSimulator* sim = nullptr;
  const Comparison* cmp = nullptr;
  ModelParams start;
};

// Several measurements of the same coil fitted together: the named
// parameters take one value for all files (set in each file's model), the
// residuals of all files stacked. Fails like identify().
FitResult identifyJoint(const std::vector<FitMember>& members, const FitOptions& options);

// Residuals of `p` (a warm-started evaluation), m.
Eigen::VectorXd evaluateResiduals(StageSimulator& sim, const Comparison& cmp, const ModelParams& p, bool warm);

// Central-difference Jacobian of the residuals at `p` with respect to `names`.
Eigen::MatrixXd residualJacobian(StageSimulator& sim, const Comparison& cmp, const ModelParams& p,
                                 const std::vector<FitParam>& params);

}  // namespace coilsim::validation
