// The sustained wall load, step by step.
#include "physics/contact/wall_load.h"

#include <algorithm>
#include <cmath>

#include "physics/model.h"
#include "physics/state.h"

namespace coilsim {
namespace {

// The row the next step's node forces go into, zeroed; (re)sizes the ring
// when the number of nodes or of the window's steps changed.
std::span<double> nextRow(WallLoad& load, int nodes, double h) {
  const int steps = wallLoadSteps(h);
  if (nodes != load.nodes || steps != load.steps) {
    load.nodes = nodes, load.steps = steps, load.filled = 0, load.next = 0;
    load.recent.assign(size_t(nodes) * size_t(steps), 0.0);
  }
  const std::span<double> row(load.recent.data() + size_t(load.next) * size_t(nodes), size_t(nodes));
  std::fill(row.begin(), row.end(), 0.0);
  return row;
}

// Closes the step whose row was filled: the peak, and once the window is
// full the largest over the nodes of each node's smallest force in it.
void closeRow(WallLoad& load, double t) {
  const size_t n = size_t(load.nodes);
  const double* row = load.recent.data() + size_t(load.next) * n;
  for (size_t i = 0; i < n; ++i) load.peak = std::max(load.peak, row[i]);
  load.next = (load.next + 1) % load.steps;
  load.filled = std::min(load.filled + 1, load.steps);
  if (load.filled < load.steps) return;
  double now = 0;
  for (size_t i = 0; i < n; ++i) {
    double held = row[i];
    for (int s = 0; s < load.steps && held > now; ++s) held = std::min(held, load.recent[size_t(s) * n + i]);
    now = std::max(now, held);
  }
  load.now = now;
  if (load.now > load.max) load.max = load.now, load.timeOfMax = t;
}

}  // namespace

int wallLoadSteps(double h) {
  if (!(h > 0)) return 1;
  return int(std::clamp(std::lround(kWallLoadWindow / h), 1L, long(kWallLoadMaxSteps)));
}

void addWallLoad(WallLoad& load, std::span<const double> nodeForce, double h, double t) {
  const std::span<double> row = nextRow(load, int(nodeForce.size()), h);
  std::copy(nodeForce.begin(), nodeForce.end(), row.begin());
  closeRow(load, t);
}

void addWallLoad(WallLoad& load, double force, double h, double t) {
  addWallLoad(load, std::span<const double>(&force, 1), h, t);
}

void recordWallLoad(const Model& model, State& state) {
  int nodes = 0;
  for (const RodState& r : state.rods) nodes += int(r.x.size());
  const std::span<double> row = nextRow(state.stats.wallLoad, nodes, model.timeStep);
  size_t first = 0;  // the rod's first column
  for (const RodState& r : state.rods) {
    const size_t active = size_t(std::max(r.activeNodes, 0));
    const size_t n = r.active ? std::min(r.contact.wallForce.size(), active) : 0;
    // Counted from the distal end, a node keeps its column when one is inserted at the catheter tip.
    for (size_t i = 0; i < n; ++i) row[first + active - 1 - i] = r.contact.wallForce[i];
    first += r.x.size();
  }
  closeRow(state.stats.wallLoad, state.time);
}

}  // namespace coilsim
