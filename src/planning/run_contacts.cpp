// The sac as a wall, and the contact effects of a run.
#include "planning/run_contacts.h"

#include <algorithm>
#include <stdexcept>

namespace coilsim::planning {

void addRunContacts(ModelDef& def, const Sac& sac) {
  if (!sac.mesh) throw std::invalid_argument("the sac has no surface to use as a wall");
  const bool sceneHasWall =
      std::any_of(def.obstacles.begin(), def.obstacles.end(), [](const Obstacle& o) { return o.contact; });
  if (!sceneHasWall) {
    Obstacle wall;
    wall.name = sac.mesh->name.empty() ? "sac" : sac.mesh->name;
    wall.mesh = sac.mesh;
    def.obstacles.push_back(std::move(wall));
  }
  for (const char* name : kRunContactEffects) {
    const bool listed =
        std::any_of(def.effects.begin(), def.effects.end(), [&](const EffectUse& e) { return e.name() == name; });
    if (listed) continue;
    EffectUse use = EffectRegistry::global().use(name);
    def.effects.push_back(std::move(use));
  }
}

void setDrawnCatheterActive(const Deployment& dep, State& state, bool active) {
  if (dep.flexible() || dep.catheterRod < 0) return;
  state.rods[size_t(dep.catheterRod)].active = active;
}

void appendInactiveCatheter(const Model& model, const State& state, const Deployment& dep, DrawData& out) {
  if (dep.flexible() || dep.catheterRod < 0) return;
  const RodState& r = state.rods[size_t(dep.catheterRod)];
  if (r.active) return;
  const RodModel& rm = model.rods[size_t(dep.catheterRod)];
  DrawTube t;
  t.name = rm.name;
  t.role = rm.role;
  t.radius = rm.section.radius;
  t.centre = r.x;
  t.frames = r.q;
  t.colours.assign(r.x.size(), defaultColour(rm.role));
  out.tubes.push_back(std::move(t));
}

}  // namespace coilsim::planning
