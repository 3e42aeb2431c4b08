#pragma once
// Result files ("coilsim-result/1", docs/scene-format.md): the final state
// of a run in millimetres, so anyone can check a result without reading C++.
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "io/scene.h"
#include "physics/deployment.h"
#include "physics/integrator.h"
#include "physics/model.h"
#include "physics/state.h"

namespace coilsim::io {

inline constexpr const char* kResultFormat = "coilsim-result/1";

// What a clinician reads off a run whose scene has a phantom with its sac
// (planning fills it, app writes it): SI and fractions here, written in
// millimetres, percent and millinewtons.
struct ClinicalReadouts {
  double packingDensity = 0;    // coil volume in the sac over the sac's volume, 0-1
  double coilLengthInSac = 0;   // m
  double coilVolume = 0, sacVolume = 0;  // m^3 (packing = coilVolume / sacVolume)
  double neckCoverage = 0;      // 0-1
  bool protruding = false;
  double protrudingLength = 0;  // m of coil beyond the neck plane
  bool wallLoadAvailable = false;  // the run has wall contact
  double wallLoad = 0, largestWallLoad = 0;  // N, sustained (physics/contact/wall_load.h), now and largest
  double wallLoadWindow = 0;    // s a load must last to count
};

// How a run went, besides the state itself.
struct RunRecord {
  std::string scene;       // scene file as given on the command line
  std::string sceneName;
  SolveMode solve = SolveMode::Dynamic;
  std::string status = "ok";  // "ok", "step_refused" or "not_converged"
  std::string error;          // why, when status is not "ok"
  std::optional<StaticReport> statics;  // static solves only
  std::vector<std::string> warnings;    // scene warnings and refused commands; the state's are added
  std::optional<DeviceState> deployment;  // scenes with a deployment
  std::optional<CatheterTip> catheterTip;     // its catheter tip (kickback, angle), when there is one
  std::optional<ClinicalReadouts> readouts;   // scenes with a phantom's sac
};

// FNV-1a 64-bit over the raw bytes of every rod's x, q, v, w (all nodes, rod
// by rod), as 16 hex digits: equal hashes mean a bit-for-bit equal state.
std::string stateHash(const State& state);

// The result document: format, scene, status, time_s, steps, state_hash,
// rods (nodes_mm, rotations w x y z of the active nodes; "active": false for
// a rod not simulated now), deployment (when there is one), energy (J),
// stats, static (when static), readouts (when there are), warnings.
nlohmann::ordered_json resultJson(const Model& model, const State& state, const RunRecord& run);

// resultJson, formatted, written atomically to `path`. Throws
// std::runtime_error naming the path on failure.
void writeResult(const std::string& path, const Model& model, const State& state, const RunRecord& run);

}  // namespace coilsim::io
