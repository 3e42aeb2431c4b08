#pragma once
// Simulated stages against the measurement: the measured centre lines are
// fitted once by smoothing splines; each simulation is resampled at its
// nodes' arc lengths (the measured arc length calibrated by one factor per
// stage, see compare.cpp) and scored (metrics.h), and its residuals
// x_sim - x_meas(s) form the least-squares vector of identification.
#include <optional>
#include <string>
#include <vector>

#include "validation/metrics.h"
#include "validation/simulate.h"
#include "validation/spline.h"

namespace coilsim::validation {

// The arc-length calibration lambda lies in [1 - this, 1 + this] (compare.cpp).
inline constexpr double kArcScaleRange = 0.05;

struct StageComparison {
  std::optional<Failure> failure;        // the stage's simulation failed (StageSim::failure): nothing compared
  StageMetrics metrics;
  std::vector<double> s;                 // (nodes) arc length, m
  std::vector<Vec3> sim, meas, ref;      // (nodes) m
  double sigma = 0;                      // noise SD per coordinate used for this stage, m
  double arcScale = 1;                   // calibration of the measured arc length (compare.cpp)
  bool ok() const { return !failure; }
  std::string message() const { return failure ? describe(*failure) : std::string(); }
};

class Comparison {
 public:
  // Fits one smoothing spline per stage (noise from point_sigma, or estimated).
  explicit Comparison(const Measurement& m);
  std::vector<StageComparison> compare(const std::vector<StageSim>& sims) const;
  // (x_sim - x_meas) of every node of every stage, stacked (3 per node), m.
  // A failed stage contributes a penalty of 0.1 m per coordinate, so an
  // optimiser backs away from it. The length depends only on the stages.
  Eigen::VectorXd residuals(const std::vector<StageSim>& sims) const;
  // Noise SD per coordinate of each residual entry (the stage's sigma).
  Eigen::VectorXd sigmas(const std::vector<StageSim>& sims) const;
  const SmoothingSpline& spline(size_t stage) const { return splines_[stage]; }
  double stageSigma(size_t stage) const { return sigma_[stage]; }
  const Measurement& measurement() const { return m_; }

 private:
  Measurement m_;
  std::vector<SmoothingSpline> splines_;
  std::vector<double> sigma_;
  mutable std::vector<size_t> expectedNodes_;  // (stages) nodes of the last successful simulation
};

}  // namespace coilsim::validation
