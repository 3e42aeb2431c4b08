// Mesh files through assimp: the patient meshes of ../shared/data/meshes
// against the counts and volumes their README gives (measured with VTK),
// hand-written OBJ/PLY/STL files, round trips, and errors naming the file.
#include "io/mesh_file.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <unistd.h>

#include "geometry/volume.h"
#include "io/expect_error.h"
#include "io/scene.h"
#include "physics/draw_data.h"
#include "physics/model.h"
#include "physics/state.h"

namespace coilsim::io {
namespace {

namespace fs = std::filesystem;

const fs::path kMeshes = fs::path(COILSIM_SOURCE_DIR) / ".." / "shared" / "data" / "meshes";

fs::path scratch(const std::string& name) {
  const fs::path dir = fs::path(testing::TempDir()) / ("coilsim_mesh_" + name + "." + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

void write(const fs::path& p, const std::string& text) { std::ofstream(p) << text; }

// The unit cube (mm) as an ASCII PLY; `flipFace` reverses one triangle.
std::string cubePly(bool flipFace, int faces = 12) {
  std::string s = "ply\nformat ascii 1.0\nelement vertex 8\nproperty float x\nproperty float y\nproperty float z\n";
  s += "element face " + std::to_string(faces) + "\nproperty list uchar int vertex_indices\nend_header\n";
  for (int i = 0; i < 8; ++i) s += std::to_string(i & 1) + " " + std::to_string((i >> 1) & 1) + " " + std::to_string((i >> 2) & 1) + "\n";
  const int tris[12][3] = {{0, 2, 3}, {0, 3, 1}, {4, 5, 7}, {4, 7, 6}, {0, 1, 5}, {0, 5, 4},
                           {2, 6, 7}, {2, 7, 3}, {0, 4, 6}, {0, 6, 2}, {1, 3, 7}, {1, 7, 5}};
  for (int t = 0; t < faces; ++t) {
    const bool flip = flipFace && t == 5;
    s += "3 " + std::to_string(tris[t][0]) + " " + std::to_string(tris[t][flip ? 2 : 1]) + " " +
         std::to_string(tris[t][flip ? 1 : 2]) + "\n";
  }
  return s;
}

struct PatientMesh {
  const char* file;
  size_t triangles;
  double volumeMm3;    // from ../shared/data/meshes/*/SOURCE.txt (VTK)
  Vec3 lower, upper;   // bounding box, mm, from the same (2 decimals)
};

TEST(MeshFile, PatientMeshesLoadClosedAndOrientedWithTheDocumentedCounts) {
  const PatientMesh meshes[] = {
      {"sofa_aneurysm3D_1/aneurysm3D_1.off", 14186, 1378.8, Vec3(-21.76, -17.30, -15.56), Vec3(11.44, 5.31, 7.40)},
      {"sofa_aneurysm3D_1/aneurysm3D_1.stl", 14186, 1378.8, Vec3(-21.76, -17.30, -15.56), Vec3(11.44, 5.31, 7.40)},
      {"dolfin_aneurysm/aneurysm_closed.stl", 3226, 778.4, Vec3(38.65, 35.62, 3.74), Vec3(60.00, 54.72, 49.62)},
      {"dolfin_aneurysm/aneurysm_grouped.obj", 3226, 778.4, Vec3(38.65, 35.62, 3.74), Vec3(60.00, 54.72, 49.62)},
  };
  int found = 0;
  for (const PatientMesh& m : meshes) {
    const fs::path path = kMeshes / m.file;
    if (!fs::exists(path)) continue;
    ++found;
    const MeshInspection in = inspectMeshFile(path.string());
    EXPECT_EQ(in.report.triangles, m.triangles) << m.file;
    EXPECT_TRUE(in.report.closed()) << describeInspection(in);
    EXPECT_TRUE(in.report.oriented()) << describeInspection(in);
    EXPECT_EQ(in.report.components, 1u) << m.file;
    EXPECT_LT((in.report.lower - m.lower).cwiseAbs().maxCoeff(), 0.006) << m.file << ": lower bound";
    EXPECT_LT((in.report.upper - m.upper).cwiseAbs().maxCoeff(), 0.006) << m.file << ": upper bound";
    EXPECT_NEAR(in.report.volume, m.volumeMm3, 0.05 + 1e-4 * m.volumeMm3) << m.file;  // README gives 0.1 mm^3
    EXPECT_TRUE(in.repaired.usable) << in.repaired.reason;
    std::printf("[ measured ] %s: %zu triangles, %.2f mm^3, %d parts, bounds [%.3f, %.3f] x [%.3f, %.3f] x [%.3f, %.3f] mm, "
                "closed %d, oriented %d, %zu repairs\n",
                m.file, in.report.triangles, in.report.volume, in.parts, in.report.lower.x(), in.report.upper.x(),
                in.report.lower.y(), in.report.upper.y(), in.report.lower.z(), in.report.upper.z(), in.report.closed(),
                in.report.oriented(), in.repaired.actions.size());
    // Loaded for the core: metres.
    const TriangleMesh si = loadMeshFile(path.string());
    EXPECT_NEAR(geometry::enclosedVolume(si), m.volumeMm3 * 1e-9, 1e-4 * m.volumeMm3 * 1e-9);
  }
  if (found == 0) GTEST_SKIP() << "no patient meshes in " << kMeshes << " (../shared/data absent): nothing checked";
}

TEST(MeshFile, HandWrittenPlyCubeLoadsAndAFlippedFaceIsRepaired) {
  const fs::path dir = scratch("ply");
  write(dir / "cube.ply", cubePly(false));
  MeshInspection in = inspectMeshFile((dir / "cube.ply").string());
  EXPECT_EQ(in.report.triangles, 12u);
  EXPECT_TRUE(in.report.usable());
  EXPECT_NEAR(in.report.volume, 1.0, 1e-12);

  write(dir / "flipped.ply", cubePly(true));
  in = inspectMeshFile((dir / "flipped.ply").string());
  EXPECT_FALSE(in.report.oriented());
  EXPECT_TRUE(in.repaired.usable);
  EXPECT_CONTAINS(describeInspection(in), "re-oriented 1 triangles");
  EXPECT_NEAR(geometry::enclosedVolume(loadMeshFile((dir / "flipped.ply").string(), 2.0)), 8e-9, 1e-20);
}

TEST(MeshFile, ObjWithQuadsIsTriangulated) {
  const fs::path dir = scratch("obj");
  write(dir / "cube.obj",
        "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nv 0 0 1\nv 1 0 1\nv 0 1 1\nv 1 1 1\n"
        "f 1 3 4 2\nf 5 6 8 7\nf 1 2 6 5\nf 3 7 8 4\nf 1 5 7 3\nf 2 4 8 6\n");
  const MeshInspection in = inspectMeshFile((dir / "cube.obj").string(), 10);
  EXPECT_EQ(in.report.triangles, 12u);
  EXPECT_TRUE(in.report.usable()) << describeInspection(in);
  EXPECT_NEAR(in.report.volume, 1000.0, 1e-9);
}

TEST(MeshFile, BinaryStlRoundTripAndSidecar) {
  const fs::path dir = scratch("stl");
  geometry::PhantomSpec spec;
  spec.sacDiameter = 6;
  spec.resolution = 0.5;
  const geometry::Phantom p = geometry::makePhantom(spec);
  const std::string stl = (dir / "sidewall.stl").string();
  writeBinaryStl(p.mesh, stl);
  EXPECT_EQ(fs::file_size(stl), 84 + 50 * p.mesh.triangles.size());
  const MeshInspection in = inspectMeshFile(stl);
  EXPECT_EQ(in.report.triangles, p.mesh.triangles.size());
  EXPECT_EQ(in.report.vertices, p.mesh.vertices.size());  // identical float vertices joined again
  EXPECT_TRUE(in.report.usable()) << describeInspection(in);
  const double v = geometry::enclosedVolume(p.mesh);
  EXPECT_NEAR(in.report.volume, v, 1e-5 * v) << "float32 coordinates";

  const std::string side = phantomSidecarPath(stl);
  EXPECT_EQ(fs::path(side).filename(), "sidewall.phantom.json");
  writePhantomSidecar(p.info, side);
  const geometry::PhantomInfo back = readPhantomSidecar(side);
  EXPECT_EQ(back.type, "sidewall");
  EXPECT_TRUE(back.neck.point.isApprox(p.info.neck.point));
  EXPECT_TRUE(back.neck.normal.isApprox(p.info.neck.normal));
  EXPECT_TRUE(back.sacCentre.isApprox(p.info.sacCentre));
  EXPECT_DOUBLE_EQ(back.idealSacVolume, p.info.idealSacVolume);
  EXPECT_EQ(back.lobes.size(), 1u);
}

TEST(MeshFile, ErrorsNameTheFileAndTheReason) {
  const fs::path dir = scratch("errors");
  const std::string missing = (dir / "missing.stl").string();
  EXPECT_CONTAINS(errorOf([&] { inspectMeshFile(missing); }), missing + ": no such mesh file");

  const std::string garbage = (dir / "garbage.stl").string();
  write(garbage, "this is not a mesh\n");
  const std::string g = errorOf([&] { inspectMeshFile(garbage); });
  EXPECT_CONTAINS(g, garbage + ": ");

  const std::string open = (dir / "open.ply").string();
  write(open, cubePly(false, 10));
  const std::string o = errorOf([&] { loadMeshFile(open); });
  EXPECT_CONTAINS(o, open + ": cannot be used as a wall");
  EXPECT_CONTAINS(o, "4 boundary edges");

  const std::string fin = (dir / "fin.obj").string();
  write(fin,
        "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nv 0 0 1\nv 1 0 1\nv 0 1 1\nv 1 1 1\nv 0.5 -1 -1\n"
        "f 1 3 4 2\nf 5 6 8 7\nf 1 2 6 5\nf 3 7 8 4\nf 1 5 7 3\nf 2 4 8 6\nf 1 2 9\n");
  const std::string f = errorOf([&] { loadMeshFile(fin); });
  EXPECT_CONTAINS(f, fin + ": cannot be used as a wall: 1 non-manifold edges");

  const std::string lines = (dir / "lines.obj").string();
  write(lines, "v 0 0 0\nv 1 0 0\nv 0 1 0\nl 1 2\nl 2 3\n");
  EXPECT_CONTAINS(errorOf([&] { inspectMeshFile(lines); }), lines + ": ");

  EXPECT_CONTAINS(errorOf([&] { inspectMeshFile(open, -1); }), "scale to millimetres");
  EXPECT_CONTAINS(errorOf([&] { inspectMeshFile(dir.string()); }), "not a regular file");

  const std::string badSidecar = (dir / "bad.phantom.json").string();
  write(badSidecar, R"({"format": "coilsim-phantom/1", "type": "fusiform"})");
  EXPECT_CONTAINS(errorOf([&] { readPhantomSidecar(badSidecar); }), badSidecar + ": /type");
}

// A one-rod scene with `obstacles` (JSON text) placed in `dir`.
std::string sceneWith(const std::string& obstacles) {
  return R"({"format": "coilsim-scene/1", "gravity_m_s2": [0, 0, 0], "solve": "dynamic",
    "time_step_s": 0.001, "duration_s": 0.01,
    "rods": [{"name": "coil", "length_mm": 10, "beams": 4, "rest_shape": {"type": "straight"},
      "material": {"young_modulus_gpa": 200, "poisson_ratio": 0.3, "density_g_cm3": 7.85},
      "section": {"wire_radius_mm": 0.1},
      "placement": {"position_mm": [0, 0, 0], "direction": [1, 0, 0], "normal": [0, 1, 0]},
      "boundary": [{"node": 0, "type": "clamped"}]}],
    "obstacles": )" + obstacles + "}";
}

TEST(SceneObstacles, MeshIsLoadedPlacedInMetresAndDrawn) {
  const fs::path dir = scratch("scene_obstacles");
  fs::create_directories(dir / "meshes");
  write(dir / "meshes" / "cube.ply", cubePly(false));
  const std::string file = (dir / "scene.json").string();
  const SceneSpec spec = sceneFromText(
      sceneWith(R"([{"name": "wall", "mesh": "meshes/cube.ply", "scale_to_mm": 2, "rotation_deg": [0, 0, 90],
                     "offset_mm": [10, 0, 0], "friction": 0.4},
                    {"mesh": "meshes/cube.ply", "contact": false}])"),
      file);
  ASSERT_EQ(spec.obstacles.size(), 2u);
  EXPECT_EQ(spec.obstacles[1].name, "cube");
  const ModelDef def = compileScene(spec);
  ASSERT_EQ(def.obstacles.size(), 2u);
  const Obstacle& wall = def.obstacles[0];
  EXPECT_EQ(wall.name, "wall");
  EXPECT_DOUBLE_EQ(wall.friction, 0.4);
  EXPECT_TRUE(wall.contact);
  EXPECT_FALSE(def.obstacles[1].contact);
  // The file's corner (1, 0, 0) is 2 mm out along x; 90 degrees about z takes
  // it to (0, 2, 0) mm; the offset adds 10 mm in x: (0.010, 0.002, 0) m.
  bool found = false;
  for (const Vec3& v : wall.mesh->vertices) found |= (v - Vec3(0.010, 0.002, 0)).norm() < 1e-15;
  EXPECT_TRUE(found);
  EXPECT_NEAR(geometry::enclosedVolume(*wall.mesh), 8e-9, 1e-22) << "a rotation keeps the surface outward";

  const Model model = compileModel(def);
  const State state = makeState(model);
  DrawData draw;
  fillDrawData(model, state, draw);
  ASSERT_EQ(draw.meshes.size(), 2u);
  EXPECT_EQ(draw.meshes[0].name, "wall");
  EXPECT_EQ(draw.meshes[0].triangles.size(), 12u);
  EXPECT_LT(draw.meshes[0].colour[3], 1.0f) << "walls are see-through";
  fillDrawData(model, state, draw);
  EXPECT_EQ(draw.meshes.size(), 2u) << "refilling does not append";
}

TEST(SceneObstacles, BadObstaclesNameSceneJsonPathAndMesh) {
  const fs::path dir = scratch("scene_obstacles_bad");
  write(dir / "open.ply", cubePly(false, 10));
  const std::string file = (dir / "scene.json").string();
  auto compileText = [&](const std::string& obstacles) { compileScene(sceneFromText(sceneWith(obstacles), file)); };
  std::string e = errorOf([&] { compileText(R"([{"mesh": "nothing.stl"}])"); });
  EXPECT_CONTAINS(e, file + ": /obstacles/0/mesh: " + (dir / "nothing.stl").string() + ": no such mesh file");
  e = errorOf([&] { compileText(R"([{"mesh": "open.ply"}])"); });
  EXPECT_CONTAINS(e, "/obstacles/0/mesh: ");
  EXPECT_CONTAINS(e, "boundary edges");
  EXPECT_CONTAINS(errorOf([&] { compileText(R"([{"mesh": "open.ply", "frction": 0.2}])"); }), "/obstacles/0");
  EXPECT_CONTAINS(errorOf([&] { compileText(R"([{"mesh": "open.ply", "friction": -1}])"); }), "/obstacles/0/friction");
  EXPECT_CONTAINS(errorOf([&] { compileText(R"([{"mesh": "open.ply", "scale_to_mm": 0}])"); }), "/obstacles/0/scale_to_mm");
  EXPECT_CONTAINS(errorOf([&] { compileText(R"([{"mesh": "a.stl"}, {"mesh": "a.stl"}])"); }), "used twice");
  EXPECT_CONTAINS(errorOf([&] { compileText(R"({"mesh": "a.stl"})"); }), "/obstacles");
}

}  // namespace
}  // namespace coilsim::io
