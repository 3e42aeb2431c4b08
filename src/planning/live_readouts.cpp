// Live packing, protrusion and wall-load read-outs.
#include "planning/live_readouts.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "io/units.h"
#include "planning/contact_forces.h"

namespace coilsim::planning {
namespace {

std::string format(const char* f, double v) {
  char b[64];
  std::snprintf(b, sizeof b, f, v);
  return b;
}

}  // namespace

LiveReadouts::LiveReadouts(const PracticeCase& pc, const Deployment& dep)
    : LiveReadouts(pc.sac, dep, pc.goal.maxWallForce) {}

LiveReadouts::LiveReadouts(const Sac& sac, const Deployment& dep, double wallForceLimit)
    : sac_(makeSac(sac.mesh, sac.neck)),
      chainRod_(dep.chainRod),
      catheterNodes_(dep.tipNode),
      threshold_(wallForceLimit) {
  sacVolume_ = sacVolume(sac_);
  neck_ = sampleNeck(sac_);
}

std::vector<LiveLine> LiveReadouts::lines(const Model& model, const State& state) {
  if (lastTime_ < 0 || std::abs(state.time - lastTime_) >= interval - 1e-12) {
    metrics_ = measureSac(sac_, sacVolume_, neck_, coilLines(model, state, chainRod_, catheterNodes_));
    lastTime_ = state.time;
  }
  // The contact layer's sustained load, kept in the State step by step (so a
  // window that reads it once a frame shows what the score sheet and plan report).
  wallAvailable_ = hasWallForces(model, state);
  wallNow_ = state.stats.wallLoad.now;
  wallMax_ = state.stats.wallLoad.max;

  std::vector<LiveLine> out;
  out.push_back({"packing density", format("%.1f %%", 100 * metrics_.packingDensity), false});
  out.push_back({"coil in the sac", format("%.1f mm", units::mToMm(metrics_.coilLengthInSac)), false});
  out.push_back({"neck coverage", format("%.0f %%", 100 * metrics_.neckCoverage), false});
  if (metrics_.protruding)
    out.push_back({"PROTRUSION", format("%.1f mm of coil through the neck", units::mToMm(metrics_.protrudingLength)), true});
  else
    out.push_back({"protrusion", "none", false});
  if (!wallAvailable_) {
    out.push_back({"wall load", "n/a (no wall contact)", false});
  } else {
    const bool high = wallNow_ > threshold_;
    out.push_back({high ? "WALL LOAD" : "wall load",
                   format("%.2f mN now", units::nToMn(wallNow_)) + format(" (limit %.0f mN)", units::nToMn(threshold_)), high});
    out.push_back({"largest wall load", format("%.2f mN", units::nToMn(wallMax_)), wallMax_ > threshold_});
    out.push_back({"wall load is", format("the largest node force lasting %.0f ms", units::sToMs(kWallLoadWindow)), false});
  }
  return out;
}

}  // namespace coilsim::planning
