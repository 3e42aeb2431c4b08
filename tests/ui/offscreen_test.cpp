// renderOffscreen, as the CLI calls it: the frame with the ImGui panel
// (golden), and clear errors for a bad path or view.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "coil_pixels.h"
#include "golden.h"
#include "physics/state.h"
#include "render/camera.h"
#include "render/xray_look.h"
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

// The rectangle the layout dump gives `name` ([x0, y0, x1, y1]); empty if none.
std::vector<float> rectOf(const std::string& dump, const std::string& name) {
  const size_t at = dump.find("\"" + name + "\": [");
  if (at == std::string::npos) return {};
  std::vector<float> r(4);
  std::sscanf(dump.c_str() + dump.find('[', at), "[%f, %f, %f, %f]", &r[0], &r[1], &r[2], &r[3]);
  return r;
}

// In the X-ray view a legend entry that names its matter shows the grey the
// renderer draws that matter in (render::xrayGreys, checked against drawn
// pixels in tests/render/xray_look_test.cpp), not its 3D colour; an entry
// without a matter keeps its colour (golden: the swatches and the picture).
TEST(RenderOffscreen, XrayLegendSwatchesAreTheGreysOfTheDrawnMatter) {
  const Model m = testing::helixModel();
  const State s = makeState(m);
  ViewerOptions o = helixOptions("xray", "offscreen_xray_legend");
  o.drawPanel = false;
  o.width = 480;
  o.height = 300;
  o.legend = {{Colour(0.85f, 0.82f, 0.75f, 1), "coil", LegendMatter::Coil},
              {Colour(0.3f, 0.5f, 0.9f, 1), "microcatheter", LegendMatter::Catheter},
              {Colour(0.85f, 0.32f, 0.30f, 0.3f), "sac and parent vessel", LegendMatter::Vessel},
              {Colour(0.25f, 0.85f, 1.0f, 0.3f), "neck plane", LegendMatter::VesselOutline},
              {Colour(1.0f, 0.85f, 0.1f, 1), "a marker (no matter: its colour)"}};
  const std::string dump = testing::outputDir() + "/offscreen_xray_legend.layout.json";
  ::setenv("COILSIM_LAYOUT_DUMP", dump.c_str(), 1);
  std::string error;
  const bool ok = renderOffscreen(m, s, o, error);
  ::unsetenv("COILSIM_LAYOUT_DUMP");
  ASSERT_TRUE(ok) << error;
  const render::Image image = load(o.screenshotPath);
  std::FILE* f = std::fopen(dump.c_str(), "rb");
  ASSERT_NE(f, nullptr) << dump;
  std::string text(1 << 16, '\0');
  text.resize(std::fread(text.data(), 1, text.size(), f));
  std::fclose(f);
  // The greys for the view's direction (AP: the vessel's mean chord depends on it).
  const render::XRayGreys g = render::xrayGreys(testing::helixDrawData(m, s), render::apView(render::Camera{}),
                                                render::XRaySettings{});
  const float want[] = {g.coil, g.catheter, g.vessel};
  for (int i = 0; i < 3; ++i) {
    const std::vector<float> r = rectOf(text, "legend_grey_" + std::to_string(i));
    ASSERT_EQ(r.size(), 4u) << i << ": " << text;
    const std::uint8_t* p = image.at(int(0.5f * (r[0] + r[2])), int(0.5f * (r[1] + r[3])));
    EXPECT_NEAR(p[0], 255 * want[i], 2.0) << "entry " << i;
    EXPECT_TRUE(p[0] == p[1] && p[1] == p[2]) << "entry " << i << " is grey";
  }
  EXPECT_LT(g.coil, g.catheter);  // platinum is darker than the catheter
  // The neck plane: the vessel's grey crossed by the outline's, darker.
  const std::vector<float> r = rectOf(text, "legend_grey_3");
  ASSERT_EQ(r.size(), 4u);
  const std::uint8_t* mid = image.at(int(0.5f * (r[0] + r[2])), int(0.5f * (r[1] + r[3])));
  EXPECT_NEAR(mid[0], 255 * g.vesselEdge, 2.0);
  // The marker keeps its yellow.
  const std::vector<float> y = rectOf(text, "legend_swatch_4");
  ASSERT_EQ(y.size(), 4u);
  const std::uint8_t* q = image.at(int(0.5f * (y[0] + y[2])), int(0.5f * (y[1] + y[3])));
  EXPECT_TRUE(q[0] > 230 && q[1] > 190 && q[2] < 60) << int(q[0]) << " " << int(q[1]) << " " << int(q[2]);
  EXPECT_TRUE(testing::matchesGolden(image, "offscreen_xray_legend"));
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
