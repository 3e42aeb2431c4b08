#pragma once
// Small scenes built inline for the renderer and ui tests (and the window
// check): a straight rod, and a helical coil leaving a catheter inside a
// spherical aneurysm on a parent vessel, with two contact markers.
#include "physics/draw_data.h"
#include "physics/model.h"
#include "physics/state.h"

namespace coilsim::testing {

// A straight 10 mm coil-like rod along x, radius 0.25 mm, clamped at node 0.
Model straightRodModel();

// A 60 mm helical platinum coil (6 mm loops, axis along y so that the AP
// view sees circles) and a straight microcatheter ending at the coil's first
// node; gravity on, the coil clamped at the catheter tip.
Model helixModel();

// What the core does not fill, added to draw data filled from a state (the
// shape of ViewerOptions::addDrawData): the rod gets a per-node colour ramp
// (to show per-node colours), the helix scene a spherical aneurysm and a
// parent vessel (closed meshes) and two contact points with force arrows.
void decorateRod(const Model& model, const State& state, DrawData& out);
void decorateHelix(const Model& model, const State& state, DrawData& out);

// fillDrawData plus the decoration.
DrawData rodDrawData(const Model& model, const State& state);
DrawData helixDrawData(const Model& model, const State& state);

}  // namespace coilsim::testing
