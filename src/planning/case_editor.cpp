#include "planning/case_editor.h"

#include <cmath>
#include <filesystem>
#include <utility>

#include "geometry/medial_balls.h"
#include "io/json_reader.h"
#include "io/json_writer.h"
#include "io/mesh_file.h"

namespace coilsim::planning {
namespace {

Vec3 vec(const std::array<double, 3>& a) { return Vec3(a[0], a[1], a[2]); }

nlohmann::ordered_json rounded(const Vec3& v, double unit) {
  const auto r = [unit](double x) { return std::round(x / unit) * unit; };
  return nlohmann::ordered_json::array({r(v.x()), r(v.y()), r(v.z())});
}

nlohmann::ordered_json readDocument(const std::string& file) {
  const nlohmann::json plain = io::readJsonFile(file);  // errors name the file and the line
  const io::JsonNode root(plain, file);
  if (!root.isObject()) root.expected("a case object (coilsim-case/1)");
  const io::JsonNode sac = root.child("sac");
  if (!sac.isObject() || !sac.has("mesh"))
    sac.expected("a sac made from a surface: {\"mesh\": FILE, \"neck_plane\": {...}} (as coilsim case new writes)");
  const io::JsonNode scene = root.child("scene");
  if (!scene.isObject()) scene.expected("an inline scene (as coilsim case new writes), whose catheter the editor moves");
  scene.child("deployment").child("catheter").child("tip_position_mm").vec3();
  return nlohmann::ordered_json::parse(plain.dump());
}

TriangleMesh surfaceOf(const std::string& file, const nlohmann::ordered_json& doc) {
  namespace fs = std::filesystem;
  const fs::path mesh(doc["sac"]["mesh"].get<std::string>());
  const fs::path path = mesh.is_absolute() ? mesh : fs::path(file).parent_path() / mesh;
  const io::MeshInspection in = io::inspectMeshFile(path.string());
  if (!in.repaired.usable) throw io::InputError(path.string() + ": cannot be used as a vessel wall: " + in.repaired.reason);
  return in.repaired.mesh;
}

}  // namespace

CaseEditor::CaseEditor(const std::string& file) : file_(file), doc_(readDocument(file)), query_(surfaceOf(file, doc_)) {
  const nlohmann::json plain = nlohmann::json::parse(doc_.dump());
  const io::JsonNode root(plain, file);
  const io::JsonNode plane = root.child("sac").child("neck_plane");
  neck_.point = vec(plane.child("point_mm").vec3());
  const Vec3 n = vec(plane.child("normal").vec3());
  if (!(n.norm() > 1e-9)) plane.child("normal").expected("a non-zero direction");
  neck_.normal = n.normalized();
  const io::JsonNode cath = root.child("scene").child("deployment").child("catheter");
  catheter_.tip = vec(cath.child("tip_position_mm").vec3());
  catheter_.direction = vec(cath.child("direction").vec3()).normalized();
  if (auto r = cath.optional("reference_normal")) catheter_.referenceNormal = vec(r->vec3()).normalized();
  // The sac centre as case new found it; else the deepest point above the neck.
  const auto morph = root.optional("morphology");
  if (morph && morph->has("sac_centre_mm")) {
    sacCentre_ = vec(morph->child("sac_centre_mm").vec3());
  } else {
    sacCentre_ = neck_.point + 1.0 * neck_.normal;
    geometry::deepestNear(query_, sacCentre_, 0.5);
  }
  if (morph && morph->has("parent_vessel_diameter_mm"))
    vesselDiameter_ = morph->child("parent_vessel_diameter_mm").number(io::Bounds::closed(0, 100));
  morphology_ = geometry::measureSac(surface(), neck_, sacCentre_, vesselDiameter_);
  if (!(morphology_.volume > 0)) plane.fail("the neck plane cuts off no sac volume");
}

bool CaseEditor::refuse(std::string why) {
  refusal_ = std::move(why);
  return false;
}

bool CaseEditor::tryNeck(const geometry::Plane& plane) {
  if (!plane.normal.allFinite() || !plane.point.allFinite()) return refuse("the neck plane is not finite");
  if (!(plane.side(sacCentre_) > 0))
    return refuse("the neck plane would leave the sac centre on the vessel side (it must stay below the sac)");
  const geometry::SacMorphology m = geometry::measureSac(surface(), plane, sacCentre_, vesselDiameter_);
  if (!(m.volume > 0)) return refuse("the neck plane would cut off no sac");
  // A plane below the ostium cuts the parent vessel, not a neck: the sac piece then has no opening.
  if (!(m.neckWidth > 0)) return refuse("the neck plane would cut the parent vessel, not the sac's opening");
  neck_ = plane, morphology_ = m, edited_ = true;
  refusal_.clear();
  return true;
}

bool CaseEditor::moveNeck(double mm) {
  if (!std::isfinite(mm)) return refuse("the shift is not a number");
  return tryNeck({neck_.point + mm * neck_.normal, neck_.normal});
}

bool CaseEditor::tiltNeck(const Vec3& axis, double radians) {
  if (!(axis.norm() > 1e-12) || !axis.allFinite() || !std::isfinite(radians)) return refuse("no axis to tilt about");
  const Eigen::AngleAxisd turn(radians, axis.normalized());
  return tryNeck({neck_.point, (turn * neck_.normal).normalized()});
}

bool CaseEditor::placeNeckThrough(const Vec3& point) { return tryNeck({point, neck_.normal}); }

bool CaseEditor::placeTip(const Vec3& point) {
  if (!point.allFinite()) return refuse("the tip position is not finite");
  if (!query_.inside(point)) return refuse("the catheter tip must lie inside the vessel surface");
  catheter_.tip = point, edited_ = catheterMoved_ = true;
  refusal_.clear();
  return true;
}

bool CaseEditor::pointTip(const Vec3& direction) {
  if (!(direction.norm() > 1e-12) || !direction.allFinite()) return refuse("the tip direction is zero or not finite");
  catheter_.direction = direction.normalized();
  Vec3 across = catheter_.referenceNormal - catheter_.referenceNormal.dot(catheter_.direction) * catheter_.direction;
  catheter_.referenceNormal = across.norm() > 1e-6 ? Vec3(across.normalized()) : Vec3(catheter_.direction.unitOrthogonal());
  edited_ = catheterMoved_ = true;
  refusal_.clear();
  return true;
}

void CaseEditor::markSaved() { edited_ = false; }

nlohmann::ordered_json CaseEditor::document() const {
  nlohmann::ordered_json d = doc_;
  d["sac"]["neck_plane"] = {{"point_mm", rounded(neck_.point, 1e-4)}, {"normal", rounded(neck_.normal, 1e-6)}};
  if (catheterMoved_) {
    auto& cath = d["scene"]["deployment"]["catheter"];
    cath["tip_position_mm"] = rounded(catheter_.tip, 1e-4);
    cath["direction"] = rounded(catheter_.direction, 1e-6);
    cath["reference_normal"] = rounded(catheter_.referenceNormal, 1e-6);
  }
  d["morphology"] = morphologyJson(morphology_, vesselDiameter_);
  d["morphology"]["sac_centre_mm"] = rounded(sacCentre_, 1e-4);
  return d;
}

void CaseEditor::save(const std::string& path) const { io::writeFileAtomic(path, io::formatJson(document())); }

}  // namespace coilsim::planning
