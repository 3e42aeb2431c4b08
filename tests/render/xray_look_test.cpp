// The X-ray greys a legend shows against the greys the renderer draws: each
// kind of matter alone, drawn off-screen (OSMesa) large enough that the
// composite's 3x3 blur is a rim, and the mean grey over where it is seen
// (the drawn image over the empty one, times I0: the vignette cancels, the
// grain is off) must be the grey xrayGreys gives it, within 0.03 (8 of 255
// levels: the renderer's tube is a 16-sided prism, not a cylinder, and the
// darkest greys are few levels).
#include "render/xray_look.h"

#include <gtest/gtest.h>

#include <memory>

#include "physics/state.h"
#include "render/backend.h"
#include "render/geometry.h"
#include "render/renderer.h"
#include "scenes.h"

namespace coilsim::render {
namespace {

constexpr int kWidth = 480, kHeight = 360;

class XRayLook : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    std::string error;
    BackendOptions o;
    o.width = kWidth, o.height = kHeight;
    backend = createBackend("osmesa", o, error).release();
    ASSERT_NE(backend, nullptr) << error;
    renderer = new Renderer;
    ASSERT_TRUE(renderer->init(error)) << error;
  }
  static void TearDownTestSuite() {
    delete renderer;
    delete backend;
    renderer = nullptr, backend = nullptr;
  }

  Image draw(const DrawData& data, const Camera& camera, const RenderSettings& s) {
    std::string error;
    EXPECT_TRUE(renderer->render(data, camera, s, kWidth, kHeight, error)) << error;
    Image image;
    EXPECT_TRUE(renderer->readFrame(image));
    return image;
  }

  // The mean grey of `data` where it darkens the empty picture, and how many pixels that is.
  std::pair<double, int> drawnGrey(const DrawData& data, const Camera& camera, const RenderSettings& s) {
    const Image with = draw(data, camera, s), without = draw(DrawData{}, camera, s);
    double sum = 0;
    int n = 0;
    for (int y = 0; y < kHeight; ++y)
      for (int x = 0; x < kWidth; ++x) {
        const double a = with.at(x, y)[0], b = without.at(x, y)[0];
        if (b - a < 3) continue;
        sum += s.xray.brightness * a / b;
        ++n;
      }
    return {n ? sum / n : -1.0, n};
  }

  static Backend* backend;
  static Renderer* renderer;
};

Backend* XRayLook::backend = nullptr;
Renderer* XRayLook::renderer = nullptr;

RenderSettings xraySettings() {
  RenderSettings s;
  s.mode = ViewMode::XRay;
  s.xray.noise = 0;
  s.xray.resolutionScale = 1;
  return s;
}

// A straight tube along x, from `from` to `to` (m).
DrawData tube(RodRole role, double radius, double from, double to) {
  DrawTube t;
  t.role = role;
  t.radius = radius;
  for (int i = 0; i <= 8; ++i) t.centre.emplace_back(from + (to - from) * i / 8.0, 0, 0);
  t.frames.assign(t.centre.size(), Quat::Identity());
  t.colours.assign(t.centre.size(), Colour(1, 1, 1, 1));
  DrawData d;
  d.tubes.push_back(t);
  return d;
}

Camera fitted(const DrawData& d) {
  Camera c = apView(Camera{});
  fitCamera(c, boundsOf(d), ViewMode::XRay, kWidth, kHeight);
  return c;
}

TEST_F(XRayLook, CoilAndCatheterSwatchesAreTheirDrawnGrey) {
  const RenderSettings s = xraySettings();
  for (const auto& [role, radius] : {std::pair{RodRole::Coil, 0.15e-3}, std::pair{RodRole::Catheter, 0.35e-3},
                                     std::pair{RodRole::Wire, 0.1e-3}}) {
    // Drawn 20 mm long, seen 1 mm of it: the rounded ends are out of the
    // picture, and the tube is over a hundred pixels wide (the blur a rim).
    const DrawData d = tube(role, radius, -10e-3, 10e-3);
    const Camera c = fitted(tube(role, radius, 0, 1e-3));
    const XRayGreys g = xrayGreys(d, c, s.xray);
    const float want = role == RodRole::Coil ? g.coil : role == RodRole::Catheter ? g.catheter : g.wire;
    const auto [drawn, pixels] = drawnGrey(d, c, s);
    ASSERT_GT(pixels, 20000) << "role " << int(role);
    EXPECT_NEAR(want, drawn, 0.03) << "role " << int(role) << ", " << pixels << " pixels";
  }
}

TEST_F(XRayLook, VesselSwatchIsTheContrastFilledSacsDrawnGrey) {
  const Model m = testing::helixModel();
  const DrawData all = testing::helixDrawData(m, makeState(m));
  DrawData sac;
  for (const DrawMesh& mesh : all.meshes)
    if (mesh.name == "aneurysm") sac.meshes.push_back(mesh);
  ASSERT_EQ(sac.meshes.size(), 1u);
  const RenderSettings s = xraySettings();
  const Camera c = fitted(sac);
  const XRayGreys g = xrayGreys(sac, c, s.xray);
  const auto [drawn, pixels] = drawnGrey(sac, c, s);
  ASSERT_GT(pixels, 20000);
  EXPECT_NEAR(g.vessel, drawn, 0.03);
  // The outline is darker than the filled sac; a sphere's mean chord is 4/3 of its radius.
  EXPECT_LT(g.vesselEdge, g.vessel);
  EXPECT_NEAR(g.vessel, s.xray.brightness * std::exp(-s.xray.muContrast * 4.0 / 3.0 * 0.0045), 0.005);
}

// What the scene does not hold has no grey; an open disc (a neck plane) holds no contrast.
TEST_F(XRayLook, AbsentMatterAndOpenMeshesHaveNoGrey) {
  DrawData d = tube(RodRole::Coil, 0.15e-3, 0, 1e-3);
  DrawMesh disc;
  disc.vertices = {Vec3(0, 0, 0), Vec3(1e-3, 0, 0), Vec3(0, 0, 1e-3), Vec3(-1e-3, 0, 0)};
  disc.triangles = {{0, 1, 2}, {0, 2, 3}};
  d.meshes.push_back(disc);
  const XRayGreys g = xrayGreys(d, fitted(d), XRaySettings{});
  EXPECT_GT(g.coil, 0.0f);
  EXPECT_EQ(g.catheter, -1.0f);
  EXPECT_EQ(g.wire, -1.0f);
  EXPECT_EQ(g.vessel, -1.0f);
}

}  // namespace
}  // namespace coilsim::render
