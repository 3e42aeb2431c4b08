// What the plain window gets from the app: the sac of a scene's phantom
// (its sidecar's neck plane, moved as the scene moves the mesh) for the
// live read-outs, and the panel's coil and catheter choice, which loads
// every catalogue coil and every tip shape into the default scene.
// (A test of the graphics file set: tests/app/CMakeLists.txt compiles it
// only with the ui layer.)
#include "app/window_setup.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include <nlohmann/json.hpp>

#include "io/scene.h"
#include "physics/deployment.h"

namespace coilsim::app {
namespace {

const std::string kRoot = COILSIM_SOURCE_DIR;

// The sidecar's neck plane as written by `coilsim phantom`, read here with plain JSON.
Vec3 sidecarNeckPointMm(const std::string& path) {
  std::ifstream in(path);
  const nlohmann::json j = nlohmann::json::parse(in);
  const auto& p = j.at("neck").at("point_mm");
  return Vec3(p[0].get<double>(), p[1].get<double>(), p[2].get<double>());
}

TEST(WindowSetup, SceneSacIsThePhantomsNeckMovedWithTheMesh) {
  io::SceneSpec scene = io::loadScene(kRoot + "/scenes/default.json");
  std::string note;
  const auto sac = planning::sceneSac(scene, note);
  ASSERT_TRUE(sac) << note;
  const Vec3 neck = sidecarNeckPointMm(kRoot + "/assets/meshes/sidewall-7mm.phantom.json");
  EXPECT_LT((sac->neck.point - 1e-3 * neck).norm(), 1e-12);
  // The scene's description says: neck plane z = 2 mm, sac centre (0, 0, 5.03) mm, so inside.
  EXPECT_TRUE(planning::insideSurface(*sac, Vec3(0, 0, 5.03e-3)));
  EXPECT_GT(sac->neck.signedDistance(Vec3(0, 0, 5.03e-3)), 0);

  // Moved 10 mm along x: the neck and the surface move with it.
  scene.obstacles[0].offsetMm = Vec3(10, 0, 0);
  const auto moved = planning::sceneSac(scene, note);
  ASSERT_TRUE(moved) << note;
  EXPECT_LT((moved->neck.point - 1e-3 * (neck + Vec3(10, 0, 0))).norm(), 1e-12);
  EXPECT_TRUE(planning::insideSurface(*moved, Vec3(10e-3, 0, 5.03e-3)));
  EXPECT_FALSE(planning::insideSurface(*moved, Vec3(0, 0, 5.03e-3)));

  // Rotated: the sidecar no longer says where the neck is; no read-outs rather than wrong ones.
  scene.obstacles[0].rotationDeg = Vec3(0, 0, 90);
  EXPECT_FALSE(planning::sceneSac(scene, note));
  EXPECT_NE(note.find("rotated"), std::string::npos) << note;
  scene.obstacles.clear();
  EXPECT_FALSE(planning::sceneSac(scene, note));
}

TEST(WindowSetup, EveryCatalogueCoilAndTipShapeLoadsIntoTheDefaultScene) {
  const io::SceneSpec scene = io::loadScene(kRoot + "/scenes/default.json");
  std::string note;
  ui::SetupChoices choices = sceneSetupChoices(scene, planning::sceneSac(scene, note));
  const std::vector<io::CoilSpec> catalogue = io::loadCatalogue(kRoot + "/assets/coils");
  ASSERT_EQ(choices.coils.size(), catalogue.size());
  for (size_t i = 0; i < catalogue.size(); ++i) {
    // The label says shape, loop diameter, length and stiffness as the coil file does.
    EXPECT_NE(choices.coils[i].find(std::string(io::shapeName(catalogue[i].shape))), std::string::npos);
    const ui::SceneSetup s = choices.build(int(i), 0);
    ASSERT_TRUE(s.model.device);
    EXPECT_NEAR(s.model.device->coilLength, catalogue[i].lengthMm * 1e-3, 1e-12) << catalogue[i].name;
    EXPECT_TRUE(s.readouts) << "the default scene's phantom gives read-outs";
  }
  // Tip shapes: the rest angle between the held base and the tip is the shape's bend
  // (0 for straight and for an S, whose two bends cancel).
  const double expectedDeg[] = {0, 0, 0, 45, 90, 180, 0};
  ASSERT_EQ(choices.catheters.size(), std::size(expectedDeg));
  for (size_t k = 0; k < choices.catheters.size(); ++k) {
    const ui::SceneSetup s = choices.build(-1, int(k));
    const Deployment& dep = *s.model.device;
    EXPECT_EQ(dep.flexible(), k >= 2) << choices.catheters[k];
    const CatheterTip tip = catheterTip(s.model, s.state);
    EXPECT_NEAR(tip.restAngle * 180 / M_PI, expectedDeg[k], 1e-6) << choices.catheters[k];
    if (!dep.flexible()) continue;
    // The body keeps the scene's approach: the held base runs along the scene's
    // (straight) catheter direction, so it stays in the parent vessel.
    const std::vector<Vec3>& x = s.state.rods[size_t(dep.chainRod)].x;
    const Vec3 approach = scene.deployment->catheter.direction.normalized();
    EXPECT_GT((x[1] - x[0]).normalized().dot(approach), 1 - 1e-9) << choices.catheters[k];
  }
}

}  // namespace
}  // namespace coilsim::app
