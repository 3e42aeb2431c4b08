// The validation panel off-screen, as `coilsim validate FILE --screenshot`
// drives it: scripted clicks on the effect toggles reach the fit callback,
// the fit runs on its own thread and its result (not the base model's) is
// what the 3D view then shows; bad scripts and failed fits are reported.
// The data are made here (two stages, a straight coil): the panel only
// displays what the app hands it, and the app's end-to-end run is in
// tests/app/validate_cmd_test.cpp.
#include <gtest/gtest.h>

#include <mutex>

#include "golden.h"
#include "ui/validation_panel.h"

namespace coilsim::ui {
namespace {

// A straight 20 mm coil along x in one colour (lit, so only its hue is kept).
DrawData straightCoil(const Colour& c) {
  DrawData d;
  DrawTube t;
  t.radius = 0.4e-3;
  for (int i = 0; i <= 10; ++i) t.centre.push_back(Vec3(2e-3 * i, 0, 0));
  t.colours.assign(t.centre.size(), c);
  d.tubes.push_back(t);
  return d;
}

ValidationView viewOf(const Colour& c, float error) {
  ValidationView v;
  for (const char* name : {"stage 1", "stage 2"}) {
    ValidationStageRow r;
    r.name = name;
    r.deployedMm = 20;
    r.ok = true;
    r.stageError = error;
    r.arcMm = {0, 10, 20};
    r.errorMm = {0, error, 2 * error};
    r.noiseFloorMm = 0.1f;
    v.stages.push_back(r);
    v.scenes.push_back(straightCoil(c));
  }
  return v;
}

struct Recorder {
  std::mutex mutex;
  std::vector<std::vector<std::string>> calls;
};

ValidationHooks hooks(Recorder& rec, bool fitOk = true) {
  ValidationHooks h;
  h.title = "synthetic";
  h.effects = {"buoyancy", "drag", "gravity_tilt"};
  h.initiallyOn = {"buoyancy"};
  h.before = viewOf(Colour(0, 1, 0, 1), 0.5f);  // the base model: green
  h.fit = [&rec, fitOk](const std::vector<std::string>& effects, const FitProgress& progress,
                        const std::function<bool()>&) {
    {
      std::lock_guard<std::mutex> lock(rec.mutex);
      rec.calls.push_back(effects);
    }
    for (int k = 1; k <= 5; ++k) progress(k, 0.5 / k);
    ValidationView v = viewOf(Colour(1, 0, 0, 1), 0.1f);  // the fitted model: red
    v.ok = fitOk;
    if (!fitOk) v.message = "no simulation succeeded";
    v.fitted = {"young_modulus = 5.6 +- 0.1 GPa"};
    return v;
  };
  return h;
}

ValidationWindowOptions options(const std::string& name) {
  ValidationWindowOptions o;
  o.width = 900;
  o.height = 560;
  o.screenshotPath = testing::outputDir() + "/" + name + ".png";
  return o;
}

// Pixels right of the panel (x >= 420) whose hue is clearly red or green.
struct Hues {
  long red = 0, green = 0;
};
Hues huesOf(const std::string& path) {
  render::Image image;
  std::string error;
  EXPECT_TRUE(render::readPng(path, image, error)) << error;
  Hues h;
  for (int y = 0; y < image.height; ++y)
    for (int x = 420; x < image.width; ++x) {
      const std::uint8_t* p = image.at(x, y);
      if (p[0] > 90 && p[0] > 2 * p[1] && p[0] > 2 * p[2]) ++h.red;
      if (p[1] > 90 && p[1] > 2 * p[0] && p[1] > 2 * p[2]) ++h.green;
    }
  return h;
}

TEST(ValidationPanel, ToggledEffectsReachTheFitAndItsResultIsShown) {
  Recorder rec;
  ValidationWindowOptions o = options("validation_panel_fit");
  o.toggle = {"buoyancy", "drag"};  // buoyancy was on: a click turns it off
  o.autoFit = true;
  std::string error;
  ASSERT_TRUE(renderValidationOffscreen(hooks(rec), o, error)) << error;
  ASSERT_EQ(rec.calls.size(), 1u);
  EXPECT_EQ(rec.calls[0], std::vector<std::string>{"drag"});
  const Hues h = huesOf(o.screenshotPath);
  EXPECT_GT(h.red, 300) << "the fitted coil (red) is not in the 3D view";
  EXPECT_EQ(h.green, 0) << "the base model (green) is still shown after the fit";
}

TEST(ValidationPanel, WithoutFitTheBaseModelIsShown) {
  Recorder rec;
  const ValidationWindowOptions o = options("validation_panel_before");
  std::string error;
  ASSERT_TRUE(renderValidationOffscreen(hooks(rec), o, error)) << error;
  EXPECT_TRUE(rec.calls.empty());
  const Hues h = huesOf(o.screenshotPath);
  EXPECT_GT(h.green, 300);
  EXPECT_EQ(h.red, 0);
}

// The charts' axes (ticks with values, labels with units) and the legend of
// the error colour scale the app hands over (golden: the panel's layout).
TEST(ValidationPanel, ChartsHaveTicksAndUnitsAndTheColourScaleItsLegend) {
  Recorder rec;
  ValidationHooks h = hooks(rec);
  h.errorScale.legend = "node error: fixed log scale, blue <= 0.01 mm, red >= 1 mm";
  for (int i = 0; i < 8; ++i) h.errorScale.colours.emplace_back(i / 7.0f, 0.3f, 1 - i / 7.0f, 1.0f);
  h.errorScale.ticks = {{0.0f, "0.01"}, {0.5f, "0.1"}, {1.0f, "1 mm"}};
  ValidationWindowOptions o = options("validation_panel_axes");
  o.width = 760;
  o.height = 720;
  std::string error;
  ASSERT_TRUE(renderValidationOffscreen(h, o, error)) << error;
  render::Image image;
  ASSERT_TRUE(render::readPng(o.screenshotPath, image, error)) << error;
  EXPECT_TRUE(testing::matchesGolden(image, "validation_panel_axes"));
}

TEST(ValidationPanel, UnknownToggleAndFailedFitAreReported) {
  Recorder rec;
  ValidationWindowOptions o = options("validation_panel_bad");
  o.toggle = {"wind"};
  std::string error;
  EXPECT_FALSE(renderValidationOffscreen(hooks(rec), o, error));
  EXPECT_NE(error.find("'wind'"), std::string::npos) << error;
  o.toggle = {};
  o.autoFit = true;
  error.clear();
  EXPECT_FALSE(renderValidationOffscreen(hooks(rec, false), o, error));
  EXPECT_NE(error.find("no simulation succeeded"), std::string::npos) << error;
}

}  // namespace
}  // namespace coilsim::ui
