// The case editor's model, driven as the window drives it: the neck plane
// dragged, the tip moved, the case saved. The volume after a drag is checked
// against geometry::volumeAbovePlane (a separate computation: the whole
// solid above the plane, which on a sidewall phantom is the sac alone once
// the plane is above the vessel's top).
#include "planning/case_editor.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <unistd.h>

#include "geometry/phantom.h"
#include "geometry/volume.h"
#include "io/json_writer.h"
#include "io/mesh_file.h"
#include "planning/case_file.h"

namespace coilsim::planning {
namespace {

namespace fs = std::filesystem;

fs::path madeCase(const std::string& name) {
  const fs::path dir = fs::path(testing::TempDir()) / ("coilsim_case_editor_" + name + "." + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  geometry::PhantomSpec spec;
  spec.sacDiameter = 7, spec.neckWidth = 3.5, spec.resolution = 0.5;
  io::writeBinaryStl(geometry::makePhantom(spec).mesh, (dir / "sidewall.stl").string());
  CaseRequest r;
  r.surface = (dir / "sidewall.stl").string();
  r.out = (dir / "case.json").string();
  const MadeCase c = makeCase(r);
  io::writeFileAtomic(r.out, io::formatJson(c.document));
  return dir;
}

TEST(CaseEditor, DraggingTheNeckUpdatesTheMorphologyAndTheSavedCase) {
  const fs::path dir = madeCase("drag");
  CaseEditor e((dir / "case.json").string());
  const geometry::Plane before = e.neck();
  const double v0 = e.morphology().volume;
  EXPECT_NEAR(v0, geometry::volumeAbovePlane(e.surface(), before), 1e-9 * v0);
  ASSERT_TRUE(e.moveNeck(0.8));
  const geometry::Plane after = e.neck();
  EXPECT_NEAR((after.point - before.point).dot(before.normal), 0.8, 1e-12);
  EXPECT_NEAR(e.morphology().volume, geometry::volumeAbovePlane(e.surface(), after), 1e-9 * v0);
  EXPECT_LT(e.morphology().volume, v0);
  EXPECT_NEAR(e.morphology().domeHeight + 0.8,
              geometry::measureSac(e.surface(), before, e.sacCentre(), 0).domeHeight, 1e-9);
  ASSERT_TRUE(e.placeTip(e.catheter().tip + 0.5 * after.normal));
  e.save((dir / "edited.json").string());

  const PracticeCase reread = loadCase((dir / "edited.json").string());  // plan and practice read it
  EXPECT_NEAR(1e3 * reread.sac.neck.point.dot(before.normal) - before.point.dot(before.normal), 0.8, 1e-3);
  std::ifstream in(dir / "edited.json");
  const nlohmann::json saved = nlohmann::json::parse(in);
  EXPECT_NEAR(saved["morphology"]["sac_volume_mm3"].get<double>(), e.morphology().volume, 1e-3);
}

TEST(CaseEditor, RefusesANeckBeyondTheSacAndATipOutside) {
  const fs::path dir = madeCase("refuse");
  CaseEditor e((dir / "case.json").string());
  const geometry::Plane before = e.neck();
  EXPECT_FALSE(e.moveNeck(50));  // past the dome: no sac left
  EXPECT_NE(e.refusal().find("sac centre"), std::string::npos) << e.refusal();
  EXPECT_FALSE(e.moveNeck(-6));  // below the ostium: through the parent vessel
  EXPECT_NE(e.refusal().find("parent vessel"), std::string::npos) << e.refusal();
  EXPECT_FALSE(e.placeTip(Vec3(100, 100, 100)));
  EXPECT_NE(e.refusal().find("inside the vessel"), std::string::npos) << e.refusal();
  EXPECT_FALSE(e.edited());
  EXPECT_EQ(e.neck().point, before.point);
  ASSERT_TRUE(e.moveNeck(0.2));  // an accepted edit clears the reason
  EXPECT_TRUE(e.refusal().empty());
}

TEST(CaseEditor, SavingMarksTheEditsSaved) {
  const fs::path dir = madeCase("saved");
  CaseEditor e((dir / "case.json").string());
  ASSERT_TRUE(e.moveNeck(0.3));
  EXPECT_TRUE(e.edited());
  e.save((dir / "edited.json").string());
  e.markSaved();
  EXPECT_FALSE(e.edited());
  ASSERT_TRUE(e.moveNeck(-0.3));
  EXPECT_TRUE(e.edited());
}

TEST(CaseEditor, AShippedSphereCaseIsRefusedNamingTheFile) {
  const std::string file = std::string(COILSIM_SOURCE_DIR) + "/scenes/cases/sphere-7mm-wide-neck.json";
  try {
    CaseEditor e(file);
    FAIL() << "a sphere sac has no surface file to edit";
  } catch (const io::InputError& err) {
    EXPECT_NE(std::string(err.what()).find("sphere-7mm-wide-neck.json"), std::string::npos) << err.what();
    EXPECT_NE(std::string(err.what()).find("/sac"), std::string::npos) << err.what();
  }
}

}  // namespace
}  // namespace coilsim::planning
