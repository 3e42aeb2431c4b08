#include "validation/adequacy.h"
#include "validation/random_vector.h"
#include "validation/text.h"

#include <cmath>
#include <cstdio>
#include <random>

namespace coilsim::validation {
namespace {

// Mean and SD over replicas of the mean squared node residual that a model
// equal to the measured spline leaves, each stage compared at `nodes`.
void noiseFloor(const Comparison& cmp, const std::vector<StageComparison>& stages, int replicas,
                std::vector<double>& mean, std::vector<double>& sd) {
  const Measurement& m = cmp.measurement();
  const size_t n = stages.size();
  // The model "x = c" at each stage's node arc lengths, and where the measured points lie on c.
  std::vector<StageSim> perfect(n);
  std::vector<std::vector<double>> at(n);
  for (size_t k = 0; k < n; ++k) {
    const SmoothingSpline& c = cmp.spline(k);
    perfect[k].failure = stages[k].failure;
    if (stages[k].s.empty() && !perfect[k].failure)
      perfect[k].failure = badDefinition("stage " + m.stages[k].name, "no nodes to compare");
    for (const double s : stages[k].s) perfect[k].s.push_back(s), perfect[k].x.push_back(c.at(s * stages[k].arcScale));
    // By the chord length along the points, scaled to the spline's length: a
    // projection onto c could jump to a neighbouring loop where loops touch.
    const std::vector<Vec3>& pts = m.stages[k].centerline;
    double chord = 0;
    at[k].push_back(0);
    for (size_t i = 1; i < pts.size(); ++i) at[k].push_back(chord += (pts[i] - pts[i - 1]).norm());
    for (double& s : at[k]) s *= c.length() / std::max(chord, 1e-300);
  }
  std::vector<double> sum(n, 0.0), sumSq(n, 0.0);
  std::vector<int> used(n, 0);
  std::mt19937 rng(20261124);
  std::normal_distribution<double> z(0.0, 1.0);
  for (int r = 0; r < replicas; ++r) {
    Measurement b = m;
    for (size_t k = 0; k < n; ++k) {
      const double sigma = cmp.stageSigma(k);
      for (size_t i = 0; i < at[k].size(); ++i)
        b.stages[k].centerline[i] = cmp.spline(k).at(at[k][i]) + sigma * drawVec3(z, rng);
    }
    const Comparison bc(b);
    const std::vector<StageComparison> s = bc.compare(perfect);
    for (size_t k = 0; k < n; ++k) {
      // A replica whose arc-length calibration ends at its bound has not
      // aligned the new spline with the old (on stacked loops a few do, with
      // node residuals of millimetres): a failed comparison, not the noise
      // (docs/validation.md, Adequacy).
      if (std::abs(s[k].arcScale - 1) > 0.99 * kArcScaleRange) continue;
      double e = 0;
      for (size_t i = 0; i < s[k].sim.size(); ++i) e += (s[k].sim[i] - s[k].meas[i]).squaredNorm();
      e /= std::max<double>(1, double(s[k].sim.size()));
      sum[k] += e, sumSq[k] += e * e, ++used[k];
    }
  }
  mean.resize(n), sd.resize(n);
  for (size_t k = 0; k < n; ++k) {
    const int r = std::max(1, used[k]);
    mean[k] = sum[k] / r;
    sd[k] = std::sqrt(std::max(0.0, sumSq[k] / r - mean[k] * mean[k]) * r / std::max(1, r - 1));
  }
}

}  // namespace

Adequacy adequacy(const Comparison& cmp, const std::vector<StageComparison>& stages, int replicas) {
  Adequacy a;
  a.explained = !stages.empty();
  std::vector<double> m0, sd0;
  noiseFloor(cmp, stages, std::max(2, replicas), m0, sd0);
  std::string worst;
  double worstRatio = 0;
  for (size_t k = 0; k < stages.size(); ++k) {
    const StageComparison& s = stages[k];
    StageAdequacy q;
    q.stage = cmp.measurement().stages[k].name;
    double sum = 0;
    for (size_t i = 0; i < s.sim.size(); ++i) sum += (s.sim[i] - s.meas[i]).squaredNorm();
    const double perNode = s.sim.empty() ? INFINITY : sum / double(s.sim.size());
    const double floor = std::max(m0[k], 1e-30);
    q.noiseFloor = std::sqrt(floor);
    q.reducedChi2 = s.ok() ? perNode / floor : INFINITY;
    q.critical = 1 + 3.09 * sd0[k] / floor;
    q.atNoise = q.reducedChi2 <= q.critical;
    if (!q.atNoise) a.explained = false;
    if (q.reducedChi2 / q.critical > worstRatio) worstRatio = q.reducedChi2 / q.critical, worst = q.stage;
    a.stages.push_back(q);
  }
  a.remaining = fingerprint(cmp, stages);
  if (a.explained)
    a.verdict = "explained: every stage's residual is at the noise (chi-square within its 99.9 % bound)";
  else
    a.verdict = "an effect is still missing: the residual of stage \"" + worst + "\" is " + fmt("%.3g", worstRatio) +
                "x its 99.9 % chi-square bound. " + a.remaining.summary;
  return a;
}

PredictionCheck predictLastStage(const Comparison& cmp, const SimOptions& options, const ModelParams& model,
                                 const std::vector<std::string>& fit, double fittedError, bool regularised) {
  PredictionCheck p;
  const Measurement& m = cmp.measurement();
  if (m.stages.size() < 2) {
    p.message = "one stage only: nothing to predict";
    return p;
  }
  Measurement earlier = m;
  earlier.stages.pop_back();
  p.stage = m.stages.back().name;
  p.fittedError = fittedError;
  StageSimulator esim(earlier, options);
  const Comparison ecmp(earlier);
  FitOptions fo;
  fo.params = fit;
  fo.regularised = regularised;
  const FitResult f = identify(esim, ecmp, model, fo);
  if (!f.ok) {
    p.message = "the fit on the earlier stages failed: " + f.message;
    return p;
  }
  StageSimulator full(m, options);
  const std::vector<StageComparison> s = cmp.compare(full.run(f.params, false));
  if (!s.back().ok()) {
    p.message = "the last stage could not be simulated with the earlier stages' fit: " + s.back().message();
    return p;
  }
  p.predictedError = s.back().metrics.stageError;
  p.ratio = p.predictedError / std::max(fittedError, 1e-300);
  p.done = true;
  p.message = "fitted on the other stages, \"" + p.stage + "\" is predicted with stage error " +
              fmt("%.4f", p.predictedError) + " against " + fmt("%.4f", fittedError) + " when fitted (" +
              fmt("%.2f", p.ratio) + "x)";
  return p;
}

}  // namespace coilsim::validation
