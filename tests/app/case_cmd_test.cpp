// `coilsim case new` run as a user runs it: on the patient-derived surfaces
// of ../shared/data/meshes (a case without hints, then a short plan whose
// coil must stay in the sac), on the phantom catalogue (the sac and neck of
// each sidecar), and on surfaces it must refuse.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>

#include "app/run_binary.h"
#include "geometry/marching_tets.h"
#include "geometry/volume.h"
#include "io/mesh_file.h"
#include "planning/case_file.h"

namespace {

using namespace apptest;
using ::coilsim::Vec3;
namespace geometry = ::coilsim::geometry;

nlohmann::json readJson(const fs::path& p) { return nlohmann::json::parse(slurp(p)); }

Vec3 vec(const nlohmann::json& a) { return Vec3(a[0].get<double>(), a[1].get<double>(), a[2].get<double>()); }

// The phantoms of assets/meshes: the neck plane of the case within 3 degrees
// and 0.5 mm of the sidecar's, the sac volume within 10 % of the one the
// sidecar's plane closes (the same tolerances as tests/geometry/sac_finder_test.cpp).
TEST(CaseNew, CataloguePhantomsGiveTheirSidecarsNeck) {
  int checked = 0;
  for (const auto& entry : fs::directory_iterator(fs::path(kSource) / "assets" / "meshes")) {
    if (entry.path().extension() != ".stl") continue;
    const std::string stl = entry.path().string();
    SCOPED_TRACE(stl);
    const fs::path dir = scratch("case_" + entry.path().stem().string());
    const Exec r = apptest::coilsim({"case", "new", stl, "--out", (dir / "case.json").string()}, dir);
    ASSERT_EQ(r.code, 0) << r.err;
    const nlohmann::json c = readJson(dir / "case.json");
    const geometry::PhantomInfo info = ::coilsim::io::readPhantomSidecar(::coilsim::io::phantomSidecarPath(stl));
    const Vec3 n = vec(c["sac"]["neck_plane"]["normal"]).normalized();
    const Vec3 p = vec(c["sac"]["neck_plane"]["point_mm"]);
    EXPECT_GT(n.dot(info.neck.normal), std::cos(3 * M_PI / 180));
    EXPECT_LT(std::abs(info.neck.side(p)), 0.5);
    const ::coilsim::TriangleMesh mesh = ::coilsim::io::inspectMeshFile(stl).repaired.mesh;
    const double truth = geometry::volumeAbovePlane(mesh, info.neck);
    EXPECT_NEAR(c["morphology"]["sac_volume_mm3"].get<double>(), truth, 0.10 * truth);
    // plan and practice read it unchanged.
    EXPECT_NO_THROW(::coilsim::planning::loadCase((dir / "case.json").string()));
    ++checked;
  }
  EXPECT_EQ(checked, 7);
}

// Each patient surface: a case without hints, then two small coils planned
// into it. The 2 x 10 mm coil stays in the sac: placed, nothing below the
// neck plane, all but 5 % of it in the sac. The 3 x 40 mm coil presses on
// the wall (a positive wall force, so the bound below means something) and
// never passes the wall's contact skin, and all of it stays inside the
// surface (in the sac, or below the neck plane in the parent vessel).
TEST(CaseNew, PatientSurfacesGiveACaseWhoseCoilStaysInTheSac) {
  const fs::path shared = fs::path(kSource) / ".." / "shared" / "data" / "meshes";
  for (const char* mesh : {"sofa_aneurysm3D_1/aneurysm3D_1.stl", "dolfin_aneurysm/aneurysm_closed.stl"}) {
    SCOPED_TRACE(mesh);
    ASSERT_TRUE(fs::exists(shared / mesh)) << "the patient meshes live in ../shared/data/meshes beside the clone";
    const fs::path dir = scratch(std::string("patient_") + fs::path(mesh).parent_path().string());
    const Exec made = apptest::coilsim({"case", "new", (shared / mesh).string(), "--out", (dir / "case.json").string()}, dir);
    ASSERT_EQ(made.code, 0) << made.err;
    EXPECT_CONTAINS(made.out, "sac volume");
    const Exec plan = apptest::coilsim({"plan", (dir / "case.json").string(), "--coils", "finishing-2x10,finishing-3x40",
                                        "--jobs", "2", "--speed", "10", "--no-screenshots", "--out", (dir / "plan").string()},
                                       dir);
    ASSERT_EQ(plan.code, 0) << plan.err << plan.out;
    // The plan packs the sac the case measured (on dolfin the neck plane
    // also cuts the daughter vessels, which are not the sac).
    EXPECT_NEAR(readJson(dir / "plan" / "plan.json")["sac_volume_mm3"].get<double>(),
                readJson(dir / "case.json")["morphology"]["sac_volume_mm3"].get<double>(), 0.05);
    const nlohmann::json coils = readJson(dir / "plan" / "plan.json")["coils"];
    ASSERT_EQ(coils.size(), 2u);
    const nlohmann::json &small = coils[0], &pressing = coils[1];
    for (const nlohmann::json& c : coils)
      std::printf("[ measured ] %s, %s: in sac %.2f mm, below the neck %.2f mm, wall force lasting %.3f / peak %.3f mN, "
                  "penetration past the skin %.3f um\n",
                  mesh, c["name"].get<std::string>().c_str(), c["coil_length_in_sac_mm"].get<double>(),
                  c["protruding_length_mm"].get<double>(), c["max_wall_force_mN"].get<double>(),
                  c["peak_wall_force_mN"].get<double>(), c["max_wall_penetration_um"].get<double>());
    EXPECT_TRUE(small["placed"].get<bool>());
    EXPECT_FALSE(small["protruding"].get<bool>());
    EXPECT_GT(small["coil_length_in_sac_mm"].get<double>(), 0.95 * 10);
    EXPECT_TRUE(pressing["placed"].get<bool>());
    EXPECT_GT(pressing["peak_wall_force_mN"].get<double>(), 0.0);
    EXPECT_EQ(pressing["max_wall_penetration_um"].get<double>(), 0.0);
    EXPECT_GT(pressing["coil_length_in_sac_mm"].get<double>() + pressing["protruding_length_mm"].get<double>(), 0.95 * 40);
  }
}

void writeSurface(const ::coilsim::TriangleMesh& m, const fs::path& p) { ::coilsim::io::writeBinaryStl(m, p.string()); }

// A straight vessel with two sacs: the command names both, asks for a
// point (exit 2), and with one makes the case.
TEST(CaseNew, TwoSacsAskForASacPoint) {
  const fs::path dir = scratch("case_two_sacs");
  const Vec3 left(-6, 0, 4.5), right(6, 0, 4.5);
  const geometry::Field field = [&](const Vec3& p) {
    const double tube = std::max(std::hypot(p.y(), p.z()) - 2, std::abs(p.x()) - 14);
    return std::min({tube, (p - left).norm() - 3.2, (p - right).norm() - 3.2});
  };
  writeSurface(geometry::polygonise(field, Vec3(-15, -4, -3), Vec3(15, 4, 9), 0.5), dir / "two.stl");
  const Exec r = apptest::coilsim({"case", "new", (dir / "two.stl").string(), "--out", (dir / "case.json").string()}, dir);
  EXPECT_EQ(r.code, 2);
  EXPECT_CONTAINS(r.err, "2 candidate sacs");
  EXPECT_CONTAINS(r.err, "--sac-point");
  EXPECT_FALSE(fs::exists(dir / "case.json"));
  const Exec chosen = apptest::coilsim({"case", "new", (dir / "two.stl").string(), "--out", (dir / "case.json").string(),
                               "--sac-point", "-6,0,5"},
                              dir);
  ASSERT_EQ(chosen.code, 0) << chosen.err;
  EXPECT_LT(vec(readJson(dir / "case.json")["sac"]["neck_plane"]["point_mm"]).x(), -4);
}

// An open surface and an inside-out one are refused with the reason.
TEST(CaseNew, OpenAndInsideOutSurfacesAreRefused) {
  const fs::path dir = scratch("case_refused");
  const geometry::Field ball = [](const Vec3& p) { return p.norm() - 4; };
  ::coilsim::TriangleMesh m = geometry::polygonise(ball, Vec3::Constant(-5), Vec3::Constant(5), 0.5);
  ::coilsim::TriangleMesh open = m;
  open.triangles.pop_back();
  writeSurface(open, dir / "open.stl");
  for (auto& t : m.triangles) std::swap(t[1], t[2]);
  writeSurface(m, dir / "inside-out.stl");
  const Exec o = apptest::coilsim({"case", "new", (dir / "open.stl").string(), "--out", (dir / "a.json").string()}, dir);
  EXPECT_EQ(o.code, 2);
  EXPECT_CONTAINS(o.err, "open.stl");
  EXPECT_CONTAINS(o.err, "boundary");
  const Exec i = apptest::coilsim({"case", "new", (dir / "inside-out.stl").string(), "--out", (dir / "b.json").string()}, dir);
  EXPECT_EQ(i.code, 2);
  EXPECT_CONTAINS(i.err, "inside-out");
  const Exec bad = apptest::coilsim({"case", "new", (dir / "open.stl").string(), "--out", (dir / "c.json").string(),
                            "--sac-point", "1,2"},
                           dir);
  EXPECT_EQ(bad.code, 2);
  EXPECT_CONTAINS(bad.err, "--sac-point needs three numbers");
}

}  // namespace

namespace {

// case edit moves the neck plane of a made case along its normal and saves
// it: the saved plane is that far from the old one, the rest of the case
// unchanged, and plan reads it.
TEST(CaseEdit, NeckShiftIsSavedAndTheRestKept) {
  const fs::path dir = scratch("case_edit");
  const std::string stl = (fs::path(kSource) / "assets" / "meshes" / "sidewall-7mm.stl").string();
  ASSERT_EQ(apptest::coilsim({"case", "new", stl, "--out", (dir / "case.json").string()}, dir).code, 0);
  const Exec r = apptest::coilsim({"case", "edit", (dir / "case.json").string(), "--neck-shift", "0.5", "--out",
                                   (dir / "edited.json").string()},
                                  dir);
  ASSERT_EQ(r.code, 0) << r.err;
  nlohmann::json before = readJson(dir / "case.json"), after = readJson(dir / "edited.json");
  const Vec3 n = vec(before["sac"]["neck_plane"]["normal"]).normalized();
  EXPECT_NEAR((vec(after["sac"]["neck_plane"]["point_mm"]) - vec(before["sac"]["neck_plane"]["point_mm"])).dot(n), 0.5, 1e-3);
  EXPECT_LT(after["morphology"]["sac_volume_mm3"].get<double>(), before["morphology"]["sac_volume_mm3"].get<double>());
  for (const char* key : {"sac", "morphology"}) before.erase(key), after.erase(key);
  EXPECT_EQ(before, after);
  EXPECT_NO_THROW(::coilsim::planning::loadCase((dir / "edited.json").string()));
  // Past the dome (no sac left) and below the ostium (the plane cuts the parent vessel, no opening): refused,
  // and nothing written; beyond the option's range, a usage error.
  for (const char* shift : {"12", "-8"}) {
    const Exec refused = apptest::coilsim({"case", "edit", (dir / "case.json").string(), "--neck-shift", shift,
                                           "--out", (dir / "never.json").string()},
                                          dir);
    EXPECT_EQ(refused.code, 2) << shift;
    EXPECT_CONTAINS(refused.err, "refused");
    EXPECT_FALSE(fs::exists(dir / "never.json"));
  }
  const Exec range = apptest::coilsim({"case", "edit", (dir / "case.json").string(), "--neck-shift", "40", "--out",
                                       (dir / "never.json").string()},
                                      dir);
  EXPECT_EQ(range.code, 2);
  EXPECT_CONTAINS(range.err, "--neck-shift needs a number in [-20, 20]");
}

// Case edit's usage errors: without --out it needs the window; a picture
// path that cannot be written is named (exit 2), whatever the build. The
// window and the picture themselves: case_window_test.cpp (a build with the
// ui layer) and graphics_none_test.cpp (one without).
TEST(CaseEdit, UsageErrorsBeforeAnyWindow) {
  const fs::path dir = scratch("case_edit_window");
  const std::string stl = (fs::path(kSource) / "assets" / "meshes" / "sidewall-7mm.stl").string();
  const std::string file = (dir / "case.json").string();
  ASSERT_EQ(apptest::coilsim({"case", "new", stl, "--out", file}, dir).code, 0);
  const Exec bare = apptest::coilsim({"case", "edit", file}, dir);
  EXPECT_EQ(bare.code, 2);
  EXPECT_CONTAINS(bare.err, "needs --out NEW.json (or --window)");
  const Exec unwritable =
      apptest::coilsim({"case", "edit", file, "--screenshot", (dir / "no" / "such" / "dir" / "x.png").string()}, dir);
  EXPECT_EQ(unwritable.code, 2);
  EXPECT_CONTAINS(unwritable.err, "x.png");
}

}  // namespace
