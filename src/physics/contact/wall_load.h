#pragma once
// The wall load: the one figure of "how hard the coil presses on the vessel
// wall" that every front end shows (the window's panel, a practice score
// sheet, a plan, a headless run's result). Defined here once, kept in the
// State step by step, so a run gives the same figure whoever steps it, and
// going back to a saved State (the window's Reset) takes the figure back too.
//
// Definition: the sustained wall load is the largest normal force of the
// contact law on one node (RodContacts::wallForce, N: the wall's penalty on
// the node's Voronoi length of wire) that was reached at EVERY step of the
// last kWallLoadWindow seconds. A penalty contact on a light node (a coil's
// distal tip, a node jolted by an insertion at the catheter tip) can carry a
// force that is there one step in two to four and is set by the penalty's
// stiffness, not by the wire's elasticity; a vessel wall feels what lasts.
// A load held for the window is set by the wire's elasticity (the penalty's
// penetration is a small part of the deflection), so it converges as the
// penalty stiffness grows (docs/contact.md, "The wall load").
#include <array>

namespace coilsim {

struct Model;
struct State;

// s a load must last to count.
inline constexpr double kWallLoadWindow = 5e-3;
// Most steps the window holds (a time step below kWallLoadWindow / this shortens the window to this many steps).
inline constexpr int kWallLoadMaxSteps = 64;

struct WallLoad {
  double now = 0;   // N, the sustained load at the last step (0 until a whole window was stepped)
  double max = 0;   // N, the largest sustained load since the start of the run
  double peak = 0;  // N, the largest node force of any single step (penalty spikes included)
  double timeOfMax = 0;  // s, when max was reached
  // The largest node force of each of the last steps (a ring of `filled` entries, next one at `next`).
  std::array<double, kWallLoadMaxSteps> recent{};
  int filled = 0, next = 0;
};

// Steps the window spans at time step h (at least 1, at most kWallLoadMaxSteps).
int wallLoadSteps(double h);

// Adds one step's largest node wall force `stepMax` (N) at time `t` (s) for time step h.
void addWallLoad(WallLoad& load, double stepMax, double h, double t);

// The largest node wall force in the state now (every active rod's RodContacts::wallForce), N.
double largestNodeWallForce(const State& state);

// After a step taken: the step's wall force into state.stats.wallLoad (dynamics.cpp).
void recordWallLoad(const Model& model, State& state);

}  // namespace coilsim
