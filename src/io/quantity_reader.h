#pragma once
// Reading a rod quantity (physics/rod_quantities.h) from a file: its key,
// its bounds in the edge unit and its SI factor all come from the one
// declaration, so scene and measurement files cannot disagree on them.
#include "io/json_reader.h"
#include "physics/rod_quantities.h"

namespace coilsim::io {

// The bounds of `q` in its edge unit, as error messages quote them.
inline Bounds boundsOf(const rodq::Quantity& q) { return {q.spec.min, q.spec.max, q.minOpen, false, q.spec.unit}; }

// The value of `q` under `parent`, in the edge unit. Fails (InputError naming
// the file and the JSON path) if it is missing, not a number or out of bounds.
inline double readEdge(const JsonNode& parent, const rodq::Quantity& q) {
  return parent.child(q.spec.name).number(boundsOf(q));
}

}  // namespace coilsim::io
