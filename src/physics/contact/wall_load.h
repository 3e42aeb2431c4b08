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
// last kWallLoadWindow seconds. Held by that one node: the window's minimum
// is taken per node, then the largest over the nodes. (The minimum over the
// steps of each step's largest node force, which this once was, counts
// spikes that move from node to node as a load: five nodes of a coil
// chattering on the wall one step each read 162 mN in the default scene's
// push where no node held more than 35 mN; docs/contact.md.) A penalty contact on a light node (a coil's
// distal tip, a node jolted by an insertion at the catheter tip) can carry a
// force that is there one step in two to four and is set by the penalty's
// stiffness, not by the wire's elasticity; a vessel wall feels what lasts.
// A load held for the window is set by the wire's elasticity (the penalty's
// penetration is a small part of the deflection), so it converges as the
// penalty stiffness grows (docs/contact.md, "The wall load").
#include <span>
#include <vector>

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
  // Each node's force at each of the last `steps` steps: a ring of rows,
  // `filled` of them valid, the next one at `next`. A node keeps its column
  // while the deployment inserts or withdraws nodes at the catheter tip:
  // columns count from each rod's distal end (recordWallLoad).
  std::vector<double> recent;  // (steps x nodes)
  int nodes = 0, steps = 0, filled = 0, next = 0;
};

// Steps the window spans at time step h (at least 1, at most kWallLoadMaxSteps).
int wallLoadSteps(double h);

// Adds one step's wall force per node `nodeForce` (N) at time `t` (s) for
// time step h. A change in the number of nodes or in the window's steps
// starts the window again (nothing counts until it is full).
void addWallLoad(WallLoad& load, std::span<const double> nodeForce, double h, double t);
// The same for a wall touched by one node only, with force `force`.
void addWallLoad(WallLoad& load, double force, double h, double t);

// After a step taken: the step's wall force per node into
// state.stats.wallLoad (dynamics.cpp). A detached coil's nodes move to
// another rod, and their window starts again there.
void recordWallLoad(const Model& model, State& state);

}  // namespace coilsim
