// Case and sac files -> PracticeCase / Sac.
#include "planning/case_file.h"

#include <algorithm>
#include <filesystem>

#include "io/mesh_file.h"
#include "io/units.h"

#ifndef COILSIM_SOURCE_DIR
#define COILSIM_SOURCE_DIR "."
#endif

namespace coilsim::planning {
namespace {

using io::Bounds;
using io::JsonNode;

Vec3 vec(const std::array<double, 3>& a) { return Vec3(a[0], a[1], a[2]); }

std::string besideFile(const std::string& file, const std::string& relative) {
  namespace fs = std::filesystem;
  const fs::path p(relative);
  return p.is_absolute() ? relative : (fs::path(file).parent_path() / p).lexically_normal().string();
}

}  // namespace

namespace {

Plane readNeckPlane(const JsonNode& p) {
  if (!p.isObject()) p.expected("{\"point_mm\": [x, y, z], \"normal\": [x, y, z] (into the sac)}");
  p.allowKeys({"point_mm", "normal"});
  Plane plane;
  plane.point = units::mmToM(1.0) * vec(p.child("point_mm").vec3());
  const JsonNode nn = p.child("normal");
  const Vec3 normal = vec(nn.vec3());
  if (!(normal.norm() > 1e-9)) nn.expected("a non-zero direction");
  plane.normal = normal.normalized();
  return plane;
}

}  // namespace

Sac readSac(const JsonNode& n) {
  if (!n.isObject())
    n.expected("a sac object: {\"phantom\": STL with its .phantom.json sidecar}, or {\"mesh\": FILE, \"neck_plane\": {...}}, "
               "or {\"sphere\": {...}, \"neck_plane\": {...}}");
  n.allowKeys({"phantom", "mesh", "sphere", "neck_plane"});
  const int given = int(n.has("phantom")) + int(n.has("mesh")) + int(n.has("sphere"));
  if (given != 1) n.fail("give exactly one of \"phantom\", \"mesh\" and \"sphere\"");
  if (n.has("phantom")) {
    if (n.has("neck_plane")) n.child("neck_plane").fail("a phantom's neck plane comes from its sidecar; drop \"neck_plane\"");
    return phantomSac(besideFile(n.file(), n.child("phantom").string()));
  }
  const Plane neck = readNeckPlane(n.child("neck_plane"));
  if (n.has("mesh")) {
    auto mesh = std::make_shared<TriangleMesh>(io::loadMeshFile(besideFile(n.file(), n.child("mesh").string())));
    try {
      return makeSac(std::move(mesh), neck);
    } catch (const std::invalid_argument& e) {
      n.child("neck_plane").fail(e.what());
    }
  }
  const JsonNode s = n.child("sphere");
  if (!s.isObject()) s.expected("{\"centre_mm\": [x, y, z], \"radius_mm\": r, \"subdivisions\": 5}");
  s.allowKeys({"centre_mm", "radius_mm", "subdivisions"});
  const Vec3 centre = units::mmToM(1.0) * vec(s.child("centre_mm").vec3());
  const double radius = units::mmToM(s.child("radius_mm").number(Bounds{0.5, 50, false, false, "mm"}));
  const int level = s.has("subdivisions") ? int(s.child("subdivisions").integer(1, 6)) : 5;
  if (std::abs(neck.signedDistance(centre)) >= radius) n.child("neck_plane").fail("the neck plane does not cut the sac sphere");
  return makeSac(std::make_shared<TriangleMesh>(makeIcosphere(centre, radius, level, "sac sphere")), neck);
}

Sac phantomSac(const std::string& stl) {
  // A generated phantom: its surface, and the neck plane from its sidecar (mm).
  const geometry::PhantomInfo info = io::readPhantomSidecar(io::phantomSidecarPath(stl));
  auto mesh = std::make_shared<TriangleMesh>(io::loadMeshFile(stl));
  return makeSac(std::move(mesh), Plane{units::mmToM(1.0) * info.neck.point, info.neck.normal});
}

std::optional<Sac> sceneSac(const io::SceneSpec& scene, std::string& note) {
  note = "no obstacle of the scene is a phantom with a sidecar (coilsim phantom writes NAME.phantom.json)";
  for (const io::ObstacleSpec& o : scene.obstacles) {
    const std::string sidecar = io::phantomSidecarPath(o.meshPath);
    if (sidecar == o.meshPath || !std::filesystem::exists(sidecar)) continue;
    if (o.rotationDeg != Vec3::Zero()) {
      note = sidecar + ": the obstacle \"" + o.name + "\" is rotated; its sidecar's neck plane is not, so no read-outs";
      continue;
    }
    const geometry::PhantomInfo info = io::readPhantomSidecar(sidecar);
    // The mesh placed as the scene places it; the neck plane moved with it
    // (the sidecar is in the STL's own millimetres).
    const Obstacle placed = io::compileObstacles({o}, scene.file).front();
    const Vec3 point = units::mmToM(1.0) * (o.scaleToMm * info.neck.point + o.offsetMm);
    note = "sac and neck plane of " + sidecar;
    return makeSac(placed.mesh, Plane{point, info.neck.normal});
  }
  return std::nullopt;
}

PracticeCase parseCase(const nlohmann::json& document, const std::string& file) {
  const JsonNode root(document, file);
  if (!root.isObject()) root.expected("a case object {\"format\": \"coilsim-case/1\", ...}");
  root.allowKeys({"format", "name", "description", "scene", "sac", "coils", "catalogue", "goal", "spacing_mm", "morphology",
                  "first_coil", "sequences"});
  // What `coilsim case new` measured and recommended: for the reader, recomputed from the sac when needed.
  for (const char* info : {"morphology", "first_coil"})
    if (auto m = root.optional(info); m && !m->isObject()) m->expected("an object (written by coilsim case new)");
  root.child("format").oneOf({kCaseFormat});
  PracticeCase c;
  c.file = file;
  c.name = root.child("name").string();
  if (auto d = root.optional("description")) c.description = d->string(true);
  const JsonNode scene = root.child("scene");
  if (scene.exists() && scene.value().is_string()) c.scene = io::loadScene(besideFile(file, scene.string()));
  else if (scene.isObject()) {
    c.scene = io::parseScene(scene.value(), file + " (scene)");
    io::checkScene(c.scene);
  } else scene.expected("a scene file path (relative to the case file) or an inline scene object");
  if (!c.scene.deployment) scene.fail("the scene has no \"deployment\" block: a case needs a catheter and a coil");
  c.sac = readSac(root.child("sac"));
  const std::string catalogue = root.has("catalogue") ? besideFile(file, root.child("catalogue").string())
                                                      : defaultCatalogue();
  const std::vector<io::CoilSpec> all = io::loadCatalogue(catalogue);
  for (const JsonNode& name : root.child("coils").items(1, 50, "an array of catalogue coil names")) {
    try {
      c.coils.push_back(io::findCoil(all, name.string()));
    } catch (const io::InputError& e) {
      name.fail(e.what());
    }
  }
  if (auto seqs = root.optional("sequences")) {
    for (const JsonNode& s : seqs->items(1, 50, "an array of sequences {\"name\": ..., \"coils\": [...]}")) {
      if (!s.isObject()) s.expected("a sequence {\"name\": ..., \"coils\": [coil names of the case's \"coils\"]}");
      s.allowKeys({"name", "coils"});
      CoilSequence seq;
      const JsonNode name = s.child("name");
      seq.name = name.string();
      for (const CoilSequence& other : c.sequences)
        if (other.name == seq.name) name.fail("two sequences are called \"" + seq.name + "\"");
      for (const JsonNode& coil : s.child("coils").items(1, 50, "an array of coil names from the case's \"coils\"")) {
        const std::string n = coil.string();
        const auto it = std::find_if(c.coils.begin(), c.coils.end(), [&](const io::CoilSpec& k) { return k.name == n; });
        if (it == c.coils.end()) coil.fail("\"" + n + "\" is not in the case's coil set (\"coils\")");
        seq.coils.push_back(*it);
      }
      c.sequences.push_back(std::move(seq));
    }
  }
  if (auto g = root.optional("goal")) {
    g->allowKeys({"min_packing_density", "no_protrusion", "max_wall_force_mN", "detach_in_sac"});
    if (auto v = g->optional("min_packing_density")) c.goal.minPackingDensity = v->number(Bounds::closed(0, 1));
    if (auto v = g->optional("no_protrusion")) c.goal.noProtrusion = v->boolean();
    if (auto v = g->optional("max_wall_force_mN")) c.goal.maxWallForce = units::mnToN(v->number(Bounds::positive()));
    if (auto v = g->optional("detach_in_sac")) c.goal.detachInSac = v->boolean();
  }
  if (auto s = root.optional("spacing_mm")) c.spacingMm = s->number(Bounds{0.05, 5, false, false, "mm"});
  return c;
}

const CoilSequence& findSequence(const PracticeCase& c, const std::string& name) {
  std::string names;
  for (const CoilSequence& s : c.sequences) {
    if (s.name == name) return s;
    names += (names.empty() ? "" : ", ") + s.name;
  }
  throw io::InputError(c.file + ": no sequence called \"" + name + "\" in \"sequences\"; " +
                       (names.empty() ? std::string("the case has none") : "it has: " + names));
}

namespace {
std::string& dataDirectory() {
  static std::string dir = COILSIM_SOURCE_DIR;
  return dir;
}
}  // namespace

void setDataDirectory(const std::string& dir) { dataDirectory() = dir; }

std::string defaultCatalogue() { return dataDirectory() + "/assets/coils"; }

PracticeCase loadCase(const std::string& path) { return parseCase(io::readJsonFile(path), path); }

Sac loadSac(const std::string& path) {
  const nlohmann::json doc = io::readJsonFile(path);
  const JsonNode root(doc, path);
  if (!root.isObject()) root.expected("an object {\"sac\": {...}}");
  root.allowKeys({"sac", "description"});
  return readSac(root.child("sac"));
}

}  // namespace coilsim::planning
