#pragma once
// Contact points and forces as markers (DrawPoint with a force arrow), and
// the largest wall force for the panel, read from what the contact effects
// leave in the State (RodState::contact). GL-free.
#include "physics/draw_data.h"
#include "physics/model.h"
#include "physics/state.h"

namespace coilsim::ui {

struct ContactSummary {
  bool available = false;  // this build's State carries contact forces
  int contacts = 0;        // wall, self and rod contacts found at the last step
  double maxWallForce = 0; // N, largest normal force of a wall on one node at the last step (penalty spikes too)
  // N, the sustained wall load now and its largest since the start (State::stats.wallLoad,
  // physics/contact/wall_load.h): the figure the read-outs, score sheets and plans report.
  double wallLoad = 0, wallLoadMax = 0;
};

// The markers' colours: wall contacts yellow, contacts between coils (self
// and rod) green, apart from the neck plane's light blue (app/sac_drawing)
// that they are drawn beside; the legends name both.
inline const Colour kWallContactColour(1.0f, 0.85f, 0.1f, 1.0f);
inline const Colour kCoilContactColour(0.3f, 0.95f, 0.3f, 1.0f);

// Appends one point per contact (kWallContactColour or kCoilContactColour) with an arrow along the force on the rod, the largest
// `arrowLength` m long. The point is where the rod touches: on its surface,
// on the side the force comes from (the centre line minus the contact
// normal times the rod's radius), so that a marker drawn there no larger
// than the rod (contactMarkerRadius) leaves the rod's own colour, its
// stress or wall load, visible around it. Returns the summary.
ContactSummary addContactMarkers(const Model& model, const State& state, double arrowLength, DrawData& out);

// The radius to draw contact markers with (RenderSettings::pointRadius):
// 0.6 times the thinnest rod's radius, m; 0 for a model without rods.
double contactMarkerRadius(const Model& model);

}  // namespace coilsim::ui
