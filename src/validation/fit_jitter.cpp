#include "validation/fit_jitter.h"

#include <algorithm>
#include <cmath>

#include "validation/params.h"

namespace coilsim::validation {

std::vector<double> stageJitter(StageSimulator& sim, const Comparison& cmp, const ModelParams& p,
                                const std::string& name, const JitterOptions& o) {
  const size_t n = cmp.measurement().stages.size();
  std::vector<double> worst(n, 0.0);
  std::vector<bool> failed(n, false);
  const double v0 = getParam(p, name);
  for (const double c : o.centres) {
    std::vector<std::vector<StageSim>> runs;
    for (const double e : {-1.0, 0.0, 1.0}) {
      ModelParams q = p;
      setParam(q, name, v0 * c * std::exp(e * o.step));
      runs.push_back(sim.run(q, false));
    }
    for (size_t k = 0; k < n; ++k) {
      const StageSim &a = runs[0][k], &b = runs[1][k], &d = runs[2][k];
      if (!a.ok() || !b.ok() || !d.ok() || a.x.size() != b.x.size() || d.x.size() != b.x.size()) {
        failed[k] = true;
        continue;
      }
      double sumSq = 0;
      for (size_t i = 0; i < b.x.size(); ++i) sumSq += (a.x[i] - 2 * b.x[i] + d.x[i]).squaredNorm();
      worst[k] = std::max(worst[k], std::sqrt(sumSq / (3.0 * double(b.x.size())) / 6.0));
    }
  }
  std::vector<double> j(n, 0.0);
  for (size_t k = 0; k < n; ++k)
    if (!failed[k]) j[k] = worst[k];
  return j;
}

}  // namespace coilsim::validation
