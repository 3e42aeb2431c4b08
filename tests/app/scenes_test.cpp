// The shipped phantom catalogue (assets/meshes) and the contact scenes that
// use it (scenes/sidewall-7mm.json, scenes/bifurcation-7mm.json), checked
// against geometry that does not come from the simulation: the catalogue's
// surfaces by their topology and by the ideal sac's spherical-cap volume,
// the deployed coils by the signed distance to the phantom surface and by
// the analytic sac sphere of the phantom's sidecar.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>

#include <nlohmann/json.hpp>

#include "app/run_binary.h"
#include "geometry/mesh_query.h"
#include "geometry/volume.h"
#include "io/mesh_file.h"
#include "planning/case_file.h"
#include "planning/metrics.h"
#include "planning/sac_geometry.h"
#include "io/scene.h"
#include "physics/run.h"
#include "physics/integrator.h"
#include "support/refusal.h"
#include "support/known_bugs.h"

namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using namespace apptest;
namespace geometry = coilsim::geometry;
namespace io = coilsim::io;
namespace planning = coilsim::planning;
using coilsim::Vec3;

const fs::path kCatalogue = fs::path(kSource) / "assets" / "meshes";

std::vector<fs::path> catalogueMeshes() {
  std::vector<fs::path> out;
  for (const auto& e : fs::directory_iterator(kCatalogue))
    if (e.path().extension() == ".stl") out.push_back(e.path());
  std::sort(out.begin(), out.end());
  return out;
}

// Every phantom the catalogue script makes is there, small, closed, oriented
// outward in one piece as written (no repair needed), with a sidecar whose
// neck plane cuts the ideal sac's volume out of the surface: the volume above
// the neck plane (exact plane cut of the mesh) against the ellipsoid cap
// a^2 c V(cap of the unit ball), within 2 % (fillets at the neck add a little,
// facets take a little away). Multi-lobe phantoms hold more than their main lobe.
TEST(PhantomCatalogue, EveryMeshIsSmallClosedOrientedAndItsSidecarCutsTheSac) {
  const std::vector<fs::path> meshes = catalogueMeshes();
  std::set<std::string> names;
  for (const fs::path& p : meshes) names.insert(p.filename().string());
  for (const char* expected : {"sidewall-5mm.stl", "sidewall-7mm.stl", "sidewall-10mm.stl", "sidewall-7mm-wide-neck.stl",
                               "multilobe-7mm.stl", "curved-7mm.stl", "bifurcation-7mm.stl"})
    EXPECT_TRUE(names.count(expected)) << expected << " missing from " << kCatalogue << ": run assets/meshes/make-catalogue.sh";
  const std::string readme = slurp(kCatalogue / "README.md");
  for (const fs::path& p : meshes) {
    SCOPED_TRACE(p.filename().string());
    EXPECT_LT(fs::file_size(p), 1000000u);
    const io::MeshInspection in = io::inspectMeshFile(p.string());
    EXPECT_TRUE(in.report.usable()) << io::describeInspection(in);
    EXPECT_EQ(in.report.components, 1u);
    EXPECT_TRUE(in.repaired.actions.empty()) << io::describeInspection(in);
    const geometry::PhantomInfo info = io::readPhantomSidecar(io::phantomSidecarPath(p.string()));
    const double above = geometry::volumeAbovePlane(in.mesh, info.neck);
    const double a = info.sacRadii.x(), c = info.sacRadii.z();
    const double s = (info.sacCentre - info.neck.point).dot(info.neck.normal) / c;  // centre above the plane, in c
    const double h = 1 - s;                                                          // unit-ball cap below the plane
    const double ideal = a * a * c * (4 * M_PI / 3 - M_PI * h * h * (3 - h) / 3);
    if (info.lobes.size() == 1)
      EXPECT_NEAR(above, ideal, 0.02 * ideal);
    else
      EXPECT_GT(above, ideal);
    std::printf("[ measured ] %s: %zu triangles, %ju bytes, sac above the neck %.1f mm^3 (ideal main lobe %.1f)\n",
                p.filename().string().c_str(), in.report.triangles, std::uintmax_t(fs::file_size(p)), above, ideal);
    // The catalogue's README lists each file with its triangle count.
    std::string file = "`", count = " ";
    file.append(p.filename().string()).append("`");
    count.append(std::to_string(in.report.triangles)).append(" ");
    EXPECT_NE(readme.find(file), std::string::npos) << "not in assets/meshes/README.md";
    EXPECT_NE(readme.find(count), std::string::npos) << in.report.triangles << " triangles not in assets/meshes/README.md";
  }
}

// Planning reads a phantom as a sac through its sidecar ({"phantom": STL}).
TEST(PhantomCatalogue, PlanningReadsASacFromAPhantomAndItsSidecar) {
  const fs::path dir = scratch("catalogue_sac");
  const fs::path stl = kCatalogue / "sidewall-7mm.stl";
  std::ofstream(dir / "sac.json") << json{{"sac", {{"phantom", stl.string()}}}}.dump();
  const planning::Sac sac = planning::loadSac((dir / "sac.json").string());
  const geometry::PhantomInfo info = io::readPhantomSidecar(io::phantomSidecarPath(stl.string()));
  EXPECT_NEAR((sac.neck.point - 1e-3 * info.neck.point).norm(), 0, 1e-12);
  EXPECT_NEAR((sac.neck.normal - Vec3::UnitZ()).norm(), 0, 1e-12);
  // The sac centre (sidecar) is inside the surface; 1 mm beyond the dome is not.
  EXPECT_TRUE(planning::insideSurface(sac, 1e-3 * info.sacCentre));
  EXPECT_FALSE(planning::insideSurface(sac, 1e-3 * (info.sacCentre + (info.sacRadii.z() + 1) * Vec3::UnitZ())));
}

struct CoilCheck {
  double minDepth = 1e9;        // smallest distance of a node centre inside the surface, mm (< 0: outside)
  double maxFromCentre = 0;     // largest distance of a node from the sac centre, mm
  double minAboveNeck = 1e9;    // lowest node above the neck plane, mm
  double beyondNeck = 0;        // coil length inside the surface beyond the neck plane, mm (planning's measure)
  int nodes = 0;
};

// Runs `scene` headless with `timeline` for `duration` s and measures the
// coil's nodes against the phantom `stl` (mesh) and its sidecar (sphere, neck).
CoilCheck deployInto(const std::string& name, const fs::path& scene, const std::string& timeline, double duration,
                     const fs::path& stl, json& result) {
  const fs::path dir = scratch("scene_" + name);
  std::ofstream(dir / "timeline.json") << timeline;
  const Exec r = apptest::coilsim({"run", scene.string(), "--headless", "--input", (dir / "timeline.json").string(), "--duration",
                          std::to_string(duration), "--out", (dir / "r.json").string()},
                         dir);
  EXPECT_EQ(r.code, 0) << r.err;
  CoilCheck c;
  if (!fs::exists(dir / "r.json")) return ADD_FAILURE() << "no result: " << r.err, c;
  result = readJson(dir / "r.json");
  const io::MeshInspection in = io::inspectMeshFile(stl.string());
  const geometry::MeshQuery query(in.mesh);
  const geometry::PhantomInfo info = io::readPhantomSidecar(io::phantomSidecarPath(stl.string()));
  const planning::Sac sac = planning::phantomSac(stl.string());
  for (const json& rod : result["rods"]) {
    if (rod["name"] != "coil") continue;
    Vec3 previous = Vec3::Zero();
    for (const json& n : rod["nodes_mm"]) {
      const Vec3 x(n[0].get<double>(), n[1].get<double>(), n[2].get<double>());
      c.minDepth = std::min(c.minDepth, -query.signedDistance(x));
      c.maxFromCentre = std::max(c.maxFromCentre, (x - info.sacCentre).norm());
      c.minAboveNeck = std::min(c.minAboveNeck, info.neck.side(x));
      if (c.nodes > 0) c.beyondNeck += 1e3 * planning::lengthBeyondNeck(sac, 1e-3 * previous, 1e-3 * x);
      previous = x;
      ++c.nodes;
    }
  }
  return c;
}

struct SceneCase {
  const char* scene;
  const char* mesh;
};

class ContactScene : public testing::TestWithParam<SceneCase> {};

// The scene as shipped (the default scene is the sidewall phantom with an
// angled catheter), with a shortened timeline: 30 mm pushed at 10 mm/s
// (the fastest clinical push) and 0.3 s to settle. No refused step; every
// node of the coil inside the phantom's surface (its centre, and its wire
// surface to within 10 % of the wire radius) and inside the ideal sac sphere
// (centre within 10 % of the wire radius: the neck fillets bulge beyond the
// sphere): the coil ends in the sac, not in the vessel.
//
// Below the neck plane only by bulging through the opening: the 7 mm loops
// are larger than the sphere their centre line can reach (radius R - r), so
// they press outward everywhere, and where a loop crosses the neck no wall
// holds it. Over the opening (radius a) a loop can sag no deeper than an arc
// of its largest curvature kappa, 1 / (R - r) (more curved than its rest
// loop, the wall bends it so), spanning the whole opening:
// 1/kappa - sqrt(1/kappa^2 - a^2), 0.49 mm here. (Recorded as the bug
// kLoopBelowNeckPlane while the test asked for no node below the plane; the
// default and bifurcation scenes end 0.16-0.35 mm below it with no wall
// penetration anywhere, where the round-off of a chaotic deployment decides
// which loop crosses the neck.) Planning's measure of coil beyond the neck
// must agree with the nodes: some length exactly when a node is below it.
TEST_P(ContactScene, ShortenedDeploymentKeepsTheCoilInTheSac) {
  const SceneCase sc = GetParam();
  if (std::string(sc.scene) == "sidewall-7mm.json") SKIP_IF_OPEN(coilsim::test::kSoftCoilHeadOnWallContact);
  const fs::path scene = fs::path(kSource) / "scenes" / sc.scene;
  const json spec = readJson(scene);
  const double r = spec["deployment"]["coil"]["section"]["outer_radius_mm"].get<double>();
  ASSERT_TRUE(spec["effects"].contains("wall_contact") && spec["effects"].contains("self_contact"));
  json result;
  const CoilCheck c = deployInto(sc.scene, scene,
                                 R"({"format": "coilsim-timeline/1", "commands": [
                                     {"t_s": 0, "push": {"speed_mm_s": 10, "distance_mm": 30}}]})",
                                 3.3, kCatalogue / sc.mesh, result);
  ASSERT_FALSE(result.is_null());
  EXPECT_EQ(result["status"], "ok");
  EXPECT_EQ(result["stats"]["blowups"], 0);
  const double initial = spec["deployment"].value("initial_deployed_mm", 0.0);
  EXPECT_NEAR(result["deployment"]["deployed_mm"].get<double>(), initial + 30.0, 1e-9);
  EXPECT_GE(c.nodes, 61);  // the tip node and at least 60 nodes of coil (0.5 mm beams)
  EXPECT_GE(c.minDepth, -0.1 * r);  // node centres inside the surface
  EXPECT_GE(c.minDepth, 0.9 * r);   // and the wire itself: penetration below 10 % of its radius (issue 6)
  const geometry::PhantomInfo info = io::readPhantomSidecar(io::phantomSidecarPath((kCatalogue / sc.mesh).string()));
  EXPECT_LE(c.maxFromCentre, info.sacRadii.x() + 0.1 * r);
  const double a = 0.5 * info.neckWidth, reach = info.sacRadii.x() - r;
  const double loopRadius = 0.5 * spec["deployment"]["coil"]["rest_shape"]["loop_diameter_mm"].get<double>();
  const double bend = std::min(reach, loopRadius), sag = bend - std::sqrt(bend * bend - a * a);
  EXPECT_GT(c.minAboveNeck, -sag) << "deeper below the neck plane than a loop can sag over the opening";
  EXPECT_EQ(c.beyondNeck > 0, c.minAboveNeck < 0) << c.beyondNeck << " mm beyond the neck plane (planning)";
  // And during the deployment, as the run's own contact detection saw it.
  const double during = result["stats"]["max_wall_penetration_of_radius"].get<double>();
  std::printf("[ measured ] %s: deepest wall penetration during the run %.1f um (%.1f %% of r)\n", sc.scene,
              result["stats"]["max_wall_penetration_um"].get<double>(), 100 * during);
  if (!coilsim::test::kTransientWallPenetration.open) {
    EXPECT_LT(during, 0.1);
  }
  std::printf("[ measured ] %s: %d nodes; nearest node centre %.5f mm inside the wall (wire radius r = %.4f mm: "
              "penetration %.2e mm); farthest node %.3f mm from the sac centre (R %.2f); lowest %.3f mm above the neck "
              "plane (a loop may sag %.3f mm over the neck), %.3f mm of coil beyond it\n",
              sc.scene, c.nodes, c.minDepth, r, std::max(0.0, r - c.minDepth),
              c.maxFromCentre, info.sacRadii.x(), c.minAboveNeck, sag, c.beyondNeck);
}

// The scene with its wall's law set: held by constraints (rigid), or a
// penalty soft enough for the scene's step to resolve: omega h =
// sqrt(k / (rho A)) h about 54 for these coils at 2 N/mm^2 and 1 ms
// (docs/contact.md: every penalty with omega h up to about 50 ends a push
// where the constraint does; the registered 200 N/mm^2, omega h 541,
// chatters). Two laws that share no code: an active set on the band, and a
// spring on its diagonal.
fs::path withWallLaw(const fs::path& scene, const std::string& name, bool rigid) {
  json spec = readJson(scene);
  for (json& o : spec["obstacles"])
    if (o.contains("mesh") && fs::path(o["mesh"].get<std::string>()).is_relative())
      o["mesh"] = (scene.parent_path() / o["mesh"].get<std::string>()).lexically_normal().string();
  json& wall = spec["effects"]["wall_contact"];
  wall["rigid"] = rigid ? 1 : 0;
  if (!rigid) wall["stiffness_n_mm2"] = 2.0, wall["stiffness_per_rigidity_1_mm3"] = 0.1;
  const fs::path out = scratch((rigid ? "constraint_" : "resolved_") + name) / "scene.json";
  std::ofstream(out) << spec.dump(2);
  return out;
}

// The shortened deployment above with the wall held by constraints (not
// the shipped default yet): where the coil ends and the largest sustained
// wall load are the converged wall's, those of the same push with the
// penalty resolved in time, within 0.5 mm of coil beyond the neck and
// 15 % of the load. In the two sidewall scenes about half the push goes
// back through the 3.5 mm neck under both (docs/contact.md, "Under the
// constraint the push ends with half the coil back in the parent vessel");
// the registered penalty at 1 ms keeps it in the sac and fails here (the
// default scene: 2.6 mm beyond the neck and 35 mN, against 14.8 mm and
// 0.78 mN). The
// bounds of the test above that do not depend on where the coil ends hold
// under the constraint too.
TEST_P(ContactScene, ShortenedDeploymentUnderTheWallConstraintEndsWhereTheResolvedPenaltyEndsIt) {
  const SceneCase sc = GetParam();
  const fs::path scene = fs::path(kSource) / "scenes" / sc.scene;
  const json spec = readJson(scene);
  const double r = spec["deployment"]["coil"]["section"]["outer_radius_mm"].get<double>();
  const std::string timeline = R"({"format": "coilsim-timeline/1", "commands": [
                                     {"t_s": 0, "push": {"speed_mm_s": 10, "distance_mm": 30}}]})";
  json result, reference;
  const CoilCheck c = deployInto(std::string("constraint_") + sc.scene, withWallLaw(scene, sc.scene, true), timeline,
                                 3.3, kCatalogue / sc.mesh, result);
  const CoilCheck soft = deployInto(std::string("resolved_") + sc.scene, withWallLaw(scene, sc.scene, false), timeline,
                                    3.3, kCatalogue / sc.mesh, reference);
  ASSERT_FALSE(result.is_null());
  ASSERT_FALSE(reference.is_null());
  EXPECT_EQ(result["status"], "ok");
  EXPECT_EQ(result["stats"]["blowups"], 0);
  const double initial = spec["deployment"].value("initial_deployed_mm", 0.0);
  EXPECT_NEAR(result["deployment"]["deployed_mm"].get<double>(), initial + 30.0, 1e-9);
  EXPECT_GE(c.nodes, 61);
  EXPECT_GE(c.minDepth, 0.9 * r);  // the wire inside the surface: penetration below 10 % of its radius
  EXPECT_LT(result["stats"]["max_wall_penetration_of_radius"].get<double>(), 0.1);
  EXPECT_EQ(c.beyondNeck > 0, c.minAboveNeck < 0) << c.beyondNeck << " mm beyond the neck plane (planning)";
  const json &got = result["readouts"], &want = reference["readouts"];
  const double beyond = got["protruding_length_mm"].get<double>(), beyondRef = want["protruding_length_mm"].get<double>();
  const double load = got["largest_wall_load_mN"].get<double>(), loadRef = want["largest_wall_load_mN"].get<double>();
  EXPECT_NEAR(beyond, beyondRef, 0.5) << "coil beyond the neck, mm";
  EXPECT_NEAR(c.beyondNeck, soft.beyondNeck, 0.5) << "planning's measure on the nodes, mm";
  EXPECT_NEAR(load, loadRef, 0.15 * loadRef) << "largest sustained wall load, mN";
  std::printf("[ measured ] %s under the constraint: %.3f mm of coil beyond the neck, largest sustained wall load "
              "%.3f mN; the penalty resolved in time (omega h about 54): %.3f mm, %.3f mN\n",
              sc.scene, beyond, load, beyondRef, loadRef);
}

// The same deployment in this process, measured at the end of every step
// against the phantom's STL itself (the test's own signed distance, not
// the contact code): at no step may the wire of any node or segment
// midpoint be more than 10 % of its radius inside the wall (issue 6; the
// soft coil's tip sat 17 um = 11 % in for several steps, recorded as
// kTransientWallPenetration). And the coil must come within 10 % of r of
// the wall's surface at some step, or the bound would prove nothing.
TEST_P(ContactScene, NoStepOfTheDeploymentPutsTheWireIntoTheWall) {
  SKIP_IF_OPEN(coilsim::test::kTransientWallPenetration);
  const SceneCase sc = GetParam();
  const fs::path scene = fs::path(kSource) / "scenes" / sc.scene;
  const coilsim::io::SceneSpec spec = io::loadScene(scene.string());
  const coilsim::Model model = coilsim::compileModel(io::compileScene(spec));
  coilsim::State state = coilsim::makeState(model);
  const coilsim::Deployment& dep = *model.device;
  ASSERT_EQ(coilsim::test::refusal(coilsim::command(model, state, {coilsim::DeviceCommand::Kind::Push, 0.01, 0.03})), "");
  const geometry::MeshQuery stl(io::inspectMeshFile((kCatalogue / sc.mesh).string()).mesh);  // mm
  const double r = 1e3 * dep.section.radius;  // mm
  double deepest = -1e9, deepestAt = 0;  // wire penetration, mm (< 0: clear)
  const int steps = int(std::lround(3.3 / model.timeStep));
  for (int i = 0; i < steps; ++i) {
    ASSERT_TRUE(coilsim::advance(model, state).ok()) << "step " << i << ": " << state.warnings.back();
    const coilsim::RodState& rod = state.rods[dep.chainRod];
    for (int k = 1; k < rod.activeNodes; ++k)
      for (const Vec3& x : {Vec3(rod.x[k]), Vec3(0.5 * (rod.x[k] + rod.x[k - 1]))}) {
        const double depth = r + stl.signedDistance(1e3 * x);
        if (depth > deepest) deepest = depth, deepestAt = state.time;
      }
  }
  std::printf("[ measured ] %s: deepest wire penetration at the end of any step %.2f um (%.1f %% of r) at t = %.3f s "
              "(STL signed distance)\n", sc.scene, 1e3 * deepest, 100 * deepest / r, deepestAt);
  EXPECT_LT(deepest, 0.1 * r);
  EXPECT_GT(deepest, -0.1 * r) << "the coil never came near the wall: the bound proves nothing";
}

INSTANTIATE_TEST_SUITE_P(Scenes, ContactScene,
                         testing::Values(SceneCase{"default.json", "sidewall-7mm.stl"},
                                         SceneCase{"sidewall-7mm.json", "sidewall-7mm.stl"},
                                         SceneCase{"bifurcation-7mm.json", "bifurcation-7mm.stl"}),
                         [](const testing::TestParamInfo<SceneCase>& i) {
                           std::string n = i.param.scene;
                           n = n.substr(0, n.find('.'));
                           std::replace(n.begin(), n.end(), '-', '_');
                           return n;
                         });

}  // namespace

// Patient-derived meshes (../shared/data/meshes, next to the source tree;
// README.txt and SOURCE.txt there: LGPL surfaces from SOFA and DOLFIN, in mm).
// Their sacs were found from the geometry alone, once, and are written here:
//  - sac centre C: the deepest point inside the surface (largest inscribed
//    ball, radius rho), from a 0.4 mm grid of signed distances refined by a
//    pattern search; the next deepest points are the vessels (< 2.6 mm);
//  - neck axis d (unit, from C toward the parent vessel): the mean direction
//    of the 12 longest free rays of 4000 cast from C (the rays that escape
//    through the neck run 14-28 mm, the others end on the sac wall at 3-7 mm);
//  - neck plane: across d at t_neck from C, where the inscribed radius along
//    the axis has fallen to the parent vessel's radius (sofa: 2.3 mm of a
//    ~4.5 mm vessel at t = 6 mm; dolfin: 2.15 mm at t = 4.5 mm, then 0.7 mm
//    at the bifurcation apex).
// The microcatheter tip sits on the axis 0.6 rho from C, pointing into the
// sac (-d). A soft helical coil of loops 0.8 of the sac diameter is pushed.
struct PatientSac {
  const char* name;
  const char* mesh;  // under ../shared/data/meshes
  Vec3 centre;       // C, mm
  double rho;        // inscribed radius at C, mm
  Vec3 axis;         // d
  double neckAt;     // t_neck, mm
  double loopMm, lengthMm;
};

const PatientSac kPatientSacs[] = {
    {"sofa_aneurysm3D_1", "sofa_aneurysm3D_1/aneurysm3D_1.stl", Vec3(5.970, -0.100, 1.291), 4.927,
     Vec3(-0.9270, 0.2065, -0.3131), 6.0, 8, 30},
    {"dolfin_aneurysm", "dolfin_aneurysm/aneurysm_closed.stl", Vec3(53.842, 43.302, 35.740), 3.168,
     Vec3(0.2130, 0.1933, -0.9577), 4.5, 5, 20},
};

json patientScene(const PatientSac& p, const fs::path& mesh) {
  json scene = readJson(fs::path(kSource) / "scenes" / "sidewall-7mm.json");  // its coil, effects, blood
  scene["name"] = std::string("patient-") + p.name;
  scene.erase("description");
  scene["obstacles"] = json::array({{{"name", p.name}, {"mesh", mesh.string()}, {"friction", 0.3}}});
  const Vec3 d = p.axis.normalized();
  const Vec3 tip = p.centre + 0.6 * p.rho * d;
  const Vec3 normal = d.cross(Vec3::UnitZ()).normalized();
  json& cath = scene["deployment"]["catheter"];
  cath["tip_position_mm"] = {tip.x(), tip.y(), tip.z()};
  cath["direction"] = {-d.x(), -d.y(), -d.z()};
  cath["reference_normal"] = {normal.x(), normal.y(), normal.z()};
  cath["draw_length_mm"] = 0.6 * p.rho;
  json& coil = scene["deployment"]["coil"];
  coil["length_mm"] = p.lengthMm;
  coil["beams"] = int(2 * p.lengthMm);
  coil["rest_shape"]["loop_diameter_mm"] = p.loopMm;
  scene["duration_s"] = p.lengthMm / 10 + 0.3;
  return scene;
}

// Each patient mesh loads (closed, oriented, usable as a wall), the sac
// found above is still where it was said to be, and a coil pushed at
// 10 mm/s from the catheter tip stays in it: no refused step, every node
// inside the surface with the wire penetrating less than 10 % of its radius,
// on the sac side of the neck plane, and in sight of the sac centre (the
// straight line from C to the node stays inside the surface: not in a side
// branch).
TEST(PatientMesh, CoilDeploysIntoTheSacFoundFromTheGeometry) {
  const fs::path shared = fs::path(kSource) / ".." / "shared" / "data" / "meshes";
  int found = 0;
  for (const PatientSac& p : kPatientSacs) {
    SCOPED_TRACE(p.name);
    const fs::path mesh = shared / p.mesh;
    if (!fs::exists(mesh)) continue;
    ++found;
    const io::MeshInspection in = io::inspectMeshFile(mesh.string());
    ASSERT_TRUE(in.repaired.usable) << io::describeInspection(in);
    const geometry::MeshQuery query(in.repaired.mesh);
    EXPECT_NEAR(-query.signedDistance(p.centre), p.rho, 0.01);
    const Vec3 d = p.axis.normalized();
    EXPECT_GT(-query.signedDistance(p.centre + 0.6 * p.rho * d), 0.5 * p.rho);  // the tip is well inside

    const fs::path dir = scratch(std::string("patient_") + p.name);
    std::ofstream(dir / "scene.json") << patientScene(p, mesh).dump(1);
    std::ofstream(dir / "timeline.json") << json{{"format", "coilsim-timeline/1"},
                                                  {"commands", {{{"t_s", 0}, {"push", {{"speed_mm_s", 10}, {"distance_mm", p.lengthMm}}}}}}};
    const Exec r = apptest::coilsim({"run", (dir / "scene.json").string(), "--headless", "--input",
                                     (dir / "timeline.json").string(), "--out", (dir / "r.json").string()},
                                    dir);
    ASSERT_EQ(r.code, 0) << r.err;
    const json result = readJson(dir / "r.json");
    EXPECT_EQ(result["stats"]["blowups"], 0);
    EXPECT_NEAR(result["deployment"]["deployed_mm"].get<double>(), p.lengthMm, 1e-9);
    const double wire = patientScene(p, mesh)["deployment"]["coil"]["section"]["outer_radius_mm"].get<double>();
    double minDepth = 1e9, maxT = -1e9;
    int nodes = 0, hidden = 0;
    for (const json& rod : result["rods"]) {
      if (rod["name"] != "coil") continue;
      for (const json& n : rod["nodes_mm"]) {
        const Vec3 x(n[0].get<double>(), n[1].get<double>(), n[2].get<double>());
        ++nodes;
        minDepth = std::min(minDepth, -query.signedDistance(x));
        maxT = std::max(maxT, (x - p.centre).dot(d));
        const int steps = int(std::ceil((x - p.centre).norm() / 0.05));
        for (int k = 1; k < steps; ++k)
          if (query.signedDistance(p.centre + (double(k) / steps) * (x - p.centre)) > 0) {
            ++hidden;
            break;
          }
      }
    }
    EXPECT_EQ(nodes, int(2 * p.lengthMm) + 1);
    EXPECT_GE(minDepth, 0.9 * wire);
    EXPECT_LT(maxT, p.neckAt);
    EXPECT_EQ(hidden, 0);
    std::printf("[ measured ] %s: %zu triangles; %d coil nodes, nearest %.5f mm inside the wall (wire radius %.4f), "
                "deepest toward the neck %.2f mm from C (neck plane at %.1f), %d out of sight of C\n",
                p.name, in.report.triangles, nodes, minDepth, wire, maxT, p.neckAt, hidden);
  }
  if (found == 0) GTEST_SKIP() << "no patient meshes in " << shared << " (../shared/data absent): nothing checked";
}
