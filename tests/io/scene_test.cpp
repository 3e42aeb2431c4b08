// Scene files: parse -> check -> compile, every bad input named by its JSON
// path, and the compiled SI values against hand computation.
#include "io/scene.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>

#include "io/expect_error.h"
#include "physics/model.h"

namespace coilsim::io {
namespace {

// A small complete scene; tests change one thing each.
constexpr const char* kScene = R"({
  "format": "coilsim-scene/1",
  "name": "small",
  "gravity_m_s2": [0, 0, -9.81],
  "solve": "dynamic",
  "time_step_s": 0.001,
  "duration_s": 0.01,
  "damping": {"rayleigh_mass_1_s": 2.0, "rayleigh_stiffness_s": 0.001},
  "effects": {"gravity": {}, "buoyancy": {"medium_density_g_cm3": 1.06}, "drag": {"rft_length_mm": 5.0}},
  "rods": [
    {
      "name": "coil",
      "role": "coil",
      "length_mm": 100,
      "beams": 10,
      "rest_shape": {"type": "straight"},
      "material": {"young_modulus_gpa": 200, "poisson_ratio": 0.3, "density_g_cm3": 7.85},
      "section": {"wire_radius_mm": 0.5},
      "placement": {"position_mm": [1, 2, 3], "direction": [0, 0, 2], "normal": [1, 0, 0]},
      "boundary": [{"node": 0, "type": "clamped", "velocity_mm_s": [10, 0, 0], "angular_velocity_deg_s": [0, 0, 90]},
                   {"node": "last", "type": "pinned"}],
      "loads": [{"node": 5, "force_N": [0, 0.5, 0], "moment_N_mm": [0, 0, 2]}]
    }
  ]
})";

nlohmann::json base() { return nlohmann::json::parse(kScene); }

SceneSpec parse(const nlohmann::json& doc) { return sceneFromText(doc.dump(2), "t.json"); }

// The error for kScene with the value at `pointer` replaced (or removed if null).
std::string errorWith(const std::string& pointer, const nlohmann::json& value, bool remove = false) {
  nlohmann::json doc = base();
  const nlohmann::json::json_pointer p(pointer);
  if (remove) doc.at(p.parent_pointer()).erase(p.back());
  else doc[p] = value;
  return errorOf([&] { (void)parse(doc); });
}

std::string errorWithout(const std::string& pointer) { return errorWith(pointer, nullptr, true); }

TEST(Scene, ParsesTheSmallScene) {
  const SceneSpec s = parse(base());
  EXPECT_EQ(s.name, "small");
  EXPECT_EQ(s.solve, SolveMode::Dynamic);
  ASSERT_EQ(s.rods.size(), 1u);
  const RodSpecMm& r = s.rods[0];
  EXPECT_EQ(r.beams, 10);
  EXPECT_TRUE(r.boundary[1].node.last);
  EXPECT_EQ(r.boundary[1].node.resolve(r.beams), 10);
  EXPECT_FALSE(r.boundary[1].clamped);
  EXPECT_EQ(s.effects.size(), 3u);
  EXPECT_TRUE(s.warnings.empty());
}

TEST(Scene, CompilesToSiByHand) {
  const ModelDef d = compileScene(parse(base()));
  EXPECT_DOUBLE_EQ(d.timeStep, 1e-3);
  EXPECT_DOUBLE_EQ(d.damping.massCoeff, 2.0);
  EXPECT_DOUBLE_EQ(d.damping.stiffnessCoeff, 1e-3);
  EXPECT_EQ(d.gravity, Vec3(0, 0, -9.81));
  const RodDef& r = d.rods[0];
  EXPECT_DOUBLE_EQ(r.length, 0.1);
  EXPECT_DOUBLE_EQ(r.material.youngModulus, 200e9);
  EXPECT_DOUBLE_EQ(r.material.shearModulus, 200e9 / 2.6);  // E / (2 (1 + nu))
  EXPECT_DOUBLE_EQ(r.material.density, 7850.0);
  const double radius = 0.5e-3;
  EXPECT_NEAR(r.section.area, M_PI * radius * radius, 1e-22);
  EXPECT_NEAR(r.section.iy, M_PI * std::pow(radius, 4) / 4, 1e-28);
  EXPECT_NEAR(r.section.torsion, M_PI * std::pow(radius, 4) / 2, 1e-28);
  EXPECT_NEAR(r.section.shearFactor, 6 * 1.3 / (7 + 6 * 0.3), 1e-15);  // Cowper, circle
  EXPECT_DOUBLE_EQ(r.section.radius, radius);
  EXPECT_TRUE(r.placement.position.isApprox(Vec3(1e-3, 2e-3, 3e-3)));
  ASSERT_EQ(r.constraints.size(), 2u);
  EXPECT_EQ(r.constraints[0].mask, unsigned(kAllDofs));
  EXPECT_EQ(r.constraints[1].mask, unsigned(kTranslation));
  EXPECT_EQ(r.constraints[1].node, 10);
  EXPECT_TRUE(r.constraints[0].velocity.isApprox(Vec3(0.01, 0, 0)));
  EXPECT_NEAR(r.constraints[0].angularVelocity.z(), M_PI / 2, 1e-15);
  ASSERT_EQ(r.loads.size(), 1u);
  EXPECT_EQ(r.loads[0].node, 5);
  EXPECT_EQ(r.loads[0].force, Vec3(0, 0.5, 0));
  EXPECT_NEAR(r.loads[0].moment.z(), 2e-3, 1e-18);  // N mm -> N m
  ASSERT_EQ(r.rest.points.size(), 11u);
  EXPECT_NEAR(r.rest.points.back().x(), 0.1, 1e-15);
}

TEST(Scene, EffectParametersComeFromTheirParamSpecs) {
  const ModelDef d = compileScene(parse(base()));
  ASSERT_EQ(d.effects.size(), 3u);
  for (const EffectUse& u : d.effects) {
    if (u.name() == "buoyancy") {
      EXPECT_DOUBLE_EQ(u.value("medium_density_g_cm3"), 1060.0);
    }
    if (u.name() == "drag") {
      EXPECT_DOUBLE_EQ(u.value("rft_length_mm"), 5e-3);
      EXPECT_DOUBLE_EQ(u.value("viscosity_pa_s"), 0.001);  // declared default, water
    }
  }
}

TEST(Scene, CompiledModelIsPlacedAsAsked) {
  const Model m = compileModel(compileScene(parse(base())));
  const RodModel& r = m.rods[0];
  // direction [0, 0, 2] and normal [1, 0, 0]: the rod rises along z from (1, 2, 3) mm.
  EXPECT_TRUE(r.restPoints.front().isApprox(Vec3(1e-3, 2e-3, 3e-3)));
  EXPECT_NEAR((r.restPoints.back() - Vec3(1e-3, 2e-3, 0.103)).norm(), 0, 1e-12);
  EXPECT_NEAR((r.restFrames.front() * Vec3::UnitY() - Vec3::UnitX()).norm(), 0, 1e-12);
  // Lumped mass: rho A L in all.
  double mass = 0;
  for (double mi : r.nodeMass) mass += mi;
  EXPECT_NEAR(mass, 7850 * M_PI * 0.25e-6 * 0.1, 1e-15);
}

TEST(Scene, ExplicitSectionConvertsMillimetrePowers) {
  nlohmann::json doc = base();
  doc["rods"][0]["section"] = {{"area_mm2", 2.0}, {"inertia_mm4", 3.0}, {"torsion_mm4", 5.0},
                               {"shear_factor", 0.0}, {"outer_radius_mm", 0.9}};
  const ModelDef d = compileScene(parse(doc));
  const Section& s = d.rods[0].section;
  EXPECT_DOUBLE_EQ(s.area, 2e-6);
  EXPECT_DOUBLE_EQ(s.iy, 3e-12);
  EXPECT_DOUBLE_EQ(s.iz, 3e-12);
  EXPECT_DOUBLE_EQ(s.torsion, 5e-12);
  EXPECT_EQ(s.shearFactor, 0.0);
  EXPECT_DOUBLE_EQ(s.radius, 0.9e-3);
}

TEST(Scene, HelixFollowsTheMeasurementDefinition) {
  nlohmann::json doc = base();
  doc["rods"][0]["rest_shape"] = {{"type", "helix"}, {"loop_diameter_mm", 7.0}, {"pitch_mm", 1.0}, {"handedness", "left"}};
  doc["rods"][0]["beams"] = 200;
  const SceneSpec s = parse(doc);
  EXPECT_FALSE(s.rods[0].rest.rightHanded);
  const RestCurve c = compileScene(s).rods[0].rest;
  // Curvature k = R / (R^2 + c^2) from three neighbouring nodes (circumscribed circle).
  const double R = 3.5e-3, pc = 1e-3 / (2 * M_PI), k = R / (R * R + pc * pc);
  const Vec3 a = c.points[100], b = c.points[101], e = c.points[102];
  const double kNodes = 2 * (b - a).cross(e - b).norm() / ((b - a).norm() * (e - b).norm() * (e - a).norm());
  EXPECT_NEAR(kNodes, k, 1e-3 * k);
}

TEST(Scene, PolylineWithinOnePercentIsAccepted) {
  nlohmann::json doc = base();
  doc["rods"][0]["rest_shape"] = {{"type", "polyline"}, {"points_mm", {{0, 0, 0}, {50, 0, 0}, {50, 50.5, 0}}}, {"frames", "parallel_transport"}, {"twist_deg_per_mm", 1.0}};
  const SceneSpec s = parse(doc);
  EXPECT_EQ(s.rods[0].rest.frames, FrameRule::ParallelTransport);
  const ModelDef d = compileScene(s);
  EXPECT_EQ(d.rods[0].rest.points.size(), 11u);
}

TEST(Scene, UnusedKeysOfTheOtherSolveModeAreWarnedAbout) {
  nlohmann::json doc = base();
  doc["solve"] = "static";
  doc["rods"][0]["boundary"][0].erase("velocity_mm_s");
  doc["rods"][0]["boundary"][0].erase("angular_velocity_deg_s");
  const SceneSpec s = parse(doc);
  ASSERT_EQ(s.warnings.size(), 3u);  // time_step_s, duration_s, damping
  EXPECT_CONTAINS(s.warnings[0], "t.json: /time_step_s: not used by a static solve");
  EXPECT_CONTAINS(s.warnings[2], "t.json: /damping: not used by a static solve");
}

TEST(Scene, StepCountRoundsUpButNotForDecimalNoise) {
  EXPECT_EQ(stepCount(3.0, 0.001), 3000);
  EXPECT_EQ(stepCount(0.3, 0.1), 3);
  EXPECT_EQ(stepCount(0.0105, 0.001), 11);
  EXPECT_EQ(stepCount(1e-6, 0.001), 1);
}

// --- Every kind of bad input names its JSON path and what was expected. ---

TEST(SceneErrors, MalformedJsonGivesLineAndColumn) {
  const std::string msg = errorOf([] { (void)sceneFromText("{\n  \"format\": \"coilsim-scene/1\",\n  \"rods\": [,]\n}", "bad.json"); });
  EXPECT_CONTAINS(msg, "bad.json: line 3, column 12: malformed JSON");
}

TEST(SceneErrors, WrongTypeNamesPathExpectationAndValue) {
  EXPECT_EQ(errorWith("/rods/0/material/young_modulus_gpa", "abc"),
            "t.json: /rods/0/material/young_modulus_gpa: expected a finite number in [0.1, 1000] GPa, got \"abc\"");
  EXPECT_CONTAINS(errorWith("/rods/0/beams", "ten"), "/rods/0/beams: expected an integer in [1, 20000], got \"ten\"");
  EXPECT_CONTAINS(errorWith("/rods", nlohmann::json::object()), "/rods: expected an array of at least one rod, got an empty object");
  EXPECT_CONTAINS(errorWith("/gravity_m_s2", {0, 0}), "/gravity_m_s2: expected [x, y, z]");
  EXPECT_CONTAINS(errorWith("/effects/gravity/enabled", 1), "/effects/gravity/enabled: expected true or false, got 1");
}

TEST(SceneErrors, MissingFieldIsNamed) {
  EXPECT_EQ(errorWithout("/rods/0/length_mm"), "t.json: /rods/0/length_mm: missing; expected a finite number in (0, 2000] mm");
  EXPECT_CONTAINS(errorWithout("/rods/0/material/density_g_cm3"), "/rods/0/material/density_g_cm3: missing");
  EXPECT_CONTAINS(errorWithout("/time_step_s"), "/time_step_s: missing");
  EXPECT_CONTAINS(errorWithout("/solve"), "/solve: missing; expected one of \"dynamic\", \"static\"");
  EXPECT_CONTAINS(errorWithout("/rods/0/boundary/0/type"), "/rods/0/boundary/0/type: missing");
  EXPECT_CONTAINS(errorWithout("/format"), "/format: missing; expected \"coilsim-scene/1\"");
}

TEST(SceneErrors, UnknownKeysAreErrorsListingTheAllowedOnes) {
  const std::string msg = errorWith("/rods/0/material/young_modulus", 7.5);
  EXPECT_CONTAINS(msg, "t.json: /rods/0/material/young_modulus: unknown key");
  EXPECT_CONTAINS(msg, "did you mean \"young_modulus_gpa\"");
  EXPECT_CONTAINS(msg, "allowed here: young_modulus_gpa, poisson_ratio, density_g_cm3");
  EXPECT_CONTAINS(errorWith("/colour", "red"), "t.json: /colour: unknown key");
  EXPECT_CONTAINS(errorWith("/effects/drag/viscosity", 1), "/effects/drag/viscosity: unknown key (did you mean \"viscosity_pa_s\"?)");
  EXPECT_CONTAINS(errorWith("/rods/0/rest_shape/pitch_mm", 1), "/rods/0/rest_shape/pitch_mm: unknown key; allowed here: type");
}

TEST(SceneErrors, NonFiniteNumberIsNamed) {
  std::string text = kScene;
  text.replace(text.find("\"length_mm\": 100"), 16, "\"length_mm\": 1e999");
  const std::string msg = errorOf([&] { (void)sceneFromText(text, "t.json"); });
  EXPECT_CONTAINS(msg, "t.json: line 14, column");
  EXPECT_CONTAINS(msg, "/rods/0/length_mm: expected a finite number, got 1e999");
}

TEST(SceneErrors, SignsAndRangesAreChecked) {
  EXPECT_EQ(errorWith("/rods/0/material/young_modulus_gpa", -7.5),
            "t.json: /rods/0/material/young_modulus_gpa: expected a finite number in [0.1, 1000] GPa, got -7.5");
  EXPECT_CONTAINS(errorWith("/rods/0/material/poisson_ratio", 0.6), "/rods/0/material/poisson_ratio: expected a finite number in (-1, 0.5], got 0.6");
  EXPECT_CONTAINS(errorWith("/rods/0/section/wire_radius_mm", 0), "/rods/0/section/wire_radius_mm: expected a finite number in (0, 5] mm, got 0");
  EXPECT_CONTAINS(errorWith("/time_step_s", 2), "/time_step_s: expected a finite number in (0, 0.01] s, got 2");
  EXPECT_CONTAINS(errorWith("/damping/rayleigh_mass_1_s", -1), "/damping/rayleigh_mass_1_s: expected a finite number >= 0");
  EXPECT_CONTAINS(errorWith("/rods/0/beams", 0), "/rods/0/beams: expected an integer in [1, 20000], got 0");
  // Effect bounds come from the effect's ParamSpec.
  EXPECT_CONTAINS(errorWith("/effects/buoyancy/medium_density_g_cm3", 30),
                  "/effects/buoyancy/medium_density_g_cm3: expected a finite number in [0, 25] g/cm3, got 30");
}

TEST(SceneErrors, NodeIndexOutOfRangeIsNamed) {
  EXPECT_CONTAINS(errorWith("/rods/0/boundary/1/node", 11),
                  "t.json: /rods/0/boundary/1/node: node 11 is out of range: rod \"coil\" has nodes 0..10");
  EXPECT_CONTAINS(errorWith("/rods/0/loads/0/node", 99), "/rods/0/loads/0/node: node 99 is out of range");
  EXPECT_CONTAINS(errorWith("/rods/0/loads/0/node", -1), "/rods/0/loads/0/node: expected an integer in [0, 10000000], got -1");
  EXPECT_CONTAINS(errorWith("/rods/0/loads/0/node", "first"), "/rods/0/loads/0/node: expected a node index (an integer >= 0) or \"last\", got \"first\"");
  EXPECT_CONTAINS(errorWith("/rods/0/boundary/1/node", 0), "/rods/0/boundary/1/node: node 0 is already held by /rods/0/boundary/0");
}

TEST(SceneErrors, PolylineLengthMismatchIsNamed) {
  nlohmann::json doc = base();
  doc["rods"][0]["rest_shape"] = {{"type", "polyline"}, {"points_mm", {{0, 0, 0}, {50, 0, 0}, {50, 48, 0}}}};
  const std::string msg = errorOf([&] { (void)parse(doc); });
  EXPECT_CONTAINS(msg, "t.json: /rods/0/rest_shape/points_mm: the polyline is 98 mm long but length_mm is 100 mm");
  doc["rods"][0]["rest_shape"]["points_mm"] = {{1, 1, 1}};
  EXPECT_CONTAINS(errorOf([&] { (void)parse(doc); }), "/rods/0/rest_shape/points_mm: expected an array of at least 2 points");
}

TEST(SceneErrors, RestShapeKeysDependOnType) {
  EXPECT_CONTAINS(errorWith("/rods/0/rest_shape/type", "spiral"), "/rods/0/rest_shape/type: expected one of \"straight\", \"helix\", \"polyline\", \"birdcage\", got \"spiral\"");
  nlohmann::json doc = base();
  doc["rods"][0]["rest_shape"] = {{"type", "helix"}, {"loop_diameter_mm", 7.0}, {"pitch_mm", 1.0}};
  EXPECT_CONTAINS(errorOf([&] { (void)parse(doc); }), "/rods/0/rest_shape/handedness: missing; expected one of \"right\", \"left\"");
  doc["rods"][0]["rest_shape"] = {{"type", "birdcage"}, {"sphere_diameter_mm", 8.0}, {"plane_turn_per_loop_deg", 400}};
  EXPECT_CONTAINS(errorOf([&] { (void)parse(doc); }), "/rods/0/rest_shape/plane_turn_per_loop_deg: expected a finite number in [-180, 180] deg");
}

TEST(SceneErrors, SectionIsOneFormOrTheOther) {
  nlohmann::json doc = base();
  doc["rods"][0]["section"]["area_mm2"] = 1.0;
  EXPECT_CONTAINS(errorOf([&] { (void)parse(doc); }), "/rods/0/section/area_mm2: unknown key; allowed here: wire_radius_mm");
  doc["rods"][0]["section"] = {{"area_mm2", 1.0}};
  EXPECT_CONTAINS(errorOf([&] { (void)parse(doc); }), "/rods/0/section/inertia_mm4: missing");
  doc["rods"][0]["section"] = nlohmann::json::object();
  EXPECT_CONTAINS(errorOf([&] { (void)parse(doc); }), "/rods/0/section: expected {\"wire_radius_mm\"}");
}

TEST(SceneErrors, CrossFieldChecksNameTheirPath) {
  EXPECT_CONTAINS(errorWith("/rods/0/placement/normal", {0, 0, 5}), "/rods/0/placement/normal: expected a non-zero vector not parallel to direction");
  EXPECT_CONTAINS(errorWith("/rods/0/placement/direction", {0, 0, 0}), "/rods/0/placement/direction: expected a non-zero vector");
  nlohmann::json doc = base();
  doc["rods"].push_back(doc["rods"][0]);
  EXPECT_CONTAINS(errorOf([&] { (void)parse(doc); }), "/rods/1/name: rod name \"coil\" is already used by /rods/0");
  doc = base();
  doc["solve"] = "static";
  EXPECT_CONTAINS(errorOf([&] { (void)parse(doc); }), "/rods/0/boundary/0: a static solve has no time");
  doc["rods"][0].erase("boundary");
  EXPECT_CONTAINS(errorOf([&] { (void)parse(doc); }), "/rods/0/boundary: a static solve needs every rod held");
}

TEST(SceneErrors, EffectsAndFormatAreChecked) {
  EXPECT_CONTAINS(errorWith("/effects/magnetism", nlohmann::json::object()), "/effects/magnetism: unknown effect; registered effects: gravity, buoyancy, drag");
  EXPECT_CONTAINS(errorWith("/format", "coilsim-scene/2"), "/format: expected \"coilsim-scene/1\", got \"coilsim-scene/2\"");
  EXPECT_CONTAINS(errorOf([] { (void)sceneFromText("[1, 2]", "t.json"); }), "t.json: /: expected a JSON object (a coilsim scene), got an array of 2");
  EXPECT_CONTAINS(errorWith("/rods/0/loads/0", {{"node", 1}}), "/rods/0/loads/0: a load needs \"force_N\", \"moment_N_mm\" or both");
}

// The scenes shipped in scenes/ all read, check and compile.
TEST(Scene, ShippedScenesLoad) {
  int count = 0;
  for (const auto& entry : std::filesystem::directory_iterator(std::string(COILSIM_SOURCE_DIR) + "/scenes")) {
    if (entry.path().extension() != ".json") continue;
    SCOPED_TRACE(entry.path().string());
    const SceneSpec s = loadScene(entry.path().string());
    EXPECT_TRUE(s.warnings.empty());
    EXPECT_NO_THROW((void)compileModel(compileScene(s)));
    ++count;
  }
  EXPECT_GE(count, 5);
}

}  // namespace
}  // namespace coilsim::io
