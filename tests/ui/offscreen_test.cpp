// renderOffscreen, as the CLI calls it: the frame with the ImGui panel
// (golden), and clear errors for a bad path or view.
#include <gtest/gtest.h>

#include "coil_pixels.h"
#include "golden.h"
#include "physics/state.h"
#include "scenes.h"
#include "ui/viewer.h"

namespace coilsim::ui {
namespace {

ViewerOptions helixOptions(const std::string& view, const std::string& name) {
  ViewerOptions o;
  o.scenePath = "helix";
  o.view = view;
  o.width = 640;
  o.height = 400;
  o.screenshotPath = testing::outputDir() + "/" + name + ".png";
  o.addDrawData = testing::decorateHelix;
  return o;
}

render::Image load(const std::string& path) {
  render::Image image;
  std::string error;
  EXPECT_TRUE(render::readPng(path, image, error)) << error;
  return image;
}

TEST(RenderOffscreen, PanelOver3dView) {
  const Model m = testing::helixModel();
  const State s = makeState(m);
  const ViewerOptions o = helixOptions("3d", "offscreen_panel_3d");
  std::string error;
  ASSERT_TRUE(renderOffscreen(m, s, o, error)) << error;
  const render::Image image = load(o.screenshotPath);
  EXPECT_EQ(image.width, 640);
  EXPECT_EQ(image.height, 400);
  EXPECT_GT(testing::countCoilPixels(image, 400), 200);
  EXPECT_TRUE(testing::matchesGolden(image, "offscreen_panel_3d"));
}

TEST(RenderOffscreen, BiplaneLabelsWithoutPanel) {
  const Model m = testing::helixModel();
  const State s = makeState(m);
  ViewerOptions o = helixOptions("biplane", "offscreen_biplane");
  o.drawPanel = false;
  o.width = 480;  // X-ray grain does not compress: keep the golden small
  o.height = 300;
  std::string error;
  ASSERT_TRUE(renderOffscreen(m, s, o, error)) << error;
  EXPECT_TRUE(testing::matchesGolden(load(o.screenshotPath), "offscreen_biplane"));
}

// A picture without the panel (plan pictures) keeps its legend in the scene's
// lower left corner: swatches in the entries' colours, a text-only line.
TEST(RenderOffscreen, LegendInTheSceneCornerWithoutPanel) {
  const Model m = testing::helixModel();
  const State s = makeState(m);
  ViewerOptions o = helixOptions("3d", "offscreen_legend");
  o.drawPanel = false;
  o.width = 480;
  o.height = 300;
  o.legend = {{Colour(0.85f, 0.82f, 0.75f, 1), "coil"},
              {Colour(0.25f, 0.85f, 1.0f, 0.3f), "neck plane (the ostium)"},
              {Colour(0, 0, 0, 0), "a line without a swatch"}};
  std::string error;
  ASSERT_TRUE(renderOffscreen(m, s, o, error)) << error;
  const render::Image image = load(o.screenshotPath);
  // The neck swatch is drawn opaque (a translucent swatch would be hard to
  // read): some pixel in the legend's corner is that cyan.
  int cyan = 0;
  for (int y = image.height - 80; y < image.height; ++y)
    for (int x = 0; x < 60; ++x) {
      const std::uint8_t* p = image.at(x, y);
      cyan += p[0] < 90 && p[1] > 190 && p[2] > 230;
    }
  EXPECT_GT(cyan, 20);
  EXPECT_TRUE(testing::matchesGolden(image, "offscreen_legend"));
}

TEST(RenderOffscreen, UnwritablePathIsNamed) {
  const Model m = testing::straightRodModel();
  const State s = makeState(m);
  ViewerOptions o;
  o.width = 64;
  o.height = 48;
  o.screenshotPath = "/nonexistent-dir/shot.png";
  std::string error;
  EXPECT_FALSE(renderOffscreen(m, s, o, error));
  EXPECT_NE(error.find("/nonexistent-dir/shot.png"), std::string::npos) << error;
}

TEST(RenderOffscreen, UnknownViewAndBadSize) {
  const Model m = testing::straightRodModel();
  const State s = makeState(m);
  ViewerOptions o;
  o.screenshotPath = testing::outputDir() + "/never.png";
  o.view = "ct";
  std::string error;
  EXPECT_FALSE(renderOffscreen(m, s, o, error));
  EXPECT_NE(error.find("'ct'"), std::string::npos) << error;
  o.view = "3d";
  o.width = 0;
  EXPECT_FALSE(renderOffscreen(m, s, o, error));
  EXPECT_NE(error.find("0x720"), std::string::npos) << error;
}

}  // namespace
}  // namespace coilsim::ui
