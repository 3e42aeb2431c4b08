#include "io/scene_obstacles.h"

#include <filesystem>
#include <memory>
#include <set>

#include "io/mesh_file.h"
#include "io/units.h"

namespace coilsim::io {

std::vector<ObstacleSpec> readObstacles(const JsonNode& node, const std::string& sceneFile) {
  std::vector<ObstacleSpec> out;
  std::set<std::string> names;
  const std::filesystem::path base = std::filesystem::path(sceneFile).parent_path();
  for (const JsonNode& n : node.items(0, 64, "an array of obstacles")) {
    if (!n.isObject()) n.expected("an object {\"mesh\": FILE, ...}");
    n.allowKeys({"name", "mesh", "scale_to_mm", "offset_mm", "rotation_deg", "friction", "contact"});
    ObstacleSpec o;
    o.at = n.path();
    o.mesh = n.child("mesh").string();
    const std::filesystem::path p(o.mesh);
    o.meshPath = p.is_absolute() ? p.string() : (base / p).lexically_normal().string();
    o.name = n.has("name") ? n.child("name").string() : p.stem().string();
    if (!names.insert(o.name).second) n.child("name").fail("obstacle name \"" + o.name + "\" is used twice");
    if (auto s = n.optional("scale_to_mm")) o.scaleToMm = s->number(Bounds::positive());
    if (auto v = n.optional("offset_mm")) {
      const auto a = v->vec3();
      o.offsetMm = Vec3(a[0], a[1], a[2]);
    }
    if (auto v = n.optional("rotation_deg")) {
      const auto a = v->vec3(Bounds::closed(-360, 360, "deg"));
      o.rotationDeg = Vec3(a[0], a[1], a[2]);
    }
    if (auto f = n.optional("friction")) o.friction = f->number(Bounds::closed(0, 2));
    if (auto c = n.optional("contact")) o.contact = c->boolean();
    out.push_back(std::move(o));
  }
  return out;
}

std::vector<Obstacle> compileObstacles(const std::vector<ObstacleSpec>& specs, const std::string& sceneFile) {
  std::vector<Obstacle> out;
  for (const ObstacleSpec& s : specs) {
    TriangleMesh mesh;
    try {
      mesh = loadMeshFile(s.meshPath, s.scaleToMm);
    } catch (const InputError& e) {
      throw InputError(sceneFile + ": " + s.at + "/mesh: " + e.what());
    }
    mesh.name = s.name;
    using units::degToRad;
    const Mat3 r = (Eigen::AngleAxisd(degToRad(s.rotationDeg.z()), Vec3::UnitZ()) *
                    Eigen::AngleAxisd(degToRad(s.rotationDeg.y()), Vec3::UnitY()) *
                    Eigen::AngleAxisd(degToRad(s.rotationDeg.x()), Vec3::UnitX()))
                       .toRotationMatrix();
    const Vec3 offset = s.offsetMm * units::kMetresPerMm;
    for (Vec3& v : mesh.vertices) v = r * v + offset;  // a rotation keeps the orientation outward
    Obstacle o;
    o.name = s.name;
    o.mesh = std::make_shared<const TriangleMesh>(std::move(mesh));
    o.friction = s.friction;
    o.contact = s.contact;
    out.push_back(std::move(o));
  }
  return out;
}

}  // namespace coilsim::io
