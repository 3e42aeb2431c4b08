// coil-measurement/1: every field read in SI exactly as the format defines
// it (hand-converted values), and each kind of bad file named precisely.
#include "io/measurement.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <iterator>
#include <string>

#include "io/expect_error.h"
#include "io/scene.h"

namespace coilsim::io {
namespace {

using validation::Measurement;

// The format's own example, with a second, dynamic stage.
const std::string kGood = R"({
  "format": "coil-measurement/1",
  "name": "helix-water-box-A",
  "description": "free text",
  "extra_key_ignored": 1,
  "coil": {
    "length_mm": 150.0,
    "wire_radius_mm": 0.3556,
    "density_g_cm3": 21.45,
    "rest_shape": {"type": "helix", "loop_diameter_mm": 7.0, "pitch_mm": 0.96, "handedness": "left"},
    "young_modulus_gpa": 7.5,
    "poisson_ratio": 0.39
  },
  "setup": {
    "gravity_m_s2": [0.0, 0.0, -9.81],
    "medium": {"density_g_cm3": 1.0, "viscosity_pa_s": 0.001},
    "catheter_tip": {"position_mm": [1, 2, 3], "direction": [1, 0, 0], "reference_normal": [0, 0, 1]}
  },
  "stages": [
    {"name": "stage 1", "deployed_length_mm": 40.0, "twist_deg": 90.0, "point_sigma_mm": 0.1,
     "centerline_mm": [[0.0, 0.0, 0.0], [0.98, 0.05, 0.12]]},
    {"name": "stage 2", "deployed_length_mm": 60.0,
     "centerline_mm": [[0.0, 0.0, 0.0], [1, 0, 0], [2, 0, 0]],
     "push_history": [[0, 40, 0], [2, 60, 45]], "capture_time_s": 2.5}
  ]
})";

// `base` (kGood by default) with `from` replaced by `to` (which must occur).
std::string with(const std::string& from, const std::string& to, std::string s = kGood) {
  const size_t p = s.find(from);
  EXPECT_NE(p, std::string::npos) << from;
  if (p != std::string::npos) s.replace(p, from.size(), to);
  return s;
}

TEST(Measurement, ReadsEveryFieldInSI) {
  const Measurement m = parseMeasurement(kGood, "m.json");
  EXPECT_EQ(m.name, "helix-water-box-A");
  EXPECT_DOUBLE_EQ(m.coil.length, 0.150);
  EXPECT_DOUBLE_EQ(m.coil.wireRadius, 0.3556e-3);
  // mass per length = density * pi r^2 = 21450 kg/m3 * pi * (0.3556e-3 m)^2
  EXPECT_DOUBLE_EQ(m.coil.density, 21450);
  EXPECT_NEAR(massPerLength(m.coil), 21450 * M_PI * 0.3556e-3 * 0.3556e-3, 1e-15);
  EXPECT_EQ(m.coil.rest.type, RestShapeDef::Type::Helix);
  EXPECT_DOUBLE_EQ(m.coil.rest.loopDiameter, 7e-3);
  EXPECT_DOUBLE_EQ(m.coil.rest.pitch, 0.96e-3);
  EXPECT_FALSE(m.coil.rest.rightHanded);
  EXPECT_DOUBLE_EQ(m.coil.youngModulus, 7.5e9);
  EXPECT_DOUBLE_EQ(m.coil.poissonRatio, 0.39);
  EXPECT_EQ(m.gravity, Vec3(0, 0, -9.81));
  EXPECT_DOUBLE_EQ(m.mediumDensity, 1000.0);
  EXPECT_DOUBLE_EQ(m.mediumViscosity, 0.001);
  EXPECT_TRUE(m.tip.position.isApprox(Vec3(1e-3, 2e-3, 3e-3)));
  EXPECT_EQ(m.tip.direction, Vec3(1, 0, 0));
  EXPECT_EQ(m.tip.normal, Vec3(0, 0, 1));
  ASSERT_EQ(m.stages.size(), 2u);
  EXPECT_DOUBLE_EQ(m.stages[0].deployed, 0.040);
  EXPECT_DOUBLE_EQ(m.stages[0].twist, M_PI / 2);
  EXPECT_DOUBLE_EQ(m.stages[0].pointSigma, 1e-4);
  ASSERT_EQ(m.stages[0].centerline.size(), 2u);
  EXPECT_TRUE(m.stages[0].centerline[1].isApprox(Vec3(0.98e-3, 0.05e-3, 0.12e-3)));
  EXPECT_FALSE(m.stages[0].dynamic());
  // Defaults: twist 0, no sigma.
  EXPECT_EQ(m.stages[1].twist, 0.0);
  EXPECT_EQ(m.stages[1].pointSigma, 0.0);
  ASSERT_TRUE(m.stages[1].dynamic());
  EXPECT_DOUBLE_EQ(m.stages[1].pushHistory[1].deployed, 0.060);
  EXPECT_DOUBLE_EQ(m.stages[1].pushHistory[1].twist, M_PI / 4);
  EXPECT_DOUBLE_EQ(m.stages[1].captureTime, 2.5);
}

TEST(Measurement, AirWhenNoMediumAndMassInsteadOfDensity) {
  std::string s = with(R"("medium": {"density_g_cm3": 1.0, "viscosity_pa_s": 0.001},)", "");
  const size_t p = s.find(R"("density_g_cm3": 21.45)");
  s.replace(p, 22, R"("mass_g": 3.0)");
  const Measurement m = parseMeasurement(s, "m.json");
  EXPECT_DOUBLE_EQ(m.mediumDensity, 1.2);  // 0.0012 g/cm3
  EXPECT_DOUBLE_EQ(m.mediumViscosity, 1.8e-5);
  EXPECT_DOUBLE_EQ(massPerLength(m.coil), 3e-3 / 0.150);
}

TEST(Measurement, PolylineRestShapeFromTheDistalTip) {
  const std::string s = with(
      R"({"type": "helix", "loop_diameter_mm": 7.0, "pitch_mm": 0.96, "handedness": "left"})",
      R"({"type": "polyline", "points_mm": [[0,0,0],[100,0,0],[100,50,0]], "twist_deg_per_mm": 2})");
  const Measurement m = parseMeasurement(s, "m.json");
  ASSERT_EQ(m.coil.rest.type, RestShapeDef::Type::Polyline);
  // Held from the proximal end, as a deployment samples a coil's rest shape.
  ASSERT_EQ(m.coil.rest.points.size(), 3u);
  EXPECT_TRUE(m.coil.rest.points[0].isApprox(Vec3(0.1, 0.05, 0)));
  EXPECT_TRUE(m.coil.rest.points[1].isApprox(Vec3(0.1, 0, 0)));
  EXPECT_TRUE(m.coil.rest.points[2].isZero());
  EXPECT_NEAR(m.coil.rest.twistPerLength, 2 * M_PI / 180 * 1000, 1e-9);
  // 149 mm of polyline for a 150 mm coil is within 1 %; 140 mm is not.
  EXPECT_NO_THROW(parseMeasurement(with("[100,50,0]", "[100,49,0]", s), "m.json"));
  EXPECT_CONTAINS(errorOf([&] { parseMeasurement(with("[100,50,0]", "[100,40,0]", s), "m.json"); }),
                  "/coil/rest_shape/points_mm");
}

TEST(Measurement, PolylineRoundTripsInTheFileOrder) {
  const std::string s = with(
      R"({"type": "helix", "loop_diameter_mm": 7.0, "pitch_mm": 0.96, "handedness": "left"})",
      R"({"type": "polyline", "points_mm": [[0,0,0],[100,0,0],[100,50,0]], "twist_deg_per_mm": 2})");
  const std::string written = formatMeasurement(parseMeasurement(s, "m.json"));
  // The file's order (from the distal tip) is written back.
  const auto points = nlohmann::json::parse(written)["coil"]["rest_shape"]["points_mm"];
  ASSERT_EQ(points.size(), 3u);
  EXPECT_DOUBLE_EQ(points[0][0].get<double>(), 0.0);
  EXPECT_DOUBLE_EQ(points[2][1].get<double>(), 50.0);
}

TEST(Measurement, RoundTripsThroughTheWriter) {
  const Measurement a = parseMeasurement(kGood, "m.json");
  const Measurement b = parseMeasurement(formatMeasurement(a), "again.json");
  EXPECT_NEAR(massPerLength(b.coil), massPerLength(a.coil), 1e-12);
  EXPECT_EQ(b.coil.rest.rightHanded, a.coil.rest.rightHanded);
  ASSERT_EQ(b.stages.size(), a.stages.size());
  for (size_t i = 0; i < a.stages.size(); ++i) {
    EXPECT_DOUBLE_EQ(b.stages[i].deployed, a.stages[i].deployed);
    EXPECT_DOUBLE_EQ(b.stages[i].twist, a.stages[i].twist);
    EXPECT_EQ(b.stages[i].pushHistory.size(), a.stages[i].pushHistory.size());
    for (size_t k = 0; k < a.stages[i].centerline.size(); ++k)
      EXPECT_LT((b.stages[i].centerline[k] - a.stages[i].centerline[k]).norm(), 1e-8);
  }
}

struct BadCase {
  std::string from, to, path, expectation;
};

TEST(Measurement, BadFilesNameFilePathAndExpectation) {
  const BadCase cases[] = {
      {R"("coil-measurement/1")", R"("coil-measurement/2")", "/format", "coil-measurement/1"},
      {R"("length_mm": 150.0,)", "", "/coil/length_mm", "missing"},
      {R"("length_mm": 150.0)", R"("length_mm": "150")", "/coil/length_mm", "number in (0, 2000] mm"},
      {R"("wire_radius_mm": 0.3556)", R"("wire_radius_mm": -1)", "/coil/wire_radius_mm", "in (0, 5] mm"},
      {R"("loop_diameter_mm": 7.0)", R"("loop_diameter_mm": 0.5)", "/coil/rest_shape/loop_diameter_mm",
       "from the wire diameter 0.7112 mm"},
      {R"("density_g_cm3": 21.45,)", "", "/coil/density_g_cm3", "mass_g"},
      {R"("handedness": "left")", R"("handedness": "up")", "/coil/rest_shape/handedness", "right"},
      {R"("gravity_m_s2": [0.0, 0.0, -9.81])", R"("gravity_m_s2": [0.0, -9.81])", "/setup/gravity_m_s2", "[x, y, z]"},
      {R"("direction": [1, 0, 0])", R"("direction": [2, 0, 0])", "/setup/catheter_tip/direction", "unit vector"},
      {R"("reference_normal": [0, 0, 1])", R"("reference_normal": [0.6, 0, 0.8])", "/setup/catheter_tip/reference_normal",
       "orthogonal"},
      {R"("deployed_length_mm": 40.0)", R"("deployed_length_mm": 151.0)", "/stages/0/deployed_length_mm", "coil length"},
      {R"([[0.0, 0.0, 0.0], [0.98, 0.05, 0.12]])", "[[0.0, 0.0, 0.0]]", "/stages/0/centerline_mm", "at least 2 points"},
      {R"([[0.0, 0.0, 0.0], [0.98, 0.05, 0.12]])", "[]", "/stages/0/centerline_mm", "at least 2 points"},
      {R"([0.98, 0.05, 0.12])", R"([0.98, "x", 0.12])", "/stages/0/centerline_mm/1/1", "number"},
      {R"("twist_deg": 90.0)", R"("twist_deg": null)", "/stages/0/twist_deg", "number"},
      {R"(, "capture_time_s": 2.5)", "", "/stages/1/capture_time_s", "required with push_history"},
      {R"([2, 60, 45])", R"([0, 60, 45])", "/stages/1/push_history/1/0", "greater than the previous"},
      {R"("stages": [)", R"("stages": [], "x": [)", "/stages", "at least one stage"},
  };
  for (const BadCase& c : cases) {
    SCOPED_TRACE(c.path);
    const std::string message = errorOf([&] { parseMeasurement(with(c.from, c.to), "bad.json"); });
    EXPECT_CONTAINS(message, "bad.json");
    EXPECT_CONTAINS(message, c.path);
    EXPECT_CONTAINS(message, c.expectation);
  }
}

// A rod quantity is declared once (physics/rod_quantities.h): a measurement
// refuses what a scene refuses, with the same key and the same bounds text.
// The reference is the scene reader given the same bad value.
TEST(Measurement, RodQuantitiesAreBoundedAsInASceneFile) {
  struct Case {
    std::string from, to, path, sceneKey, sceneValue;
  };
  const Case cases[] = {
      {R"("density_g_cm3": 21.45)", R"("density_g_cm3": 0.2)", "/coil/density_g_cm3", "density_g_cm3", "0.2"},
      {R"("young_modulus_gpa": 7.5)", R"("young_modulus_gpa": 2000)", "/coil/young_modulus_gpa", "young_modulus_gpa",
       "2000"},
      {R"("length_mm": 150.0)", R"("length_mm": 2500)", "/coil/length_mm", "length_mm", "2500"},
  };
  const std::string scene = std::string(COILSIM_SOURCE_DIR) + "/scenes/cantilever-static.json";
  std::ifstream in(scene);
  ASSERT_TRUE(in) << scene;
  const std::string sceneText((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  for (const Case& c : cases) {
    SCOPED_TRACE(c.path);
    const std::string message = errorOf([&] { parseMeasurement(with(c.from, c.to), "bad.json"); });
    EXPECT_CONTAINS(message, c.path);
    // The same value in the scene's rod: the scene reader's words for it.
    const std::string key = "\"" + c.sceneKey + "\": ";
    const size_t at = sceneText.find(key);
    ASSERT_NE(at, std::string::npos) << key;
    std::string bad = sceneText;
    bad.replace(at + key.size(), bad.find_first_of(",}\n", at + key.size()) - at - key.size(), c.sceneValue);
    const std::string sceneMessage = errorOf([&] { sceneFromText(bad, "s.json"); });
    const size_t expected = sceneMessage.find("expected ");
    ASSERT_NE(expected, std::string::npos) << sceneMessage;
    const std::string words = sceneMessage.substr(expected, sceneMessage.find(", got", expected) - expected);
    EXPECT_CONTAINS(message, words);
  }
}

TEST(Measurement, NonFiniteAndMalformedAndMissingFile) {
  // JSON has no NaN; an overflowing literal is the way a non-finite number arrives.
  EXPECT_CONTAINS(errorOf([&] { parseMeasurement(with("0.3556", "1e999"), "bad.json"); }), "finite");
  EXPECT_CONTAINS(errorOf([&] { parseMeasurement(with("\"stages\"", "\"stages\" ::"), "bad.json"); }), "line");
  EXPECT_CONTAINS(errorOf([&] { readMeasurement("/nonexistent/m.json"); }), "/nonexistent/m.json");
}

TEST(Measurement, SharedControlFileReads) {
  const std::string path = COILSIM_SOURCE_DIR "/../shared/data/measurements/control-helix-a.json";
  if (!std::ifstream(path)) GTEST_SKIP() << "shared measurement " << path << " is absent";
  const Measurement m = readMeasurement(path);
  EXPECT_DOUBLE_EQ(m.coil.length, 0.120);
  ASSERT_EQ(m.stages.size(), 3u);
  EXPECT_DOUBLE_EQ(m.stages[2].deployed, 0.100);
  EXPECT_GT(m.stages[0].centerline.size(), 10u);
}

}  // namespace
}  // namespace coilsim::io
