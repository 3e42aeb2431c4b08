#include "validation/fit_staged.h"

#include <algorithm>

#include "validation/fit_jitter.h"
#include "validation/params.h"

namespace coilsim::validation {

StagedFit identifySmoothFirst(StageSimulator& sim, const Comparison& cmp, const ModelParams& start,
                              const FitOptions& options) {
  StagedFit out;
  const Measurement& m = cmp.measurement();
  out.jitter.assign(m.stages.size(), 0.0);
  // Static stages follow one equilibrium branch by continuation: smooth.
  // Only a dynamic stage can land in another state.
  Measurement smooth = m;
  smooth.stages.clear();
  for (const Stage& s : m.stages)
    if (!s.dynamic()) smooth.stages.push_back(s);
  if (smooth.stages.size() < m.stages.size() && !smooth.stages.empty()) {
    out.jitter = stageJitter(sim, cmp, start, youngModulusFit());
    for (size_t k = 0; k < m.stages.size(); ++k) out.staged = out.staged || out.jitter[k] > kJitterShare * cmp.stageSigma(k);
  }
  if (!out.staged) {
    out.fit = identify(sim, cmp, start, options);
    return out;
  }
  StageSimulator smoothSim(smooth, sim.options());
  const Comparison smoothCmp(smooth);
  const FitResult f = identify(smoothSim, smoothCmp, start, options);
  if (!f.ok) {
    out.fit = f;
    return out;
  }
  // Every stage at the smooth stages' optimum, for the residual the
  // diagnosis judges; the values and their sigmas are the smooth fit's.
  FitOptions evaluate = options;
  evaluate.params.clear();
  out.fit = identify(sim, cmp, f.params, evaluate);
  if (!out.fit.ok) return out;
  out.fit.fitted = f.fitted;
  out.fit.jacobian = f.jacobian;
  out.fit.covariance = f.covariance;
  out.fit.evaluations = f.evaluations;
  out.fit.history = f.history;
  out.fit.regularised = f.regularised;
  return out;
}

}  // namespace coilsim::validation
