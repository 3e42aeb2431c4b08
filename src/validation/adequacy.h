#pragma once
// Is the fitted model adequate, i.e. does its residual reach the noise?
//
// Chi-square per stage: the node residuals r_i = x_sim(s_i) - c(s_i) are
// measured against the smoothing spline c of the stage's points, so even a
// perfect model leaves the spline's own error from the noise (its variance,
// about sigma^2 edf / n per coordinate for edf effective degrees of freedom
// and n points, and its bias: smoothing shrinks loops, the arc length
// calibration). Rather than a formula that knows only the first, the noise
// floor is found by a parametric bootstrap through the same comparison: the
// points are drawn again from c with noise of the file's point_sigma, a new
// spline fitted, and the model "x = c" compared with it at the same nodes.
// Over R replicas this gives the mean squared node residual of a perfect
// model, m0, and its spread sd0. Then
//   chi2_red = (sum_i |r_i|^2 / N) / m0,
// about 1 for a right model, and the 99.9 % bound is 1 + 3.09 sd0 / m0
// (normal approximation of the replicas). The two rod models of the
// reference files reach it on their own data: the formula sigma^2 edf / n
// alone put the true model at 3.3x it. "Explained" only when every stage
// passes; otherwise "an effect is still missing", with the remaining
// residual's fingerprint.
//
// Prediction check: the same model fitted on all stages but the last
// (ordered as in the file), then run on the last: its error there beside
// the error of the fit that saw it. A model that is right predicts the
// last stage about as well as it fits it; one that absorbed a missing
// effect into its parameters does not.
#include <string>
#include <vector>

#include "validation/identify.h"

namespace coilsim::validation {

// Where a residual lies (implemented in diagnose.cpp), so that a user can
// reason about an effect not in the list.
struct Fingerprint {
  std::vector<double> rmsAlongGravity, rmsAlongCoil, rmsAcross;  // (stages) m, per node
  std::vector<double> rmsTotal;                                  // (stages) m, per node
  std::vector<double> shareProximal, shareMiddle, shareDistal;    // (stages) of sum |r|^2, thirds of the arc length
  double growthExponent = 0;  // RMS ~ l^k over the stages' deployed lengths (0 with one stage)
  bool aboveNoise = false;    // RMS per coordinate above 1.5 sigma in some stage
  std::string summary;        // one paragraph
};

Fingerprint fingerprint(const Comparison& cmp, const std::vector<StageComparison>& stages);

struct StageAdequacy {
  std::string stage;
  double reducedChi2 = 0;  // chi2_red above
  double noiseFloor = 0;   // sqrt(m0): RMS node residual of a perfect model, m
  double critical = 0;     // 99.9 % bound of chi2_red
  bool atNoise = false;
};

struct Adequacy {
  std::vector<StageAdequacy> stages;  // (stages) file order
  bool explained = false;
  std::string verdict;                // "explained: ..." or "an effect is still missing: ..."
  Fingerprint remaining;              // of the final model's residual
};

// `replicas` bootstrap draws per stage (fixed seed: the same answer every run).
Adequacy adequacy(const Comparison& cmp, const std::vector<StageComparison>& stages, int replicas = 24);

struct PredictionCheck {
  bool done = false;
  std::string message;     // why not done, or the summary
  std::string stage;       // the predicted (last) stage
  double fittedError = 0;     // its stage error with the fit on all stages
  double predictedError = 0;  // with the fit on the others
  double ratio = 0;           // predicted / fitted
};

// Fits `fit` names of `model` on every stage of `cmp` but the last, starting
// from `model`, and predicts the last (needs two stages or more).
PredictionCheck predictLastStage(const Comparison& cmp, const SimOptions& options, const ModelParams& model,
                                 const std::vector<std::string>& fit, double fittedError, bool regularised);

}  // namespace coilsim::validation
