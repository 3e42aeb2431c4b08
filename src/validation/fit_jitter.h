#pragma once
// Does a stage's simulated outcome jump under small parameter changes?
//
// In a dynamic stage in which loops land on one another, which stacking
// the coil comes to rest in can change discontinuously with E: the whole
// coil ends in another rest state between neighbouring values. Such a stage
// cannot identify E (fit_staged.h; measured in docs/validation.md, Limits).
//
// Measure: the second difference of every node over the parameter at
// c * value * exp(-d, 0, +d) cancels a smooth response to second order
// (d^2 x''), while a jump of SD j per coordinate in independent runs gives
// var = 6 j^2; per centre c, j = RMS(second difference) / sqrt(6). The jumps
// are rare and large, so the centres span the +-20 % a fit searches and
// the largest j is returned (an RMS over a few centres misses them).
#include <string>
#include <vector>

#include "validation/compare.h"
#include "validation/simulate.h"

namespace coilsim::validation {

struct JitterOptions {
  double step = 0.01;  // d, in log value (1 %)
  std::vector<double> centres = {0.8, 0.85, 0.9, 0.95, 1.0, 1.05, 1.1, 1.15, 1.2};  // c
};

// Per stage (file order), the largest jitter j of its nodes (m per
// coordinate) under changes of the positive parameter `name` of `p`
// (params.h names); 0 for a stage that fails at some point (its residual
// is then the fit's concern). Each run is cold (pushed from zero): a warm
// start would carry one run's stacking into the next. Fails
// (std::invalid_argument) on an unknown name, like getParam.
std::vector<double> stageJitter(StageSimulator& sim, const Comparison& cmp, const ModelParams& p,
                                const std::string& name, const JitterOptions& o = {});

}  // namespace coilsim::validation
