// Wall forces per node from the contact layer's per-rod records.
#include "planning/contact_forces.h"

namespace coilsim::planning {

bool wallContactForces(const Model& model, const State& state, std::vector<std::vector<double>>& out) {
  const EffectUse* wall = findEffect(model, "wall_contact");
  if (!wall || !wall->enabled) return false;
  out.resize(state.rods.size());
  for (size_t r = 0; r < state.rods.size(); ++r) {
    const RodState& rs = state.rods[r];
    const std::vector<double>& f = rs.contact.wallForce;
    // Only active nodes carry this step's forces.
    const size_t n = rs.active ? std::min(f.size(), size_t(std::max(rs.activeNodes, 0))) : 0;
    out[r].assign(f.begin(), f.begin() + long(n));
  }
  return true;
}

}  // namespace coilsim::planning
