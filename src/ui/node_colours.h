#pragma once
// Per-node colours the panel can ask for: the bending moment carried by the
// rod at each node, so that a clinician sees where the coil is loaded.
// GL-free (tested in tests/ui).
#include <vector>

#include "physics/draw_data.h"
#include "physics/state.h"

namespace coilsim::ui {

// Magnitude of the bending moment (the part of the elastic end moment
// normal to the element's axis; torsion left out) at each active node of
// rod `rod`, N m, from the state's element constants (a deployment
// rewrites them): the mean over the one or two elements meeting there.
// A rod bent to a circle of radius R carries E I / R. Empty for an inactive rod.
void bendingMoments(const State& state, int rod, std::vector<double>& out);

// Heat colour for t in [0, 1]: `base` at 0 through yellow to red at 1.
Colour heatColour(const Colour& base, double t);

// Recolours the tubes of `data` (filled by fillDrawData from `state`, one
// tube per active rod, in order) by bending moment: `scale` N m is fully
// red; scale <= 0 picks the largest moment. Returns the largest moment, N m.
double colourByBendingMoment(const State& state, double scale, DrawData& data);

}  // namespace coilsim::ui
