// The "deployment" block of scene files: read with the rods' own sub-readers,
// checked (every bad input named by its JSON path), compiled to SI and to
// the rods addDeployment appends.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "io/expect_error.h"
#include "io/scene.h"
#include "physics/state.h"
#include "physics/model.h"

namespace coilsim::io {
namespace {

// A deployment-only scene; tests change one thing each.
constexpr const char* kScene = R"({
  "format": "coilsim-scene/1",
  "gravity_m_s2": [0, 0, -9.81],
  "solve": "dynamic",
  "time_step_s": 0.001,
  "duration_s": 0.01,
  "deployment": {
    "coil": {
      "name": "coil",
      "length_mm": 30,
      "beams": 30,
      "rest_shape": {"type": "helix", "loop_diameter_mm": 7, "pitch_mm": 0.96, "handedness": "right"},
      "material": {"young_modulus_gpa": 7.5, "poisson_ratio": 0.39, "density_g_cm3": 21.45},
      "section": {"wire_radius_mm": 0.1}
    },
    "catheter": {"type": "rigid", "tip_position_mm": [1, 2, 3], "direction": [0, 2, 0], "reference_normal": [0, 0, 1],
                 "outer_diameter_mm": 0.6, "draw_length_mm": 20},
    "initial_deployed_mm": 5,
    "initial_twist_deg": 90,
    "max_push_speed_mm_s": 20
  }
})";

nlohmann::json base() { return nlohmann::json::parse(kScene); }

SceneSpec parse(const nlohmann::json& doc) { return sceneFromText(doc.dump(2), "d.json"); }

std::string errorOfDoc(const nlohmann::json& doc) {
  return errorOf([&] { (void)parse(doc); });
}

// The error for kScene with the value at `pointer` replaced (or removed if `remove`).
std::string errorWith(const std::string& pointer, const nlohmann::json& value, bool remove = false) {
  nlohmann::json doc = base();
  const nlohmann::json::json_pointer p(pointer);
  if (remove) doc.at(p.parent_pointer()).erase(p.back());
  else doc[p] = value;
  return errorOfDoc(doc);
}

TEST(SceneDeployment, ParsesWithoutRods) {
  const SceneSpec s = parse(base());
  EXPECT_TRUE(s.rods.empty());
  ASSERT_TRUE(s.deployment.has_value());
  const DeploymentSpec& d = *s.deployment;
  EXPECT_EQ(d.coilName, "coil");
  EXPECT_EQ(d.beams, 30);
  EXPECT_EQ(d.rest.type, RestShapeSpec::Type::Helix);
  EXPECT_DOUBLE_EQ(d.material.youngModulusGpa, 7.5);
  EXPECT_DOUBLE_EQ(d.section.wireRadiusMm, 0.1);
  EXPECT_EQ(d.catheter.direction, Vec3(0, 2, 0));
  EXPECT_DOUBLE_EQ(d.maxTwistRateDegS, 720);  // default
  EXPECT_TRUE(s.warnings.empty());
}

TEST(SceneDeployment, CompilesToSiAndAppendsItsRodsAfterTheScenesRods) {
  nlohmann::json doc = base();
  doc["rods"] = nlohmann::json::parse(R"([{"name": "wire", "length_mm": 10, "beams": 2, "rest_shape": {"type": "straight"},
    "material": {"young_modulus_gpa": 200, "poisson_ratio": 0.3, "density_g_cm3": 7.85},
    "section": {"wire_radius_mm": 0.2}, "boundary": [{"node": 0, "type": "clamped"}]}])");
  const ModelDef def = compileScene(parse(doc));
  ASSERT_TRUE(def.device.has_value());
  ASSERT_EQ(def.rods.size(), 1u);  // the scene's wire; compileModel appends the deployment's
  const Model m = compileModel(def);
  ASSERT_TRUE(m.device.has_value());
  const Deployment& dep = *m.device;
  ASSERT_EQ(m.rods.size(), 4u);  // wire, then chain, detached coil, catheter
  EXPECT_EQ(m.rods[0].name, "wire");
  EXPECT_EQ(dep.chainRod, 1);
  EXPECT_EQ(m.rods[1].name, "coil");
  EXPECT_DOUBLE_EQ(dep.coilLength, 0.03);
  EXPECT_EQ(dep.coilBeams, 30);
  EXPECT_DOUBLE_EQ(dep.material.youngModulus, 7.5e9);
  EXPECT_DOUBLE_EQ(dep.material.density, 21450);
  EXPECT_DOUBLE_EQ(dep.section.radius, 1e-4);
  EXPECT_TRUE(dep.tip.position.isApprox(Vec3(1e-3, 2e-3, 3e-3)));
  EXPECT_DOUBLE_EQ(dep.maxPushSpeed, 0.02);
  EXPECT_NEAR(dep.maxTwistRate, 4 * M_PI, 1e-12);
  EXPECT_DOUBLE_EQ(dep.initialDeployed, 5e-3);
  EXPECT_NEAR(dep.initialTwist, M_PI / 2, 1e-15);
  // makeState puts the device there.
  EXPECT_DOUBLE_EQ(makeState(m).device.deployed, 5e-3);
  // The coil's rest shape is the rods' helix, from the proximal end.
  ASSERT_EQ(dep.restX.size(), 31u);
  EXPECT_NEAR(dep.restX.front().norm(), 0, 1e-15);
  // The drawn catheter: outer diameter 0.6 mm.
  EXPECT_DOUBLE_EQ(m.rods[dep.catheterRod].section.radius, 0.3e-3);
}

TEST(SceneDeployment, CoilReusesTheRodReadersAndTheirMessages) {
  EXPECT_CONTAINS(errorWith("/deployment/coil/rest_shape/type", "spiral"),
                  "d.json: /deployment/coil/rest_shape/type: expected one of \"straight\", \"helix\"");
  EXPECT_CONTAINS(errorWith("/deployment/coil/material/young_modulus", 7.5),
                  "/deployment/coil/material/young_modulus: unknown key (did you mean \"young_modulus_gpa\"?)");
  EXPECT_CONTAINS(errorWith("/deployment/coil/section", nlohmann::json::object()), "/deployment/coil/section: expected");
  EXPECT_CONTAINS(errorWith("/deployment/coil/beams", 1), "/deployment/coil/beams: expected an integer in [2, 20000], got 1");
  EXPECT_CONTAINS(errorWith("/deployment/coil/length_mm", -30), "/deployment/coil/length_mm: expected a finite number in (0, 2000] mm");
  EXPECT_CONTAINS(errorWith("/deployment/coil/length_mm", nullptr, true), "/deployment/coil/length_mm: missing");
  EXPECT_CONTAINS(errorWith("/deployment/coil/boundary", nlohmann::json::array()),
                  "/deployment/coil/boundary: unknown key; allowed here: name, length_mm");
  nlohmann::json doc = base();
  doc["deployment"]["coil"]["rest_shape"] = {{"type", "polyline"}, {"points_mm", {{0, 0, 0}, {10, 0, 0}}}};
  EXPECT_CONTAINS(errorOfDoc(doc),
                  "/deployment/coil/rest_shape/points_mm: the polyline is 10 mm long but length_mm is 30 mm");
}

TEST(SceneDeployment, CatheterErrorsNameTheirPath) {
  EXPECT_CONTAINS(errorWith("/deployment/catheter/reference_normal", {0, 1, 1}),
                  "d.json: /deployment/catheter/reference_normal: expected a vector orthogonal to direction; the angle "
                  "between them is 45 deg");
  EXPECT_CONTAINS(errorWith("/deployment/catheter/reference_normal", {0, 0, 0}),
                  "/deployment/catheter/reference_normal: expected a non-zero vector");
  EXPECT_CONTAINS(errorWith("/deployment/catheter/direction", {0, 0, 0}),
                  "/deployment/catheter/direction: expected a non-zero vector");
  EXPECT_CONTAINS(errorWith("/deployment/catheter/type", "shaped"),
                  "/deployment/catheter/type: expected one of \"rigid\", \"flexible\", got \"shaped\"");
  EXPECT_CONTAINS(errorWith("/deployment/catheter/type", nullptr, true), "/deployment/catheter/type: missing");
  EXPECT_CONTAINS(errorWith("/deployment/catheter/tip_position_mm", {0, 1}),
                  "/deployment/catheter/tip_position_mm: expected [x, y, z]");
  EXPECT_CONTAINS(errorWith("/deployment/catheter/outer_diameter_mm", 0),
                  "/deployment/catheter/outer_diameter_mm: expected a finite number > 0, got 0");
  EXPECT_CONTAINS(errorWith("/deployment/catheter/tip", 1), "/deployment/catheter/tip: unknown key");
  EXPECT_CONTAINS(errorWith("/deployment/catheter", nullptr, true), "/deployment/catheter: missing");
}

// kScene with a flexible 90 deg catheter instead of the rigid tip.
nlohmann::json flexible() {
  nlohmann::json doc = base();
  doc["deployment"]["catheter"] = nlohmann::json::parse(R"({
    "type": "flexible", "tip_position_mm": [1, 2, 3], "direction": [0, 2, 0], "reference_normal": [0, 0, 1],
    "outer_diameter_mm": 0.6, "inner_diameter_mm": 0.42,
    "material": {"young_modulus_gpa": 0.3, "poisson_ratio": 0.4, "density_g_cm3": 1.1},
    "rest_shape": {"type": "angled", "angle_deg": 90, "radius_mm": 4},
    "held_length_mm": 5, "free_length_mm": 15, "beams": 20})");
  return doc;
}

std::string flexibleErrorWith(const std::string& pointer, const nlohmann::json& value, bool remove = false) {
  nlohmann::json doc = flexible();
  const nlohmann::json::json_pointer p(pointer);
  if (remove) doc.at(p.parent_pointer()).erase(p.back());
  else doc[p] = value;
  return errorOfDoc(doc);
}

TEST(SceneDeployment, FlexibleCatheterCompilesToSiWithItsTipAtTheStatedPose) {
  const Model m = compileModel(compileScene(parse(flexible())));
  ASSERT_TRUE(m.device);
  const Deployment& dep = *m.device;
  EXPECT_EQ(dep.tipNode, 20);
  EXPECT_DOUBLE_EQ(dep.catheter.material.youngModulus, 0.3e9);
  EXPECT_DOUBLE_EQ(dep.catheter.outerRadius, 0.3e-3);
  EXPECT_DOUBLE_EQ(dep.catheter.innerRadius, 0.21e-3);
  EXPECT_NEAR(dep.catheter.shape.angle, M_PI / 2, 1e-15);
  EXPECT_DOUBLE_EQ(dep.catheter.shape.radius, 4e-3);
  EXPECT_EQ(dep.catheter.weighting, CompositeWeighting::BendingStiffness) << "the moment balance is the default";
  // Chain: 20 catheter beams then the coil's 30; nodes within 5 mm of the base held.
  EXPECT_EQ(m.rods[dep.chainRod].nnode, 20 + 30 + 1);
  EXPECT_EQ(m.rods[dep.chainRod].constraints.size(), 6u);
  // The catheter's rest tip sits where the scene puts the tip, exit along +y,
  // and its base 90 deg away: the proximal axis is then along -z x y... any
  // normal of y; the bend turns it by 90 deg.
  const RodModel& cath = m.rods[dep.catheterRod];
  EXPECT_NEAR((cath.restPoints.back() - Vec3(1e-3, 2e-3, 3e-3)).norm(), 0, 1e-15);
  EXPECT_NEAR((cath.restFrames.back() * Vec3::UnitX() - Vec3::UnitY()).norm(), 0, 1e-14);
  EXPECT_NEAR(std::abs((cath.restFrames.front() * Vec3::UnitX()).dot(Vec3::UnitY())), 0, 1e-14);
  auto doc = flexible();
  doc["deployment"]["catheter"]["composite_weighting"] = "young_modulus";
  EXPECT_EQ(compileScene(parse(doc)).device->catheter.weighting, CompositeWeighting::YoungModulus);
}

TEST(SceneDeployment, FlexibleCatheterErrorsNameTheirPath) {
  EXPECT_CONTAINS(flexibleErrorWith("/deployment/catheter/inner_diameter_mm", 0.7),
                  "d.json: /deployment/catheter/inner_diameter_mm: expected less than outer_diameter_mm (0.6 mm), got 0.7 mm");
  EXPECT_CONTAINS(flexibleErrorWith("/deployment/catheter/rest_shape", {{"type", "j"}, {"radius_mm", 6}}),
                  "/deployment/catheter/rest_shape: the bends take 18.8496 mm of arc (angle x radius) but free_length_mm "
                  "is 15 mm");
  EXPECT_CONTAINS(flexibleErrorWith("/deployment/catheter/rest_shape/type", "hook"),
                  "/deployment/catheter/rest_shape/type: expected one of \"straight\", \"angled\", \"j\", \"s\"");
  EXPECT_CONTAINS(flexibleErrorWith("/deployment/catheter/rest_shape/angle_deg", 0),
                  "/deployment/catheter/rest_shape/angle_deg: expected a finite number in (0, 180] deg");
  EXPECT_CONTAINS(flexibleErrorWith("/deployment/catheter/rest_shape/radius_mm", nullptr, true),
                  "/deployment/catheter/rest_shape/radius_mm: missing");
  EXPECT_CONTAINS(flexibleErrorWith("/deployment/catheter/material/young_modulus_gpa", "soft"),
                  "/deployment/catheter/material/young_modulus_gpa: expected a finite number in [0.1, 1000] GPa");
  EXPECT_CONTAINS(flexibleErrorWith("/deployment/catheter/beams", 1),
                  "/deployment/catheter/beams: expected an integer in [2, 10000], got 1");
  EXPECT_CONTAINS(flexibleErrorWith("/deployment/catheter/free_length_mm", nullptr, true),
                  "/deployment/catheter/free_length_mm: missing");
  EXPECT_CONTAINS(flexibleErrorWith("/deployment/catheter/held_length_mm", -1),
                  "/deployment/catheter/held_length_mm: expected a finite number >= 0, got -1");
  EXPECT_CONTAINS(flexibleErrorWith("/deployment/catheter/composite_weighting", "average"),
                  "/deployment/catheter/composite_weighting: expected one of \"bending_stiffness\", \"young_modulus\"");
  // Keys of the other type are unknown here, and the other way round.
  EXPECT_CONTAINS(flexibleErrorWith("/deployment/catheter/draw_length_mm", 20),
                  "/deployment/catheter/draw_length_mm: unknown key");
  EXPECT_CONTAINS(errorWith("/deployment/catheter/held_length_mm", 5), "/deployment/catheter/held_length_mm: unknown key");
  EXPECT_CONTAINS(flexibleErrorWith("/deployment/catheter/rest_shape", {{"type", "straight"}, {"angle_deg", 90}}),
                  "/deployment/catheter/rest_shape/angle_deg: unknown key");
}

TEST(SceneDeployment, LimitsAndNumbersAreChecked) {
  EXPECT_CONTAINS(errorWith("/deployment/initial_deployed_mm", 31),
                  "d.json: /deployment/initial_deployed_mm: expected at most the coil's length_mm (30 mm), got 31 mm");
  EXPECT_CONTAINS(errorWith("/deployment/initial_deployed_mm", -1),
                  "/deployment/initial_deployed_mm: expected a finite number >= 0, got -1");
  EXPECT_CONTAINS(errorWith("/deployment/max_push_speed_mm_s", 0),
                  "/deployment/max_push_speed_mm_s: expected a finite number in (0, 1000] mm/s");
  EXPECT_CONTAINS(errorWith("/deployment/initial_twist_deg", "90"), "/deployment/initial_twist_deg: expected a finite number");
  EXPECT_CONTAINS(errorWith("/deployment/initial_deployed", 3),
                  "/deployment/initial_deployed: unknown key (did you mean \"initial_deployed_mm\"?)");
  // Beyond the range of a double: caught while parsing, with the path.
  std::string text = base().dump();
  text.replace(text.find("\"initial_twist_deg\":90"), 22, "\"initial_twist_deg\":1e999");
  EXPECT_CONTAINS(errorOf([&] { (void)sceneFromText(text, "d.json"); }),
                  "/deployment/initial_twist_deg: expected a finite number, got 1e999");
}

TEST(SceneDeployment, SceneLevelChecks) {
  nlohmann::json doc = base();
  doc["solve"] = "static";
  EXPECT_CONTAINS(errorOfDoc(doc), "d.json: /deployment: a deployment moves in time: it needs \"solve\": \"dynamic\"");
  // Neither rods nor a deployment: nothing to simulate.
  doc = base();
  doc.erase("deployment");
  EXPECT_CONTAINS(errorOfDoc(doc), "/rods: missing; expected an array of at least one rod (or a \"deployment\" block)");
  // Rod names the deployment takes.
  doc = base();
  doc["rods"] = nlohmann::json::parse(R"([{"name": "catheter", "length_mm": 10, "beams": 2,
    "rest_shape": {"type": "straight"}, "material": {"young_modulus_gpa": 200, "poisson_ratio": 0.3,
    "density_g_cm3": 7.85}, "section": {"wire_radius_mm": 0.2}}])");
  EXPECT_CONTAINS(errorOfDoc(doc), "/rods/0/name: rod name \"catheter\" is taken by the deployment");
  EXPECT_CONTAINS(errorWith("/deployment", 5), "/deployment: expected an object");
}

}  // namespace
}  // namespace coilsim::io
