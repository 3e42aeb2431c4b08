#include "io/result.h"

#include "io/json_writer.h"
#include "io/units.h"

namespace coilsim::io {

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
  ordered_json rods = ordered_json::array();
  for (size_t k = 0; k < model.rods.size(); ++k) {
    const RodState& r = state.rods[k];
    ordered_json nodes = ordered_json::array(), rotations = ordered_json::array();
    for (const Vec3& x : r.x) nodes.push_back({units::mToMm(x.x()), units::mToMm(x.y()), units::mToMm(x.z())});
    for (const Quat& q : r.q) rotations.push_back({q.w(), q.x(), q.y(), q.z()});
    ordered_json rod;
    rod["name"] = model.rods[k].name;
    rod["nodes_mm"] = std::move(nodes);
    rod["rotations"] = std::move(rotations);
    rods.push_back(std::move(rod));
  }
  out["rods"] = std::move(rods);
  const Energy e = computeEnergy(model, state);
  out["energy"] = {{"kinetic_J", e.kinetic}, {"elastic_J", e.elastic}, {"potential_J", e.potential},
                   {"total_J", e.total()}};
  const StepStats& st = state.stats;
  out["stats"] = {{"mean_step_us", st.steps ? 1e6 * st.totalStepSeconds / double(st.steps) : 0.0},
                  {"max_step_us", 1e6 * st.maxStepSeconds},
                  {"newton_iterations", st.newtonIterations},
                  {"blowups", state.blowups}};
  if (run.statics)
    out["static"] = {{"converged", run.statics->converged},
                     {"increments", run.statics->increments},
                     {"iterations", run.statics->iterations}};
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
