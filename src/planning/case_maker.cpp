#include "planning/case_maker.h"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "io/mesh_file.h"
#include "planning/case_file.h"

namespace coilsim::planning {
namespace {

nlohmann::ordered_json vec(const Vec3& v, double unit = 1e-4) {
  const auto r = [unit](double x) { return std::round(x / unit) * unit; };
  return nlohmann::ordered_json::array({r(v.x()), r(v.y()), r(v.z())});
}

double round3(double x) { return std::round(x * 1e3) / 1e3; }

// The scene of a made case: blood (weight, upthrust, drag) as in the shipped
// cases, a rigid microcatheter at the tip; the wall is the case's sac mesh
// (plans and practice add it, docs/planning.md "Contacts").
nlohmann::ordered_json sceneJson(const std::string& name, const Catheter& c, const FirstCoil& f) {
  using J = nlohmann::ordered_json;
  const double loop = std::clamp(std::round(2 * f.loopDiameterMm) / 2, 1.0, 20.0);
  return J{{"format", "coilsim-scene/1"},
           {"name", name + "-scene"},
           {"description", "Made by coilsim case new: the catheter tip inside the neck, in blood."},
           {"gravity_m_s2", {0.0, 0.0, -9.81}},
           {"solve", "dynamic"},
           {"time_step_s", 0.001},
           {"duration_s", 30.0},
           {"damping", {{"rayleigh_mass_1_s", 1.0}, {"rayleigh_stiffness_s", 0.0}}},
           {"effects", {{"gravity", J::object()}, {"buoyancy", {{"medium_density_g_cm3", 1.06}}},
                        {"drag", {{"viscosity_pa_s", 0.0035}, {"rft_length_mm", 5.0}}}}},
           {"deployment",
            {{"coil", {{"name", "coil"}, {"length_mm", 20.0}, {"beams", 40},
                       {"rest_shape", {{"type", "helix"}, {"loop_diameter_mm", loop}, {"pitch_mm", 0.3}, {"handedness", "right"}}},
                       {"material", {{"young_modulus_gpa", 168}, {"poisson_ratio", 0.38}, {"density_g_cm3", 21.45}}},
                       {"section", {{"wire_radius_mm", 0.127}}}}},
             {"catheter", {{"type", "rigid"}, {"tip_position_mm", vec(c.tip)}, {"direction", vec(c.direction, 1e-6)},
                           {"reference_normal", vec(c.referenceNormal, 1e-6)}, {"outer_diameter_mm", 0.6},
                           {"draw_length_mm", 20}}},
             {"initial_deployed_mm", 0},
             {"initial_twist_deg", 0},
             {"max_push_speed_mm_s", 20}}}};
}

}  // namespace

Catheter placeCatheter(const geometry::SacFinding& s, const geometry::SacMorphology& m) {
  Catheter c;
  c.direction = s.neck.normal.normalized();
  c.tip = m.neckCentre + 0.3 * m.domeHeight * c.direction;
  Vec3 across = s.vesselDirection - s.vesselDirection.dot(c.direction) * c.direction;
  c.referenceNormal = across.norm() > 1e-6 ? Vec3(across.normalized()) : Vec3(c.direction.unitOrthogonal());
  return c;
}

nlohmann::ordered_json morphologyJson(const geometry::SacMorphology& m, double vesselDiameterMm) {
  return {{"sac_volume_mm3", round3(m.volume)},         {"neck_area_mm2", round3(m.neckArea)},
          {"max_diameter_mm", round3(m.maxDiameter)},   {"mean_diameter_mm", round3(m.meanDiameter)},
          {"width_mm", round3(m.width)},                {"depth_mm", round3(m.depth)},
          {"neck_width_mm", round3(m.neckWidth)},       {"dome_height_mm", round3(m.domeHeight)},
          {"max_height_mm", round3(m.maxHeight)},       {"aspect_ratio", round3(m.aspectRatio)},
          {"dome_to_neck", round3(m.domeToNeck)},       {"parent_vessel_diameter_mm", round3(vesselDiameterMm)},
          {"size_ratio", round3(m.sizeRatio)}};
}

MadeCase makeCase(const CaseRequest& r) {
  namespace fs = std::filesystem;
  const io::MeshInspection in = io::inspectMeshFile(r.surface);
  // An inside-out file is refused, not flipped: a surface exported with its
  // normals into the lumen often is not the lumen (a mould, a complement).
  if (in.report.closed() && in.report.oriented() && in.report.volume < 0)
    throw CaseError(r.surface + ": the surface is inside-out (its triangles face into the vessel, enclosed volume " +
                    std::to_string(in.report.volume) + " mm^3); export the lumen with outward normals");
  if (!in.repaired.usable) throw CaseError(r.surface + ": cannot be used as a vessel wall: " + in.repaired.reason);
  const geometry::MeshQuery query(in.repaired.mesh);
  geometry::SacFinderOptions options;
  options.sacPoint = r.sacPoint;
  MadeCase out;
  out.sac = geometry::findSac(query, options);
  if (!out.sac.found)
    throw CaseError(r.surface + ": " + out.sac.problem +
                    (r.sacPoint ? std::string() : "; give a point in the sac with --sac-point x,y,z (mm)"));
  const double vesselDiameter = 2 * out.sac.vesselRadius;
  out.morphology = geometry::measureSac(in.repaired.mesh, out.sac.neck, out.sac.centre, vesselDiameter);
  if (!(out.morphology.volume > 0)) throw CaseError(r.surface + ": the neck plane cuts off no sac volume");
  const std::string catalogue = r.catalogue.empty() ? defaultCatalogue() : r.catalogue;
  out.firstCoil = recommendFirstCoil(out.morphology, io::loadCatalogue(catalogue));
  out.catheter = placeCatheter(out.sac, out.morphology);
  if (!query.inside(out.catheter.tip))
    throw CaseError(r.surface + ": no clear neck: the catheter tip would lie outside the surface");

  // Paths in the case are relative to the case file.
  const fs::path outDir = fs::absolute(fs::path(r.out)).parent_path();
  const std::string mesh = fs::absolute(r.surface).lexically_relative(outDir).string();
  std::string name = fs::path(r.out).stem().string();
  nlohmann::ordered_json doc;
  doc["format"] = kCaseFormat;
  doc["name"] = name;
  doc["description"] = "Made by coilsim case new from " + fs::path(r.surface).filename().string() + ". " + out.firstCoil.rule + ".";
  doc["scene"] = sceneJson(name, out.catheter, out.firstCoil);
  doc["sac"] = {{"mesh", mesh}, {"neck_plane", {{"point_mm", vec(out.morphology.neckCentre)}, {"normal", vec(out.sac.neck.normal, 1e-6)}}}};
  doc["coils"] = out.firstCoil.neighbours;
  if (!r.catalogue.empty()) doc["catalogue"] = fs::absolute(r.catalogue).lexically_relative(outDir).string();
  doc["goal"] = {{"min_packing_density", 0.25}, {"no_protrusion", true}, {"max_wall_force_mN", 100}, {"detach_in_sac", true}};
  doc["spacing_mm"] = 0.5;
  doc["morphology"] = morphologyJson(out.morphology, vesselDiameter);
  doc["morphology"]["sac_centre_mm"] = vec(out.sac.centre);
  doc["first_coil"] = {{"loop_diameter_mm", round3(out.firstCoil.loopDiameterMm)}, {"length_mm", round3(out.firstCoil.lengthMm)},
                       {"rule", out.firstCoil.rule}, {"nearest_in_catalogue", out.firstCoil.best}};
  out.document = std::move(doc);
  return out;
}

}  // namespace coilsim::planning
