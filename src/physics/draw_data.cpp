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
  out.tubes.resize(model.rods.size());
  for (size_t k = 0; k < model.rods.size(); ++k) {
    const RodModel& rm = model.rods[k];
    DrawTube& t = out.tubes[k];
    t.name = rm.name;
    t.role = rm.role;
    t.radius = rm.section.radius;
    t.centre = state.rods[k].x;
    t.frames = state.rods[k].q;
    t.colours.assign(rm.nnode, defaultColour(rm.role));
  }
}

}  // namespace coilsim
