// Live packing, protrusion and wall-load read-outs.
#include "planning/live_readouts.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

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
  sacVolume_ = volumeOnSide(*sac_.mesh, sac_.neck);
  neck_ = sampleNeck(sac_);
}

std::vector<LiveLine> LiveReadouts::lines(const Model& model, const State& state) {
  if (lastTime_ < 0 || std::abs(state.time - lastTime_) >= interval - 1e-12) {
    metrics_ = measureSac(sac_, sacVolume_, neck_, coilLines(model, state, chainRod_, catheterNodes_));
    lastTime_ = state.time;
  }
  std::vector<std::vector<double>> forces;
  wallAvailable_ = wallContactForces(model, state, forces);
  wallNow_ = 0;
  for (const auto& rod : forces)
    for (const double f : rod) wallNow_ = std::max(wallNow_, f);
  wallMax_ = std::max(wallMax_, wallNow_);

  std::vector<LiveLine> out;
  out.push_back({"packing density", format("%.1f %%", 100 * metrics_.packingDensity), false});
  out.push_back({"coil in the sac", format("%.1f mm", metrics_.coilLengthInSac * 1e3), false});
  out.push_back({"neck coverage", format("%.0f %%", 100 * metrics_.neckCoverage), false});
  if (metrics_.protruding)
    out.push_back({"PROTRUSION", format("%.1f mm of coil through the neck", metrics_.protrudingLength * 1e3), true});
  else
    out.push_back({"protrusion", "none", false});
  if (!wallAvailable_) {
    out.push_back({"wall force", "n/a (no wall contact)", false});
  } else {
    const bool high = wallNow_ > threshold_;
    out.push_back({high ? "WALL FORCE" : "wall force",
                   format("%.2f mN now", wallNow_ * 1e3) + format(" (limit %.0f mN)", threshold_ * 1e3), high});
    out.push_back({"largest wall force", format("%.2f mN", wallMax_ * 1e3), wallMax_ > threshold_});
  }
  return out;
}

}  // namespace coilsim::planning
