#pragma once
// coil-measurement/1 files (../shared/formats/coil-measurement.md) <-> the
// validation::Measurement data, in SI. Unknown keys are ignored, as the
// format says; everything else is checked on entry.
#include <string>
#include <string_view>

#include "validation/measurement.h"

namespace coilsim::io {

// Reads the file at `path`. Throws InputError naming the file, the JSON
// path and what was expected: a missing required field, a wrong type, a
// non-finite number, an empty or one-point centre line, a stage longer than
// the coil, a non-unit direction, a reference normal not orthogonal to it,
// a push history out of order or without capture time.
validation::Measurement readMeasurement(const std::string& path);
// The same from text; `file` only labels messages.
validation::Measurement parseMeasurement(std::string_view text, const std::string& file);

// The file text of `m` (millimetres, GPa, degrees), which parseMeasurement
// reads back to the same values up to rounding of the printed digits.
// Throws std::invalid_argument for a rest shape the format has no name for
// (a bird-cage).
std::string formatMeasurement(const validation::Measurement& m);

}  // namespace coilsim::io
