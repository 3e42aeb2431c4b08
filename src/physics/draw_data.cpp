#include "physics/draw_data.h"

#include "physics/model.h"
#include "physics/state.h"

namespace coilsim {

Colour defaultColour(RodRole role) {
  switch (role) {
    case RodRole::Coil: return Colour(0.85f, 0.82f, 0.75f, 1.0f);      // platinum
    case RodRole::Catheter: return Colour(0.35f, 0.55f, 0.85f, 0.9f);  // polymer blue
    case RodRole::Wire: return Colour(0.6f, 0.6f, 0.6f, 1.0f);
  }
  return Colour(1, 1, 1, 1);
}

void fillDrawData(const Model& model, const State& state, DrawData& out) {
  size_t count = 0;
  for (const RodState& r : state.rods) count += r.active ? 1 : 0;
  out.tubes.resize(count);
  size_t slot = 0;
  for (size_t k = 0; k < model.rods.size(); ++k) {
    if (!state.rods[k].active) continue;
    const RodModel& rm = model.rods[k];
    const RodState& r = state.rods[k];
    DrawTube& t = out.tubes[slot++];
    t.name = rm.name;
    t.role = rm.role;
    t.radius = rm.section.radius;
    t.centre.assign(r.x.begin(), r.x.begin() + r.activeNodes);
    t.frames.assign(r.q.begin(), r.q.begin() + r.activeNodes);
    t.colours.assign(r.activeNodes, defaultColour(rm.role));
  }
  // Obstacles (vessel walls) are drawn semi-transparent so the coil stays
  // visible inside; storage is reused, so no allocation after the first frame.
  out.meshes.resize(model.obstacles.size());
  for (size_t k = 0; k < model.obstacles.size(); ++k) {
    const Obstacle& o = model.obstacles[k];
    DrawMesh& m = out.meshes[k];
    m.name = o.name;
    if (o.mesh) {
      m.vertices.assign(o.mesh->vertices.begin(), o.mesh->vertices.end());
      m.triangles.assign(o.mesh->triangles.begin(), o.mesh->triangles.end());
    } else {
      m.vertices.clear(), m.triangles.clear();
    }
    // Touchable walls reddish, drawn-only ones grey.
    m.colour = o.contact ? Colour(0.85f, 0.35f, 0.3f, 0.3f) : Colour(0.6f, 0.6f, 0.6f, 0.2f);
  }
}

}  // namespace coilsim
