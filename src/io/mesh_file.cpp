#include "io/mesh_file.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <sstream>

#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include "io/json_reader.h"
#include "io/json_writer.h"
#include "io/units.h"

namespace coilsim::io {
namespace {

[[noreturn]] void fail(const std::string& file, const std::string& message) { throw InputError(file + ": " + message); }

std::string yesNo(bool b) { return b ? "yes" : "no"; }

}  // namespace

MeshInspection inspectMeshFile(const std::string& path, double scaleToMm) {
  if (!(scaleToMm > 0) || !std::isfinite(scaleToMm))
    fail(path, "the scale to millimetres must be a finite number > 0, got " + std::to_string(scaleToMm));
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) fail(path, "no such mesh file");
  if (!std::filesystem::is_regular_file(path, ec)) fail(path, "not a regular file");

  Assimp::Importer importer;
  // Points and lines are dropped at import: a wall is made of triangles.
  importer.SetPropertyInteger(AI_CONFIG_PP_SBP_REMOVE, aiPrimitiveType_POINT | aiPrimitiveType_LINE);
  const aiScene* scene = importer.ReadFile(
      path, aiProcess_Triangulate | aiProcess_JoinIdenticalVertices | aiProcess_SortByPType |
                aiProcess_PreTransformVertices);
  if (!scene) fail(path, std::string("cannot read the mesh: ") + importer.GetErrorString());

  MeshInspection out;
  out.file = path;
  out.parts = int(scene->mNumMeshes);
  TriangleMesh raw;
  raw.name = std::filesystem::path(path).stem().string();
  for (unsigned m = 0; m < scene->mNumMeshes; ++m) {
    const aiMesh* mesh = scene->mMeshes[m];
    const int base = int(raw.vertices.size());
    for (unsigned v = 0; v < mesh->mNumVertices; ++v) {
      const aiVector3D& p = mesh->mVertices[v];
      raw.vertices.push_back(scaleToMm * Vec3(p.x, p.y, p.z));
    }
    for (unsigned f = 0; f < mesh->mNumFaces; ++f) {
      const aiFace& face = mesh->mFaces[f];
      if (face.mNumIndices != 3) continue;
      raw.triangles.emplace_back(base + int(face.mIndices[0]), base + int(face.mIndices[1]), base + int(face.mIndices[2]));
    }
  }
  if (raw.triangles.empty()) fail(path, "the file holds no triangles");
  for (const Vec3& v : raw.vertices)
    if (!v.allFinite()) fail(path, "a vertex coordinate is not a finite number");
  // Parts of one surface (OBJ groups, STL solids) meet at identical vertices.
  out.mesh = geometry::weldVertices(raw, 0);
  out.report = geometry::analyseMesh(out.mesh);
  out.repaired = geometry::repairMesh(out.mesh, 0);
  return out;
}

std::string describeInspection(const MeshInspection& in) {
  const geometry::MeshReport& r = in.report;
  std::ostringstream s;
  s.precision(6);
  s << in.file << ": " << r.triangles << " triangles, " << r.vertices << " vertices";
  if (in.parts > 1) s << " in " << in.parts << " parts";
  s << "\n  bounds mm   [" << r.lower.x() << ", " << r.upper.x() << "] x [" << r.lower.y() << ", " << r.upper.y()
    << "] x [" << r.lower.z() << ", " << r.upper.z() << "]\n";
  s << "  closed      " << yesNo(r.closed());
  if (!r.closed())
    s << " (" << r.boundaryEdges << " boundary edges, " << r.nonManifoldEdges << " non-manifold edges)";
  s << "\n  oriented    " << yesNo(r.oriented());
  if (!r.oriented() && r.misorientedEdges) s << " (" << r.misorientedEdges << " edges with inconsistent triangles)";
  s << "\n  components  " << r.components << "\n  volume mm^3 " << r.volume
    << (r.closed() && r.oriented() ? (r.volume > 0 ? " (normals outward)" : " (normals inward)") : " (not meaningful: not closed and oriented)")
    << "\n";
  if (r.degenerateTriangles) s << "  degenerate  " << r.degenerateTriangles << " triangles\n";
  for (const std::string& a : in.repaired.actions) s << "  repair      " << a << "\n";
  if (in.repaired.usable)
    s << "  usable      yes" << (in.repaired.actions.empty() ? "" : ", after the repairs above") << "\n";
  else
    s << "  usable      no: " << in.repaired.reason << "\n";
  return s.str();
}

TriangleMesh loadMeshFile(const std::string& path, double scaleToMm) {
  MeshInspection in = inspectMeshFile(path, scaleToMm);
  if (!in.repaired.usable)
    fail(path, "cannot be used as a wall: " + in.repaired.reason + "\n" + describeInspection(in));
  TriangleMesh mesh = std::move(in.repaired.mesh);
  for (Vec3& v : mesh.vertices) v = Vec3(units::mmToM(v.x()), units::mmToM(v.y()), units::mmToM(v.z()));
  return mesh;
}

void writeBinaryStl(const TriangleMesh& mesh, const std::string& path) {
  // Binary STL: 80-byte header, uint32 count, then per triangle a float32
  // normal, three float32 vertices and a uint16 attribute (little endian).
  std::string data(80, '\0');
  const std::string header = "coilsim binary STL, millimetres: " + mesh.name;
  std::memcpy(data.data(), header.data(), std::min<size_t>(header.size(), 80));
  auto put = [&](const void* p, size_t n) { data.append(static_cast<const char*>(p), n); };
  const uint32_t count = uint32_t(mesh.triangles.size());
  put(&count, 4);
  data.reserve(84 + 50 * size_t(count));
  for (const Eigen::Vector3i& t : mesh.triangles) {
    const Vec3 &a = mesh.vertices[t[0]], &b = mesh.vertices[t[1]], &c = mesh.vertices[t[2]];
    Vec3 n = (b - a).cross(c - a);
    if (n.norm() > 0) n.normalize();
    for (const Vec3* v : std::initializer_list<const Vec3*>{&n, &a, &b, &c}) {
      const float xyz[3] = {float(v->x()), float(v->y()), float(v->z())};
      put(xyz, 12);
    }
    const uint16_t attribute = 0;
    put(&attribute, 2);
  }
  static_assert(std::endian::native == std::endian::little, "STL is little endian");
  writeFileAtomic(path, data);
}

std::string phantomSidecarPath(const std::string& stlPath) {
  std::filesystem::path p(stlPath);
  p.replace_extension(".phantom.json");
  return p.string();
}

namespace {
nlohmann::ordered_json vec(const Vec3& v) { return {v.x(), v.y(), v.z()}; }
}  // namespace

void writePhantomSidecar(const geometry::PhantomInfo& info, const std::string& path) {
  const geometry::PhantomSpec& s = info.spec;
  nlohmann::ordered_json j;
  j["format"] = "coilsim-phantom/1";
  j["description"] = "saccular aneurysm phantom made by coilsim phantom; lengths in mm";
  j["type"] = info.type;
  j["parameters"] = {{"sac_diameter_mm", s.sacDiameter},
                     {"sac_height_mm", info.sacRadii.z() * 2},
                     {"neck_width_mm", info.neckWidth},
                     {"dome_to_neck", s.sacDiameter / info.neckWidth},
                     {"lobes", s.lobes},
                     {"vessel_diameter_mm", s.vesselDiameter},
                     {"resolution_mm", s.resolution},
                     {"blend_mm", s.blend}};
  j["sac"] = {{"centre_mm", vec(info.sacCentre)},
              {"radii_mm", vec(info.sacRadii)},
              {"axis_u", vec(info.axisU)},
              {"axis_v", vec(info.axisV)},
              {"ideal_volume_above_neck_mm3", info.idealSacVolume}};
  nlohmann::ordered_json lobes = nlohmann::ordered_json::array();
  for (const geometry::Lobe& l : info.lobes) lobes.push_back({{"centre_mm", vec(l.centre)}, {"radii_mm", vec(l.radii)}});
  j["sac"]["lobes"] = lobes;
  j["neck"] = {{"point_mm", vec(info.neck.point)}, {"normal", vec(info.neck.normal)}, {"width_mm", info.neckWidth}};
  j["vessel_radius_mm"] = info.vesselRadius;
  writeFileAtomic(path, formatJson(j));
}

geometry::PhantomInfo readPhantomSidecar(const std::string& path) {
  const nlohmann::json doc = readJsonFile(path);
  const JsonNode root(doc, path);
  root.allowKeys({"format", "description", "type", "parameters", "sac", "neck", "vessel_radius_mm"});
  root.child("format").oneOf({"coilsim-phantom/1"});
  geometry::PhantomInfo info;
  info.type = root.child("type").oneOf({"sidewall", "curved", "bifurcation"});
  geometry::parseVesselType(info.type, info.spec.vessel);
  auto v3 = [](const JsonNode& n, const Bounds& b = Bounds::any()) {
    const auto a = n.vec3(b);
    return Vec3(a[0], a[1], a[2]);
  };
  const JsonNode p = root.child("parameters");
  p.allowKeys({"sac_diameter_mm", "sac_height_mm", "neck_width_mm", "dome_to_neck", "lobes", "vessel_diameter_mm",
               "resolution_mm", "blend_mm"});
  info.spec.sacDiameter = p.child("sac_diameter_mm").number(Bounds::positive());
  info.spec.sacHeight = p.child("sac_height_mm").number(Bounds::positive());
  info.spec.neckWidth = p.child("neck_width_mm").number(Bounds::positive());
  info.spec.domeToNeck = p.child("dome_to_neck").number(Bounds::positive());
  info.spec.lobes = int(p.child("lobes").integer(1, 100));
  info.spec.vesselDiameter = p.child("vessel_diameter_mm").number(Bounds::positive());
  info.spec.resolution = p.child("resolution_mm").number(Bounds::positive());
  info.spec.blend = p.child("blend_mm").number(Bounds::nonNegative());
  const JsonNode sac = root.child("sac");
  sac.allowKeys({"centre_mm", "radii_mm", "axis_u", "axis_v", "ideal_volume_above_neck_mm3", "lobes"});
  info.sacCentre = v3(sac.child("centre_mm"));
  info.sacRadii = v3(sac.child("radii_mm"), Bounds::positive());
  info.axisU = v3(sac.child("axis_u"));
  info.axisV = v3(sac.child("axis_v"));
  info.idealSacVolume = sac.child("ideal_volume_above_neck_mm3").number(Bounds::positive());
  for (const JsonNode& l : sac.child("lobes").items(1, 100, "an array of lobes")) {
    l.allowKeys({"centre_mm", "radii_mm"});
    info.lobes.push_back({v3(l.child("centre_mm")), v3(l.child("radii_mm"), Bounds::positive())});
  }
  const JsonNode neck = root.child("neck");
  neck.allowKeys({"point_mm", "normal", "width_mm"});
  info.neck.point = v3(neck.child("point_mm"));
  info.neck.normal = v3(neck.child("normal"));
  if (std::abs(info.neck.normal.norm() - 1) > 1e-6) neck.child("normal").expected("a unit vector");
  info.neckWidth = neck.child("width_mm").number(Bounds::positive());
  info.vesselRadius = root.child("vessel_radius_mm").number(Bounds::positive());
  return info;
}

}  // namespace coilsim::io
