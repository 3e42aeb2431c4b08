// Screenshot regression of the renderer: small inline scenes drawn
// off-screen (OSMesa) in each view and compared with golden PNGs.
#include <gtest/gtest.h>

#include <memory>

#include "golden.h"
#include "physics/state.h"
#include "render/backend.h"
#include "render/renderer.h"
#include "scenes.h"

namespace coilsim {
namespace {

constexpr int kWidth = 320, kHeight = 240;

class RendererTest : public ::testing::Test {
 protected:
  // One context and renderer for the suite keeps it fast (llvmpipe start-up).
  static void SetUpTestSuite() {
    std::string error;
    render::BackendOptions o;
    o.width = kWidth;
    o.height = kHeight;
    backend = render::createBackend("osmesa", o, error).release();
    ASSERT_NE(backend, nullptr) << error;
    renderer = new render::Renderer;
    ASSERT_TRUE(renderer->init(error)) << error;
  }
  static void TearDownTestSuite() {
    delete renderer;
    delete backend;
    renderer = nullptr;
    backend = nullptr;
  }

  render::Image draw(const DrawData& data, const std::string& view) {
    render::RenderSettings s;
    s.mode = *render::parseViewMode(view);
    render::Camera camera;
    if (s.mode != render::ViewMode::Shaded) camera = render::apView(camera);
    render::fitCamera(camera, render::boundsOf(data), s.mode, kWidth, kHeight);
    std::string error;
    EXPECT_TRUE(renderer->render(data, camera, s, kWidth, kHeight, error)) << error;
    render::Image image;
    EXPECT_TRUE(renderer->readFrame(image));
    return image;
  }

  static render::Backend* backend;
  static render::Renderer* renderer;
};

render::Backend* RendererTest::backend = nullptr;
render::Renderer* RendererTest::renderer = nullptr;

TEST_F(RendererTest, StraightRod3d) {
  const Model m = testing::straightRodModel();
  const State s = makeState(m);
  EXPECT_TRUE(testing::matchesGolden(draw(testing::rodDrawData(m, s), "3d"), "rod_3d"));
}

TEST_F(RendererTest, StraightRodXRay) {
  const Model m = testing::straightRodModel();
  const State s = makeState(m);
  EXPECT_TRUE(testing::matchesGolden(draw(testing::rodDrawData(m, s), "xray"), "rod_xray"));
}

TEST_F(RendererTest, Helix3d) {
  const Model m = testing::helixModel();
  const State s = makeState(m);
  EXPECT_TRUE(testing::matchesGolden(draw(testing::helixDrawData(m, s), "3d"), "helix_3d"));
}

TEST_F(RendererTest, HelixXRay) {
  const Model m = testing::helixModel();
  const State s = makeState(m);
  EXPECT_TRUE(testing::matchesGolden(draw(testing::helixDrawData(m, s), "xray"), "helix_xray"));
}

TEST_F(RendererTest, HelixBiplane) {
  const Model m = testing::helixModel();
  const State s = makeState(m);
  EXPECT_TRUE(testing::matchesGolden(draw(testing::helixDrawData(m, s), "biplane"), "helix_biplane"));
}

}  // namespace
}  // namespace coilsim
