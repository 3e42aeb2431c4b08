// The case editor's view off-screen (OSMesa), as `coilsim case edit CASE
// --screenshot` draws it: a case made from the sidewall phantom, the editor
// wired by the app, one frame compared with its golden; and the picture
// holds what the window promises, counted by colour: the sac in orange, the
// neck disc in cyan, the tip in yellow (the real window under Xvfb is
// tests/ui/case-editor-window-test).
#include <gtest/gtest.h>

#include <filesystem>

#include "app/case_window.h"
#include "golden.h"
#include "io/json_writer.h"
#include "planning/case_editor.h"
#include "planning/case_maker.h"
#include "ui/case_editor_window.h"

namespace coilsim::ui {
namespace {

namespace fs = std::filesystem;

// Pixels whose colour is clearly of one hue: red over blue (orange), blue and green over red (cyan), red and green
// over blue, both bright (yellow).
struct Hues {
  long orange = 0, cyan = 0, yellow = 0;
};

Hues countHues(const render::Image& image) {
  Hues h;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const std::uint8_t* p = image.at(x, y);
      const int r = p[0], g = p[1], b = p[2];
      if (r > 150 && g > 150 && b < 90) ++h.yellow;
      else if (r > b + 60 && r > g + 25) ++h.orange;
      else if (b > r + 50 && g > r + 40) ++h.cyan;
    }
  return h;
}

TEST(CaseEditorWindow, OffscreenViewOfASidewallCase) {
  const fs::path dir = fs::path(testing::outputDir()) / "case_editor";
  fs::create_directories(dir);
  planning::CaseRequest r;
  r.surface = std::string(COILSIM_SOURCE_DIR) + "/assets/meshes/sidewall-7mm.stl";
  r.out = (dir / "case.json").string();
  io::writeFileAtomic(r.out, io::formatJson(planning::makeCase(r).document));
  planning::CaseEditor editor(r.out);
  CaseEditorHooks hooks = app::caseEditorHooks(editor, r.out, r.out);
  EXPECT_TRUE(hooks.saveOverwrites);
  // The panel's header without the build directory, which differs from machine to machine.
  hooks.title = hooks.savePath = "sidewall-7mm-case.json";
  CaseEditorWindowOptions o;
  o.width = 960;
  o.height = 600;
  o.screenshotPath = (dir / "case_editor.png").string();
  std::string error;
  ASSERT_TRUE(renderCaseEditorOffscreen(hooks, o, error)) << error;
  render::Image image;
  ASSERT_TRUE(render::readPng(o.screenshotPath, image, error)) << error;
  EXPECT_EQ(image.width, 960);
  const Hues h = countHues(image);
  EXPECT_GT(h.orange, 2000) << "the sac";
  EXPECT_GT(h.cyan, 200) << "the neck disc";
  EXPECT_GT(h.yellow, 20) << "the catheter tip";
  EXPECT_TRUE(testing::matchesGolden(image, "case_editor"));
}

TEST(CaseEditorWindow, OffscreenWithoutAPathSaysSo) {
  CaseEditorHooks hooks;
  std::string error;
  EXPECT_FALSE(renderCaseEditorOffscreen(hooks, CaseEditorWindowOptions{}, error));
  EXPECT_NE(error.find("screenshot"), std::string::npos) << error;
}

}  // namespace
}  // namespace coilsim::ui
