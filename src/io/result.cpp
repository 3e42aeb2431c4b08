#include "io/result.h"

#include <cstdint>
#include <cstdio>
#include <algorithm>

#include "io/json_writer.h"
#include "io/units.h"

namespace coilsim::io {

namespace {

// FNV-1a, 64-bit (Fowler, Noll, Vo): offset basis and prime.
constexpr uint64_t kFnvOffset = 14695981039346656037ull;
constexpr uint64_t kFnvPrime = 1099511628211ull;

template <class T>
void hashBytes(uint64_t& h, const std::vector<T>& values) {
  const auto* bytes = reinterpret_cast<const unsigned char*>(values.data());
  for (size_t i = 0; i < values.size() * sizeof(T); ++i) h = (h ^ bytes[i]) * kFnvPrime;
}

}  // namespace

std::string stateHash(const State& state) {
  // Eigen's fixed-size vectors and quaternions hold their doubles contiguously, no padding.
  static_assert(sizeof(Vec3) == 3 * sizeof(double) && sizeof(Quat) == 4 * sizeof(double));
  uint64_t h = kFnvOffset;
  for (const RodState& r : state.rods) {
    hashBytes(h, r.x);
    hashBytes(h, r.q);
    hashBytes(h, r.v);
    hashBytes(h, r.w);
  }
  char buf[17];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(h));
  return buf;
}

nlohmann::ordered_json resultJson(const Model& model, const State& state, const RunRecord& run) {
  using nlohmann::ordered_json;
  ordered_json out;
  out["format"] = kResultFormat;
  out["scene"] = run.scene;
  out["name"] = run.sceneName;
  out["solve"] = run.solve == SolveMode::Static ? "static" : "dynamic";
  out["status"] = run.status;
  if (!run.error.empty()) out["error"] = run.error;
  out["time_s"] = state.time;
  out["steps"] = state.stats.steps;
  out["state_hash"] = stateHash(state);
  ordered_json rods = ordered_json::array();
  for (size_t k = 0; k < model.rods.size(); ++k) {
    const RodState& r = state.rods[k];
    // Only the active nodes are the rod as it is now (a deployment's coil
    // grows node by node out of the catheter); a rod not active has none.
    const size_t n = r.active ? std::min(size_t(r.activeNodes), r.x.size()) : 0;
    ordered_json nodes = ordered_json::array(), rotations = ordered_json::array();
    for (size_t i = 0; i < n; ++i) {
      const Vec3& x = r.x[i];
      const Quat& q = r.q[i];
      nodes.push_back({units::mToMm(x.x()), units::mToMm(x.y()), units::mToMm(x.z())});
      rotations.push_back({q.w(), q.x(), q.y(), q.z()});
    }
    ordered_json rod;
    rod["name"] = model.rods[k].name;
    if (!r.active) rod["active"] = false;
    rod["nodes_mm"] = std::move(nodes);
    rod["rotations"] = std::move(rotations);
    rods.push_back(std::move(rod));
  }
  out["rods"] = std::move(rods);
  if (run.deployment) {
    const DeviceState& d = *run.deployment;
    out["deployment"] = {{"deployed_mm", units::mToMm(d.deployed)},
                         {"twist_deg", units::radToDeg(d.twist)},
                         {"detached", d.detached},
                         {"tip_offset_mm", units::mToMm(d.tipOffset)}};
    if (run.catheterTip) {
      // Kickback: how far the tip went back along its initial exit direction.
      out["deployment"]["catheter_kickback_mm"] = units::mToMm(run.catheterTip->kickback);
      out["deployment"]["catheter_tip_angle_deg"] = units::radToDeg(run.catheterTip->angle);
      out["deployment"]["catheter_rest_tip_angle_deg"] = units::radToDeg(run.catheterTip->restAngle);
    }
  }
  const Energy e = computeEnergy(model, state);
  out["energy"] = {{"kinetic_J", e.kinetic}, {"elastic_J", e.elastic}, {"potential_J", e.potential},
                   {"total_J", e.total()}};
  const StepStats& st = state.stats;
  out["stats"] = {{"mean_step_us", st.steps ? 1e6 * st.totalStepSeconds / double(st.steps) : 0.0},
                  {"max_step_us", 1e6 * st.maxStepSeconds},
                  {"newton_iterations", st.newtonIterations},
                  {"blowups", state.blowups},
                  {"substepped_steps", state.substepped},
                  {"max_wall_penetration_um", 1e6 * st.maxWallPenetration},
                  {"max_wall_penetration_of_radius", st.maxWallPenetrationOfRadius}};
  if (run.statics)
    out["static"] = {{"converged", run.statics->converged()},
                     {"increments", run.statics->increments},
                     {"iterations", run.statics->iterations}};
  if (run.readouts) {
    const ClinicalReadouts& c = *run.readouts;
    ordered_json r;
    r["packing_percent"] = 100 * c.packingDensity;
    r["coil_in_sac_mm"] = units::mToMm(c.coilLengthInSac);
    r["coil_volume_mm3"] = units::m3ToMm3(c.coilVolume);
    r["sac_volume_mm3"] = units::m3ToMm3(c.sacVolume);
    r["neck_coverage_percent"] = 100 * c.neckCoverage;
    r["protruding"] = c.protruding;
    r["protruding_length_mm"] = units::mToMm(c.protrudingLength);
    r["wall_load_window_ms"] = 1e3 * c.wallLoadWindow;
    // Without wall contact the load is unknown, not zero.
    r["wall_load_mN"] = c.wallLoadAvailable ? ordered_json(1e3 * c.wallLoad) : ordered_json(nullptr);
    r["largest_wall_load_mN"] = c.wallLoadAvailable ? ordered_json(1e3 * c.largestWallLoad) : ordered_json(nullptr);
    out["readouts"] = std::move(r);
  }
  ordered_json warnings = ordered_json::array();
  for (const std::string& w : run.warnings) warnings.push_back(w);
  for (const std::string& w : state.warnings) warnings.push_back(w);
  out["warnings"] = std::move(warnings);
  return out;
}

void writeResult(const std::string& path, const Model& model, const State& state, const RunRecord& run) {
  writeFileAtomic(path, formatJson(resultJson(model, state, run)));
}

}  // namespace coilsim::io
