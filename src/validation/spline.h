#pragma once
// Smoothing cubic B-spline of a measured centre line (a P-spline: Eilers &
// Marx 1996, cubic B-splines on uniform knots with a second-difference
// penalty), re-parameterised by its own arc length so that it can be
// resampled at the simulated nodes' arc lengths s.
//
// The smoothing weight follows the discrepancy principle (Morozov; Reinsch
// 1967): the mean squared residual per coordinate normal to the curve equals
// the noise variance sigma^2 (the point_sigma of the file or, when it gives
// none, an estimate from the data's local second differences); the noise
// along the curve goes into the parameterisation, not the residual.
#include <cmath>
#include <vector>

#include "physics/math.h"

namespace coilsim::validation {

struct SplineOptions {
  double sigma = 0;        // noise SD per coordinate, m; 0: estimate it from the data
  int maxIntervals = 150;  // knot intervals (fewer when there are fewer points)
  int reparameterisations = 3;  // refits on the arc length of the previous fit
};

class SmoothingSpline {
 public:
  // Fits `points` (in order along the curve, at least 2, any spacing).
  // Throws std::invalid_argument when fewer than 2 distinct points.
  SmoothingSpline(const std::vector<Vec3>& points, const SplineOptions& options = {});

  double length() const { return arc_.back(); }          // m
  Vec3 at(double s) const;       // position at arc length s; beyond the ends, continued along the end tangent
  Vec3 tangentAt(double s) const;
  double residualRms() const { return residualRms_; }    // m, per coordinate normal to the curve
  double lambda() const { return lambda_; }
  double sigmaUsed() const { return sigma_; }
  // Effective degrees of freedom of the smoother per coordinate (trace of
  // its hat matrix) and the number of points it was fitted to: the curve's
  // own error from the noise has variance sigma^2 edf / n per coordinate on
  // average over the points (adequacy.h).
  double effectiveDof() const { return edf_; }
  int points() const { return points_; }

  // Arc length where the curve passes closest to `p` (coarse table, refined),
  // searching only arc lengths up to maxArc.
  double project(const Vec3& p, double maxArc = INFINITY) const;
  // The same, searching only near curve parameter t (within one knot interval).
  double projectNear(const Vec3& p, double t) const;

 private:
  Vec3 eval(double t, int derivative) const;
  double tAtArc(double s) const;
  double arcAt(double t) const;
  void fit(const std::vector<double>& t, const std::vector<Vec3>& y, double sigma);
  void buildArcTable();

  double t0_ = 0, t1_ = 1, h_ = 1;
  int intervals_ = 4;
  std::vector<Vec3> coef_;     // (intervals + 3)
  std::vector<double> tTable_, arc_;  // dense table t -> arc length
  double residualRms_ = 0, lambda_ = 0, sigma_ = 0, edf_ = 0;
  int points_ = 0;
};

// Noise SD per coordinate estimated from how far each inner point lies off
// the chord of its two neighbours (exact for straight data, a slight
// overestimate on curved data sampled coarsely).
double estimateNoise(const std::vector<Vec3>& points);

}  // namespace coilsim::validation
