// Placed coils: rods kept in the sac from one coil's run to the next.
#include "planning/placed_coils.h"

#include <algorithm>
#include <stdexcept>

namespace coilsim::planning {

size_t addPlacedRods(ModelDef& def, const std::vector<PlacedCoil>& placed) {
  const size_t first = def.rods.size();
  for (const PlacedCoil& p : placed) def.rods.push_back(p.def);
  return first;
}

void restorePlacedRods(State& state, size_t first, const std::vector<PlacedCoil>& placed) {
  if (state.rods.size() < first + placed.size())
    throw std::invalid_argument("the state has " + std::to_string(state.rods.size()) + " rods, too few for " +
                                std::to_string(placed.size()) + " placed coils from rod " + std::to_string(first));
  for (size_t i = 0; i < placed.size(); ++i) {
    // Whole, so that whatever a rod's state carries (its contacts' memory,
    // whether it sleeps) stays with it; only the motion is dropped.
    RodState& s = state.rods[first + i];
    s = placed[i].pose;
    std::fill(s.v.begin(), s.v.end(), Vec3::Zero());
    std::fill(s.w.begin(), s.w.end(), Vec3::Zero());
    // Its self contacts name it by its index in this model; its pairs with
    // other rods named theirs in the last one, and are found anew. A
    // sleeping coil keeps its wall and self contacts (physics/sleep.h).
    for (ContactPoint& c : s.contact.self) c.other = int(first + i);
    s.contact.rod.clear();
  }
}

void keepPlacedCoils(const ModelDef& def, const State& state, size_t first, int coilRod, const std::string& name,
                     std::vector<PlacedCoil>& placed) {
  for (size_t i = 0; i < placed.size(); ++i) placed[i].pose = state.rods.at(first + i);
  PlacedCoil now{def.rods.at(size_t(coilRod)), state.rods.at(size_t(coilRod))};
  now.def.name = name + " (placed)";
  placed.push_back(std::move(now));
}

}  // namespace coilsim::planning
