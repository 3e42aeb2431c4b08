#pragma once
// Coil-choice planning: each candidate coil is deployed automatically into the
// same aneurysm from the same catheter position (or small variations of it,
// for sensitivity), headless, and the outcomes are compared side by side.
// Candidates are independent: runCandidates runs them on several threads,
// one Model and State each.
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "io/coil_catalogue.h"
#include "io/scene.h"
#include "physics/model.h"
#include "physics/state.h"
#include "planning/auto_deploy.h"
#include "planning/metrics.h"
#include "planning/sac_geometry.h"

namespace coilsim::planning {

// Everything the candidates share.
struct PlanSetup {
  std::string label;           // scene or case file, for reports
  io::SceneSpec scene;         // has a deployment block; each candidate replaces its coil
  Sac sac;
  double sacVolume = 0;        // m^3, volumeOnSide(sac)
  NeckGrid neck;
  double spacingMm = 0.5;      // beam length of the candidate coils
  AutoDeployOptions deploy;
  MetricOptions metrics;
};

// Fills sacVolume and neck from sac; throws std::invalid_argument if the
// neck plane leaves no volume on the sac side.
void prepareSac(PlanSetup& setup);

// One run: a coil, or a sequence of coils deployed one after the other
// (framing, then filling, then finishing: each detached coil stays in the
// sac as an obstacle of the next, through rod_contact), and a catheter tip
// variation (sensitivity).
struct Candidate {
  std::vector<io::CoilSpec> coils;  // one, or a sequence in deployment order
  std::string variant = "nominal";
  Vec3 tipShiftMm = Vec3::Zero();  // added to the catheter tip position
  double tipTiltDeg = 0;           // exit direction turned about the reference normal
  std::string sequence;            // the case's name of the sequence, when it is one of a case's "sequences"
  std::string name() const;        // the coil names joined by " + "
};

// How far a run is, for a progress line.
struct RunProgress {
  size_t coil = 0, coils = 1;   // coil (0-based) of the candidate's coils being deployed
  std::string coilName;
  double deployed = 0;          // m of this coil out
  double coilLength = 0;        // m
  double deployedBefore = 0;    // m of the coils before it (each counted whole)
  double time = 0;              // s simulated by the run so far
};
using RunProgressCallback = std::function<void(const RunProgress&)>;

struct CandidateResult {
  std::string name, variant, sequence;
  bool ok = false;
  std::string error;
  SacMetrics sac;
  int occlusion = 3;
  AutoDeployResult deploy;  // of the whole sequence: times and counts summed, maxima over the coils
  double wallSeconds = 0;  // wall time of the run
  Model model;             // final configuration, for the screenshot
  State state;
};

// Deploys one candidate; never throws (errors land in `error`). Contact
// detection uses `detectionThreads` (1 or 2) threads; the results are the
// same bit for bit (physics/contact/detect_parallel.h).
CandidateResult runCandidate(const PlanSetup& setup, const Candidate& candidate, const WallForceCheck& contacts = {},
                             int detectionThreads = 1, const RunProgressCallback& progress = {});

// Threads for each run's contact detection when `runsAtOnce` runs go at
// once: 2 for a single run on a machine of two cores or more whose load
// leaves a core idle, else 1. (The results are the same either way.)
int detectionThreadsFor(int runsAtOnce);

// All candidates on up to `jobs` threads; results in the candidates' order.
std::vector<CandidateResult> runCandidates(const PlanSetup& setup, const std::vector<Candidate>& candidates, int jobs,
                                           const WallForceCheck& contacts = {});

// Sensitivity variants of a coil: nominal, tip shifted by +-shift along the
// two axes across the exit direction, exit direction tilted by +-tilt.
std::vector<Candidate> sensitivityVariants(const std::vector<io::CoilSpec>& coils, double shiftMm, double tiltDeg);

// DIR/plan.json body: {"format": "coilsim-plan/1", "scene", "sac_volume_mm3", "coils": [...]}.
nlohmann::ordered_json planJson(const PlanSetup& setup, const std::vector<CandidateResult>& results);
// The same as a Markdown table with a short reading guide.
std::string planMarkdown(const nlohmann::ordered_json& plan);

// Merges plan.json documents (e.g. one per Slurm array task) into one; throws
// io::InputError naming the file if one is not a coilsim-plan/1 document.
nlohmann::ordered_json mergePlans(const std::vector<std::string>& planFiles);

}  // namespace coilsim::planning
