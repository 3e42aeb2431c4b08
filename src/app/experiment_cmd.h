#pragma once
// `coilsim experiment injection`: the wire-injection experiment of the
// dense-packing literature (planning/wire_injection.h) over a sweep of
// cavity sizes and friction coefficients, printed as one Markdown table
// (docs/planning.md, "A published check of dense packing").
#include "app/options.h"

namespace coilsim::app {

// Returns 0, 1 if a run's step was refused (the others are still printed),
// 2 on bad input (a list item that is no number, or out of range).
int runExperiment(const ParsedArgs& args);

}  // namespace coilsim::app
