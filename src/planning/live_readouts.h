#pragma once
// What a window shows live during a manual deployment of a case's coil:
// packing density, protrusion through the neck and the wall load now, with
// warnings as they happen (protrusion; a wall load above the case's safety
// threshold). Pure computation on a Model and State; the app hands it to
// the ui as read-outs.
#include <string>
#include <vector>

#include "physics/deployment.h"
#include "planning/case_file.h"
#include "planning/metrics.h"

namespace coilsim::planning {

struct LiveLine {
  std::string label, value;
  bool warning = false;
};

class LiveReadouts {
 public:
  // `dep` names the chain: its nodes before the tip node are catheter; the coil line starts at the tip.
  LiveReadouts(const PracticeCase& practiceCase, const Deployment& dep);
  // Any sac (a scene's phantom, sceneSac), warning above `wallForceLimit` N.
  LiveReadouts(const Sac& sac, const Deployment& dep, double wallForceLimit);
  // The lines for this state. The sac metrics are recomputed at most every
  // `interval` s of simulated time (they walk every segment); the wall load
  // is the State's, kept step by step.
  std::vector<LiveLine> lines(const Model& model, const State& state);
  double interval = 0.05;  // s

  const SacMetrics& metrics() const { return metrics_; }
  bool wallLoadAvailable() const { return wallAvailable_; }
  // N, the sustained wall load now and its largest so far (State::stats.wallLoad, physics/contact/wall_load.h)
  double wallLoadNow() const { return wallNow_; }
  double wallLoadMax() const { return wallMax_; }

 private:
  Sac sac_;
  double sacVolume_ = 0;
  NeckGrid neck_;
  int chainRod_ = -1, catheterNodes_ = 0;
  double threshold_ = 0.1;  // N
  double lastTime_ = -1;
  SacMetrics metrics_;
  double wallNow_ = 0, wallMax_ = 0;
  bool wallAvailable_ = false;
};

}  // namespace coilsim::planning
