#pragma once
// Synthetic measurements made with coilsim's own model (a finer one than
// the workbench fits with), for tests, the shipped examples and the bench:
// each stage simulated with the `truth` parameters (hidden effects
// included), its centre line sampled at uneven arc lengths and perturbed by
// Gaussian noise of SD `sigma` per coordinate. The returned measurement
// keeps the skeleton's nominal values (young_modulus_gpa...), not the truth.
#include <cstdint>

#include "validation/simulate.h"

namespace coilsim::validation {

struct GenerateOptions {
  double sigma = 0.1e-3;          // m, per coordinate
  double minGap = 0.5e-3, maxGap = 1.5e-3;  // m, uneven sampling along the curve
  std::uint32_t seed = 1;
  SimOptions sim = {1e-3, 1e-3, 1e-3};     // finer than the workbench's default
};

// Fills the stages' centre lines (and point_sigma) of `skeleton`. Throws
// std::runtime_error naming the stage if the simulation fails.
Measurement generateMeasurement(const Measurement& skeleton, const ModelParams& truth, const GenerateOptions& o);

}  // namespace coilsim::validation
