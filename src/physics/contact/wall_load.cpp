// The sustained wall load, step by step.
#include "physics/contact/wall_load.h"

#include <algorithm>
#include <cmath>

#include "physics/model.h"
#include "physics/state.h"

namespace coilsim {

int wallLoadSteps(double h) {
  if (!(h > 0)) return 1;
  return int(std::clamp(std::lround(kWallLoadWindow / h), 1L, long(kWallLoadMaxSteps)));
}

void addWallLoad(WallLoad& load, double stepMax, double h, double t) {
  const int n = wallLoadSteps(h);
  load.peak = std::max(load.peak, stepMax);
  load.recent[size_t(load.next)] = stepMax;
  load.next = (load.next + 1) % n;
  load.filled = std::min(load.filled + 1, n);
  if (load.filled < n) return;
  load.now = *std::min_element(load.recent.begin(), load.recent.begin() + n);
  if (load.now > load.max) load.max = load.now, load.timeOfMax = t;
}

double largestNodeWallForce(const State& state) {
  double m = 0;
  for (const RodState& r : state.rods) {
    if (!r.active) continue;
    // Only active nodes carry this step's forces.
    const size_t n = std::min(r.contact.wallForce.size(), size_t(std::max(r.activeNodes, 0)));
    for (size_t i = 0; i < n; ++i) m = std::max(m, r.contact.wallForce[i]);
  }
  return m;
}

void recordWallLoad(const Model& model, State& state) {
  addWallLoad(state.stats.wallLoad, largestNodeWallForce(state), model.timeStep, state.time);
}

}  // namespace coilsim
