#include "validation/metrics.h"

#include <cmath>
#include <limits>
#include <stdexcept>

namespace coilsim::validation {

StageMetrics computeMetrics(const std::vector<Vec3>& sim, const std::vector<Vec3>& meas, const std::vector<Vec3>& ref,
                            double minDisplacement) {
  if (sim.empty() || sim.size() != meas.size() || sim.size() != ref.size())
    throw std::invalid_argument("computeMetrics: simulated, measured and reference positions must be equally many nodes");
  StageMetrics m;
  double distSq = 0, dispSq = 0, sum = 0, sumSq = 0;
  for (size_t i = 0; i < sim.size(); ++i) {
    const double dist = (sim[i] - meas[i]).norm(), disp = (meas[i] - ref[i]).norm();
    distSq += dist * dist, dispSq += disp * disp;
    m.meanDistance += dist, m.meanDisplacement += disp;
    if (disp >= minDisplacement) {
      const double e = dist / disp;
      sum += e, sumSq += e * e;
      ++m.nodesCounted;
    }
  }
  const double n = double(sim.size());
  m.meanDistance /= n, m.meanDisplacement /= n;
  if (m.nodesCounted) {
    m.nodeErrorMean = sum / m.nodesCounted;
    m.nodeErrorSd = std::sqrt(std::max(0.0, sumSq / m.nodesCounted - m.nodeErrorMean * m.nodeErrorMean));
  }
  m.stageError = dispSq > 0 ? std::sqrt(distSq / dispSq) : (distSq > 0 ? std::numeric_limits<double>::infinity() : 0.0);
  return m;
}

}  // namespace coilsim::validation
