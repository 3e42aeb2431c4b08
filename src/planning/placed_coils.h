#pragma once
// Coils already placed in the sac while the next one goes in (a plan's
// sequence, a practice session with several coils): each is a rod of its
// own after the running deployment's rods, at its pose when it was left,
// at rest, and an obstacle of the next coil through rod contact.
#include <string>
#include <vector>

#include "physics/model.h"
#include "physics/state.h"

namespace coilsim::planning {

// A placed coil: its rod as the model defined it and its state when it was left.
struct PlacedCoil {
  RodDef def;
  RodState pose;
};

// Appends the placed coils' rods to `def`, after every rod it has (add the
// deployment's rods first, so that its rod indices are those of a run
// without placed coils). Returns the index of the first placed rod.
size_t addPlacedRods(ModelDef& def, const std::vector<PlacedCoil>& placed);

// Puts the placed coils into `state` (a makeState of the model built from
// that def), rods from `first` on: each RodState copied whole, as it was
// left, with its velocities set to zero. Throws std::invalid_argument if
// the state has fewer rods than that.
void restorePlacedRods(State& state, size_t first, const std::vector<PlacedCoil>& placed);

// After a coil has been placed: the placed coils keep the poses they have
// now in `state` (they moved while it went in), and the coil, rod `coilRod`
// of `def`, joins them as "<name> (placed)".
void keepPlacedCoils(const ModelDef& def, const State& state, size_t first, int coilRod, const std::string& name,
                     std::vector<PlacedCoil>& placed);

}  // namespace coilsim::planning
