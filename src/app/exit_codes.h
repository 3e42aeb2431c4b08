#pragma once
// Process exit codes of every coilsim command, and the one place a physics
// failure becomes one.
#include <optional>

#include "physics/failure.h"

namespace coilsim::app {

inline constexpr int kExitOk = 0;
inline constexpr int kExitFailure = 1;  // the simulation failed (step refused, static not converged) or rendering did
inline constexpr int kExitUsage = 2;    // bad command line or bad input file

// A definition physics refused is bad input (2); a run that failed is a
// failed simulation (1). A refused device command fails nothing by itself
// (front ends report it as a warning), so it maps to 1 only when a caller
// decides it ends the run.
inline int exitCodeOf(const Failure& f) { return f.kind == FailureKind::BadDefinition ? kExitUsage : kExitFailure; }

// A command that failed (a fit, a diagnosis): as its physics cause says when
// it has one (the Failure of the stage that could not be simulated), else a
// failed simulation (1: the optimiser gave up, nothing succeeded).
inline int exitCodeOf(const std::optional<Failure>& cause) { return cause ? exitCodeOf(*cause) : kExitFailure; }

}  // namespace coilsim::app
