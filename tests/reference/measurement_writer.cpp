// The coil-measurement/1 file and its truth sidecar (experiment.h), written
// with a fixed layout (numeric arrays on one line) so the committed files
// are small, diffable and reproducible byte for byte.
#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <sstream>

#include "experiment.h"

namespace refrod {

namespace {

using nlohmann::ordered_json;

void pretty(const ordered_json& j, int depth, std::ostringstream& os) {
  const std::string pad(2 * depth + 2, ' '), padEnd(2 * depth, ' ');
  if (j.is_object()) {
    os << "{\n";
    size_t i = 0;
    for (auto it = j.begin(); it != j.end(); ++it, ++i) {
      os << pad << ordered_json(it.key()).dump() << ": ";
      pretty(it.value(), depth + 1, os);
      os << (i + 1 < j.size() ? ",\n" : "\n");
    }
    os << padEnd << "}";
  } else if (j.is_array()) {
    const bool flat = std::all_of(j.begin(), j.end(), [](const ordered_json& e) { return e.is_primitive(); });
    if (flat) {
      os << "[";
      for (size_t i = 0; i < j.size(); ++i) os << (i ? ", " : "") << j[i].dump();
      os << "]";
      return;
    }
    os << "[\n";
    for (size_t i = 0; i < j.size(); ++i) {
      os << pad;
      pretty(j[i], depth + 1, os);
      os << (i + 1 < j.size() ? ",\n" : "\n");
    }
    os << padEnd << "]";
  } else {
    os << j.dump();
  }
}

std::string text(const ordered_json& j) {
  std::ostringstream os;
  pretty(j, 0, os);
  os << "\n";
  return os.str();
}

// Declared numbers keep what the scenario says; computed ones are rounded
// to a stated number of significant digits so that the text is stable.
double sig(double v, int digits) {
  if (v == 0 || !std::isfinite(v)) return v;
  const double e = std::pow(10.0, digits - 1 - int(std::floor(std::log10(std::abs(v)))));
  return std::round(v * e) / e;
}
ordered_json vec(const Vec3& v, int digits = 6) {
  const auto c = [&](double x) { return std::abs(x) < 1e-9 ? 0.0 : sig(x, digits); };  // no 2e-16 noise
  return {c(v.x()), c(v.y()), c(v.z())};
}

}  // namespace

std::string measurementJson(const Scenario& sc, const std::vector<StageResult>& r) {
  ordered_json j;
  j["format"] = "coil-measurement/1";
  j["name"] = sc.name;
  j["description"] = sc.description;
  j["coil"] = {{"length_mm", sc.lengthMm},
               {"wire_radius_mm", sc.wireRadiusMm},
               {"density_g_cm3", sc.densityGcm3},
               {"rest_shape",
                {{"type", "helix"},
                 {"loop_diameter_mm", sc.loopDiameterMm},
                 {"pitch_mm", sc.pitchMm},
                 {"handedness", sc.rightHanded ? "right" : "left"}}},
               {"young_modulus_gpa", sc.nominalYoungGpa},
               {"poisson_ratio", sc.poisson}};
  j["setup"] = {{"gravity_m_s2", vec(sc.gravity)},
                {"medium", {{"density_g_cm3", sc.mediumDensityGcm3}, {"viscosity_pa_s", sc.mediumViscosityPas}}},
                {"catheter_tip",
                 {{"position_mm", vec(sc.tipMm)},
                  {"direction", vec(sc.direction)},
                  {"reference_normal", vec(sc.referenceNormal)}}}};
  ordered_json stages = ordered_json::array();
  for (size_t i = 0; i < sc.stages.size(); ++i) {
    const StageDef& st = sc.stages[i];
    ordered_json s;
    s["name"] = st.name;
    s["deployed_length_mm"] = st.deployedMm;
    s["twist_deg"] = st.twistDeg;
    s["point_sigma_mm"] = st.sigmaMm;
    if (!st.history.empty()) {
      ordered_json h = ordered_json::array();
      for (const PushSample& p : st.history)
        h.push_back({sig(p.t, 6), sig(p.l * 1e3, 6), sig(p.twist * 180 / M_PI, 6)});
      s["push_history"] = h;
      s["capture_time_s"] = st.captureS;
    }
    ordered_json cl = ordered_json::array();
    for (const Vec3& p : r[i].sampledMm) cl.push_back({p.x(), p.y(), p.z()});
    s["centerline_mm"] = cl;
    stages.push_back(s);
  }
  j["stages"] = stages;
  return text(j);
}

std::string truthJson(const Scenario& sc, const std::vector<StageResult>& r, const std::vector<double>& effectMm) {
  const RodSpec spec = trueSpec(sc);
  const double G = sc.trueYoungGpa / (2 * (1 + sc.poisson));
  ordered_json j;
  j["format"] = "coil-measurement-truth/1";
  j["measurement"] = sc.name + ".json";
  j["model"] = "tests/reference (discrete Cosserat rod, shares no code with coilsim)";
  j["hidden_effects"] = sc.hidden;
  j["true_model"] = sc.trueModel;
  j["coil"] = {{"young_modulus_gpa", sc.trueYoungGpa},
               {"nominal_young_modulus_gpa", sc.nominalYoungGpa},
               {"nominal_over_true", sig(sc.nominalYoungGpa / sc.trueYoungGpa, 4)},
               {"shear_modulus_gpa", sig(G, 6)},
               {"bending_stiffness_n_mm2", sig(spec.coil.EI1 * 1e6, 6)},
               {"torsional_stiffness_n_mm2", sig(spec.coil.GJ * 1e6, 6)}};
  j["gravity"] = {{"declared_m_s2", vec(sc.gravity)},
                  {"true_m_s2", vec(tiltedGravity(sc.gravity, sc.tiltADeg, sc.tiltBDeg))},
                  {"tilt_a_deg", sc.tiltADeg},
                  {"tilt_b_deg", sc.tiltBDeg},
                  {"tilt_convention", "g' = exp(a e1 + b e2) g, e1 = x made orthogonal to g, e2 = g^ x e1 "
                                      "(coilsim gravity_tilt)"}};
  j["buoyancy"] = {{"applied", sc.buoyancy},
                   {"medium_density_g_cm3", sc.mediumDensityGcm3},
                   {"net_weight_over_weight", sig(1 - sc.mediumDensityGcm3 / sc.densityGcm3, 6)}};
  j["drag"] = {{"applied_in_push_stages", true},
               {"law", "Lighthill resistive-force theory, Lambda = pi D (loop arc length)"},
               {"viscosity_pa_s", sc.mediumViscosityPas},
               {"normal_n_s_m2", sig(spec.dragNormal, 6)},
               {"tangential_n_s_m2", sig(spec.dragTangent, 6)},
               {"coilsim_rft_length_mm", sig(0.09 * M_PI * sc.loopDiameterMm, 6)},
               {"coilsim_tangential_over_this", sig(std::log(0.18 * M_PI * sc.loopDiameterMm / sc.wireRadiusMm) /
                                                        (std::log(0.18 * M_PI * sc.loopDiameterMm / sc.wireRadiusMm) - 0.5), 4)},
               {"note", "coilsim's c_n = 4 pi mu / (ln(2 lambda / r) + 1/2) equals this c_n at lambda = 0.09 Lambda; "
                        "its c_t = 2 pi mu / (ln(2 lambda / r) - 1/2) is then larger by coilsim_tangential_over_this"}};
  j["self_contact"] = {{"applied", true},
                       {"law", "phi = k w (2r - d)^3 / 3 between quadrature points ~r apart on non-adjacent edges, "
                               "w = ds_p ds_q / (2r)^2, frictionless"},
                       {"stiffness_n_m2", spec.contactStiffness}};
  if (sc.tube.lengthMm > 0) {
    const TubeDef& t = sc.tube;
    j["catheter_tube"] = {{"free_length_mm", t.lengthMm},
                          {"outer_diameter_mm", t.outerDiameterMm},
                          {"inner_diameter_mm", t.innerDiameterMm},
                          {"young_modulus_gpa", t.youngGpa},
                          {"poisson_ratio", t.poisson},
                          {"density_g_cm3", t.densityGcm3},
                          {"composite_bending_stiffness_n_mm2", sig(spec.tube.EI1 * 1e6, 6)},
                          {"tube_only_bending_stiffness_n_mm2", sig((spec.tube.EI1 - spec.coil.EI1) * 1e6, 6)},
                          {"composite_net_weight_n_per_m", sig(spec.tube.weight.norm(), 6)},
                          {"base_mm", vec((sc.tipMm - t.lengthMm * sc.direction.normalized()), 6)}};
  } else {
    j["catheter_tube"] = nullptr;
  }
  j["discretisation"] = {{"edge_mm", sc.edgeMm},
                         {"static_push_increment_mm", sig(spec.h() * 1e3, 6)},
                         {"time_step_s", sc.timeStepS},
                         {"newmark_beta_gamma", {0.3025, 0.6}},
                         {"noise_seed", sc.seed}};
  ordered_json stages = ordered_json::array();
  for (size_t i = 0; i < sc.stages.size(); ++i) {
    const StageResult& s = r[i];
    stages.push_back({{"name", sc.stages[i].name},
                      {"dynamic", !sc.stages[i].history.empty()},
                      {"true_exit_mm", vec(s.exitMm, 6)},
                      {"true_exit_direction", vec(s.exitDirection, 6)},
                      {"free_end_mm", vec(s.nodesM.back() * 1e3, 6)},
                      {"max_displacement_from_rest_mm", sig(s.maxSagMm, 4)},
                      {"hidden_effect_size_mm", i < effectMm.size() ? sig(effectMm[i], 4) : 0.0},
                      {"contact_edge_pairs", s.contactPairs},
                      {"min_gap_mm", sig(s.minGapMm, 4)}});
  }
  j["stages"] = stages;
  return text(j);
}

}  // namespace refrod
