#pragma once
// Identification when a dynamic stage jumps under small parameter changes
// (fit_jitter.h). A stage whose simulated outcome is not a function of the
// parameters cannot identify them: a local optimiser stops in the first of
// its dips near the start, and its Jacobian's sigma measures that dip.
// Weighting the stage by its measured jitter is not enough (the jumps are
// rare and large: their RMS over a few dozen runs is itself noise). So the
// parameters are fitted on the stages that do not jump, and every stage is
// then simulated and compared at that optimum: the jumping stages still
// count in the residual the diagnosis judges (explained fraction,
// significance), in the stage errors and in the adequacy test. What is
// lost is what the jumping stage alone could tell (e.g. inertia).
// Measurements: docs/validation.md (Method, Limits).
#include <vector>

#include "validation/identify.h"

namespace coilsim::validation {

struct StagedFit {
  FitResult fit;               // values and sigmas from the stages that do not jump; residual of all
  std::vector<double> jitter;  // (stages) m per coordinate, 0 for a stage not measured (static)
  bool staged = false;         // some dynamic stage jumped: the others were fitted alone
};

// A stage jumps when its jitter under young_modulus exceeds this share of its point sigma.
inline constexpr double kJitterShare = 0.1;

// Fits `options.params` like identify(). When the measurement has both
// static and dynamic stages, each dynamic stage's jitter under
// young_modulus is measured at `start`; if one jumps, the parameters are
// fitted on the static stages and the result carries every stage's
// residual at that optimum. Otherwise it is identify() itself. Fails like
// identify().
StagedFit identifySmoothFirst(StageSimulator& sim, const Comparison& cmp, const ModelParams& start,
                              const FitOptions& options);

}  // namespace coilsim::validation
