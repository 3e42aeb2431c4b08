// The `coilsim` command, tested by running the real binary: exit codes,
// messages that name the file, result files a reader can check by hand.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

#include "app/run_binary.h"

namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using namespace apptest;

// Checks what every result must hold, against the scene it came from.
void expectValidResult(const json& result, const json& sceneDoc) {
  EXPECT_EQ(result["format"], "coilsim-result/1");
  EXPECT_EQ(result["status"], "ok");
  ASSERT_EQ(result["rods"].size(), sceneDoc["rods"].size());
  for (size_t k = 0; k < result["rods"].size(); ++k) {
    const json& rod = result["rods"][k];
    EXPECT_EQ(rod["name"], sceneDoc["rods"][k]["name"]);
    const size_t nodes = sceneDoc["rods"][k]["beams"].get<size_t>() + 1;
    ASSERT_EQ(rod["nodes_mm"].size(), nodes);
    ASSERT_EQ(rod["rotations"].size(), nodes);
    for (const json& x : rod["nodes_mm"])
      for (const json& c : x) ASSERT_TRUE(c.is_number() && std::isfinite(c.get<double>()));
    for (const json& q : rod["rotations"]) {
      double n2 = 0;
      for (const json& c : q) n2 += c.get<double>() * c.get<double>();
      EXPECT_NEAR(n2, 1.0, 1e-9);
    }
  }
  for (const char* key : {"kinetic_J", "elastic_J", "potential_J", "total_J"})
    EXPECT_TRUE(std::isfinite(result["energy"][key].get<double>()));
  EXPECT_EQ(result["stats"]["blowups"], 0);
  if (sceneDoc["solve"] == "static") {
    EXPECT_EQ(result["static"]["converged"], true);
  } else {
    EXPECT_GT(result["steps"].get<long>(), 0);
    EXPECT_NEAR(result["time_s"].get<double>(), sceneDoc["duration_s"].get<double>(), 1e-9);
  }
}

TEST(Cli, CantileverTipMatchesHandFormula) {
  const fs::path dir = scratch("cantilever");
  const Exec r = coilsim({"run", scene("cantilever-static.json"), "--headless", "--out", (dir / "r.json").string()}, dir);
  ASSERT_EQ(r.code, 0) << r.err;
  // P L^3 / (3 E I), I = pi r^4 / 4, from the scene's own numbers.
  const json s = readJson(scene("cantilever-static.json"))["rods"][0];
  const double L = s["length_mm"].get<double>() * 1e-3, radius = s["section"]["wire_radius_mm"].get<double>() * 1e-3;
  const double E = s["material"]["young_modulus_gpa"].get<double>() * 1e9, P = -s["loads"][0]["force_N"][2].get<double>();
  const double deflectionMm = 1e3 * P * L * L * L / (3 * E * M_PI * std::pow(radius, 4) / 4);
  const json result = readJson(dir / "r.json");
  const double tipZ = result["rods"][0]["nodes_mm"].back()[2].get<double>();
  EXPECT_NEAR(-tipZ, deflectionMm, 1e-3 * deflectionMm);
  EXPECT_CONTAINS(r.out, "cantilever-static.json: static, converged");
}

TEST(Cli, ElasticaSceneLandsNearTheTables) {
  const fs::path dir = scratch("elastica");
  const Exec r = coilsim({"run", scene("elastica-static.json"), "--headless", "--out", (dir / "r.json").string()}, dir);
  ASSERT_EQ(r.code, 0) << r.err;
  // Bisshopp & Drucker (1945), P L^2 / E I = 2: tip 0.4935 L down, 0.1606 L back.
  const json tip = readJson(dir / "r.json")["rods"][0]["nodes_mm"].back();
  EXPECT_NEAR(-tip[2].get<double>() / 100.0, 0.4935, 0.005 * 0.4935);
  EXPECT_NEAR(1.0 - tip[0].get<double>() / 100.0, 0.1606, 0.01 * 0.1606);
}

TEST(Cli, EveryShippedSceneRunsHeadless) {
  int count = 0;
  for (const auto& entry : fs::directory_iterator(kSource + "/scenes")) {
    if (entry.path().extension() != ".json") continue;
    // Deployment scenes run for half a minute of pushing; deployment_test.cpp runs them briefly.
    if (readJson(entry.path()).contains("deployment")) continue;
    SCOPED_TRACE(entry.path().string());
    const fs::path dir = scratch("scene_" + entry.path().stem().string());
    const Exec r = coilsim({"run", entry.path().string(), "--headless", "--out", (dir / "r.json").string()}, dir);
    EXPECT_EQ(r.code, 0) << r.err;
    EXPECT_CONTAINS(r.out, entry.path().string() + ": ");
    ASSERT_TRUE(fs::exists(dir / "r.json"));
    expectValidResult(readJson(dir / "r.json"), readJson(entry.path()));
    ++count;
  }
  EXPECT_GE(count, 5);
}

TEST(Cli, HelixKeepsItsRestShape) {
  const fs::path dir = scratch("helix_rest");
  const Exec r = coilsim({scene("helix-rest.json"), "--headless", "--steps", "50", "--out", (dir / "r.json").string()}, dir);
  ASSERT_EQ(r.code, 0) << r.err;
  const json result = readJson(dir / "r.json");
  EXPECT_EQ(result["steps"], 50);
  EXPECT_LT(std::abs(result["energy"]["total_J"].get<double>()), 1e-20);
}

TEST(Cli, BadSceneExits2NamingFileAndPath) {
  const fs::path dir = scratch("bad_scene");
  json doc = readJson(scene("cantilever-static.json"));
  doc["rods"][0]["material"]["young_modulus_gpa"] = "abc";
  const fs::path bad = dir / "bad.json";
  std::ofstream(bad) << doc.dump(2);
  const Exec r = coilsim({"run", bad.string(), "--headless", "--out", (dir / "r.json").string()}, dir);
  EXPECT_EQ(r.code, 2);
  EXPECT_CONTAINS(r.err, bad.string() + ": /rods/0/material/young_modulus_gpa: expected a finite number in [0.1, 1000] GPa, got \"abc\"");
  EXPECT_FALSE(fs::exists(dir / "r.json"));
}

TEST(Cli, MalformedSceneExits2WithLineAndColumn) {
  const fs::path dir = scratch("malformed");
  const fs::path bad = dir / "broken.json";
  std::ofstream(bad) << "{\n  \"format\": \"coilsim-scene/1\"\n  \"rods\": []\n}\n";
  const Exec r = coilsim({bad.string(), "--headless"}, dir);
  EXPECT_EQ(r.code, 2);
  EXPECT_CONTAINS(r.err, bad.string() + ": line 3, column");
  EXPECT_CONTAINS(r.err, "malformed JSON");
}

TEST(Cli, MissingFileExits2) {
  const fs::path dir = scratch("missing");
  const Exec r = coilsim({"run", (dir / "nope.json").string(), "--headless"}, dir);
  EXPECT_EQ(r.code, 2);
  EXPECT_CONTAINS(r.err, (dir / "nope.json").string() + ": cannot open");
}

TEST(Cli, UsageErrorsExit2) {
  const fs::path dir = scratch("usage");
  EXPECT_EQ(coilsim({}, dir).code, 2);
  Exec r = coilsim({"run", scene("default.json"), "--frobnicate"}, dir);
  EXPECT_EQ(r.code, 2);
  EXPECT_CONTAINS(r.err, "unknown option \"--frobnicate\"");
  EXPECT_EQ(coilsim({"--frobnicate"}, dir).code, 2);
  EXPECT_EQ(coilsim({"run"}, dir).code, 2);
  EXPECT_EQ(coilsim({"run", scene("default.json"), "--steps", "0"}, dir).code, 2);
  EXPECT_EQ(coilsim({"run", scene("default.json"), "--duration", "abc"}, dir).code, 2);
  EXPECT_EQ(coilsim({"run", scene("default.json"), "--duration", "1", "--steps", "3"}, dir).code, 2);
  EXPECT_EQ(coilsim({"run", scene("default.json"), "--out"}, dir).code, 2);
  r = coilsim({"run", scene("cantilever-static.json"), "--headless", "--steps", "3"}, dir);
  EXPECT_EQ(r.code, 2);
  EXPECT_CONTAINS(r.err, "this scene has \"solve\": \"static\"");
}

TEST(Cli, UnwritableOutExits2) {
  const fs::path dir = scratch("unwritable");
  const Exec r = coilsim({"run", scene("cantilever-static.json"), "--headless", "--out", "/nonexistent/dir/r.json"}, dir);
  EXPECT_EQ(r.code, 2);
  EXPECT_CONTAINS(r.err, "/nonexistent/dir/r.json");
}

TEST(Cli, HelpAndVersion) {
  const fs::path dir = scratch("help");
  Exec r = coilsim({"help"}, dir);
  EXPECT_EQ(r.code, 0);
  EXPECT_CONTAINS(r.out, "coilsim run SCENE");
  EXPECT_CONTAINS(r.out, "medium_density_g_cm3");  // effect parameters come from their ParamSpecs
  r = coilsim({"--version"}, dir);
  EXPECT_EQ(r.code, 0);
  EXPECT_CONTAINS(r.out, "coilsim ");
}

TEST(Cli, SceneAloneWithoutDisplayRunsOffScreen) {
  const fs::path dir = scratch("no_display");
  const Exec r = coilsim({scene("cantilever-static.json")}, dir);
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_CONTAINS(r.err, "no display");
  EXPECT_CONTAINS(r.out, "static, converged");
}

TEST(Cli, DurationAndStepsOverrideTheScene) {
  const fs::path dir = scratch("override");
  Exec r = coilsim({scene("default.json"), "--headless", "--steps", "7", "--out", (dir / "a.json").string()}, dir);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(readJson(dir / "a.json")["steps"], 7);
  r = coilsim({scene("default.json"), "--headless", "--duration=0.02", "--out=" + (dir / "b.json").string()}, dir);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NEAR(readJson(dir / "b.json")["time_s"].get<double>(), 0.02, 1e-12);
}

// A wire hit by a kilonewton: the first step is refused as a blow-up.
constexpr const char* kBlowUp = R"({
  "format": "coilsim-scene/1", "gravity_m_s2": [0, 0, -9.81], "solve": "dynamic",
  "time_step_s": 0.001, "duration_s": 0.01,
  "rods": [{"name": "wire", "length_mm": 10, "beams": 5, "rest_shape": {"type": "straight"},
            "material": {"young_modulus_gpa": 1, "poisson_ratio": 0.3, "density_g_cm3": 1},
            "section": {"wire_radius_mm": 0.1},
            "boundary": [{"node": 0, "type": "clamped"}],
            "loads": [{"node": "last", "force_N": [0, 0, 1000]}]}]
})";

TEST(Cli, RefusedStepExits1AndSaysWhere) {
  const fs::path dir = scratch("blowup");
  std::ofstream(dir / "blowup.json") << kBlowUp;
  const Exec r = coilsim({(dir / "blowup.json").string(), "--headless", "--out", (dir / "r.json").string()}, dir);
  EXPECT_EQ(r.code, 1);
  EXPECT_CONTAINS(r.err, "blowup.json: step 1 refused at t = 0 s: rod 'wire'");
  const json result = readJson(dir / "r.json");
  EXPECT_EQ(result["status"], "step_refused");
  EXPECT_EQ(result["stats"]["blowups"], 1);
}

TEST(Cli, UnconvergedStaticExits1) {
  const fs::path dir = scratch("static_fail");
  json doc = json::parse(kBlowUp);
  doc["solve"] = "static";
  doc["rods"][0]["boundary"][0]["type"] = "pinned";  // free to spin about the pin: no equilibrium
  std::ofstream(dir / "pinned.json") << doc.dump();
  const Exec r = coilsim({(dir / "pinned.json").string(), "--headless", "--out", (dir / "r.json").string()}, dir);
  EXPECT_EQ(r.code, 1);
  EXPECT_CONTAINS(r.err, "pinned.json: static solve did not converge: rod 'wire'");
  EXPECT_EQ(readJson(dir / "r.json")["status"], "not_converged");
}

}  // namespace
