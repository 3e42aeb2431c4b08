#pragma once
// The comparison metrics of coil-measurement/1 (table 1 of Dequidt et al.
// 2008): per node the relative error e_i = |x_sim - x_meas| / |x_meas - x_ref|
// with x_ref on the straight catheter axis; per stage the mean and SD of e_i
// over nodes displaced by at least 1 mm, the stage error
// sqrt(sum |x_sim - x_meas|^2) / sqrt(sum |x_meas - x_ref|^2), the mean
// displacement mean |x_meas - x_ref| and the mean distance mean |x_sim - x_meas|.
#include <vector>

#include "physics/math.h"

namespace coilsim::validation {

struct StageMetrics {
  double nodeErrorMean = 0, nodeErrorSd = 0;  // over counted nodes; SD with 1/n (population)
  int nodesCounted = 0;                       // nodes with |x_meas - x_ref| >= minDisplacement
  double stageError = 0;
  double meanDisplacement = 0;  // m
  double meanDistance = 0;      // m
};

// All three arrays have one entry per node. Throws std::invalid_argument on
// mismatched or empty arrays. A stage with no displacement at all has stage
// error +inf when the simulation differs from it, 0 when it does not.
StageMetrics computeMetrics(const std::vector<Vec3>& sim, const std::vector<Vec3>& meas, const std::vector<Vec3>& ref,
                            double minDisplacement = 1e-3);

}  // namespace coilsim::validation
