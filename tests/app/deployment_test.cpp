// `coilsim run SCENE --input TIMELINE`, by running the real binary: a coil
// pushed out of a catheter, bit-for-bit replay, refused commands that do
// not stop the run, and bad timelines that do.
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

// A small coil (30 mm, 30 beams, 7 mm loops) behind a rigid catheter tip, in water.
constexpr const char* kScene = R"({
  "format": "coilsim-scene/1",
  "name": "small-deploy",
  "gravity_m_s2": [0, 0, -9.81],
  "solve": "dynamic",
  "time_step_s": 0.001,
  "duration_s": 0.5,
  "damping": {"rayleigh_mass_1_s": 1.0},
  "effects": {"gravity": {}, "buoyancy": {"medium_density_g_cm3": 1.0}, "drag": {}},
  "deployment": {
    "coil": {
      "name": "coil", "length_mm": 30, "beams": 30,
      "rest_shape": {"type": "helix", "loop_diameter_mm": 7, "pitch_mm": 0.96, "handedness": "right"},
      "material": {"young_modulus_gpa": 7.5, "poisson_ratio": 0.39, "density_g_cm3": 21.45},
      "section": {"wire_radius_mm": 0.1}
    },
    "catheter": {"type": "rigid", "tip_position_mm": [0, 0, 0], "direction": [1, 0, 0], "reference_normal": [0, 0, 1]}
  }
})";

std::string timeline(const std::string& commands) {
  return R"({"format": "coilsim-timeline/1", "commands": [)" + commands + "]}";
}

struct Files {
  fs::path dir, scene, timeline, out;
};

Files write(const std::string& name, const std::string& timelineText, const std::string& sceneText = kScene) {
  Files f;
  f.dir = scratch(name);
  f.scene = f.dir / "scene.json";
  f.timeline = f.dir / "timeline.json";
  f.out = f.dir / "r.json";
  std::ofstream(f.scene) << sceneText;
  std::ofstream(f.timeline) << timelineText;
  return f;
}

Exec run(const Files& f, std::vector<std::string> extra = {}) {
  std::vector<std::string> args{"run", f.scene.string(), "--headless", "--input", f.timeline.string(), "--out",
                                f.out.string()};
  args.insert(args.end(), extra.begin(), extra.end());
  return coilsim(args, f.dir);
}

TEST(Deployment, PushedLengthIsSpeedTimesTime) {
  const Files f = write("push", timeline(R"({"t_s": 0, "push": {"speed_mm_s": 10}})"));
  const Exec r = run(f);
  ASSERT_EQ(r.code, 0) << r.err;
  const json result = readJson(f.out);
  EXPECT_EQ(result["status"], "ok");
  EXPECT_EQ(result["steps"], 500);
  // 10 mm/s for the scene's 0.5 s.
  EXPECT_NEAR(result["deployment"]["deployed_mm"].get<double>(), 5.0, 1e-9);
  EXPECT_EQ(result["deployment"]["twist_deg"], 0.0);
  EXPECT_EQ(result["deployment"]["detached"], false);
  EXPECT_EQ(result["deployment"]["tip_offset_mm"], 0.0);
  EXPECT_TRUE(result["warnings"].empty()) << result["warnings"];
  // The coil's rod holds the tip node and the nodes outside (1 mm apart): 5 or 6 of them.
  const json& coil = result["rods"][0];
  EXPECT_EQ(coil["name"], "coil");
  EXPECT_GE(coil["nodes_mm"].size(), 5u);
  EXPECT_LE(coil["nodes_mm"].size(), 6u);
  EXPECT_EQ(result["rods"][1]["active"], false);  // the detached copy, not in use yet
  for (const json& x : coil["nodes_mm"]) EXPECT_TRUE(std::isfinite(x[0].get<double>()));
  EXPECT_CONTAINS(r.out, "scene.json: dynamic, 500 of 500 steps");
  EXPECT_CONTAINS(r.out, "coil 5 of 30 mm out, twist 0 deg");
  // --duration overrides the scene's duration_s.
  const Exec shorter = run(f, {"--duration", "0.2"});
  ASSERT_EQ(shorter.code, 0) << shorter.err;
  EXPECT_NEAR(readJson(f.out)["deployment"]["deployed_mm"].get<double>(), 2.0, 1e-9);
}

TEST(Deployment, SameInputsReplayBitForBit) {
  const std::string commands = R"({"t_s": 0, "push": {"speed_mm_s": 20, "distance_mm": 6}},
                                  {"t_s": 0.1, "twist": {"rate_deg_s": 180, "angle_deg": 45}},
                                  {"t_s": 0.3, "pull": {"speed_mm_s": 5, "distance_mm": 1}})";
  const Files a = write("replay_a", timeline(commands)), b = write("replay_b", timeline(commands));
  const Exec ra = run(a), rb = run(b);
  ASSERT_EQ(ra.code, 0) << ra.err;
  ASSERT_EQ(rb.code, 0) << rb.err;
  const json ja = readJson(a.out), jb = readJson(b.out);
  ASSERT_TRUE(ja["state_hash"].is_string());
  EXPECT_EQ(ja["state_hash"].get<std::string>().size(), 16u);
  EXPECT_EQ(ja["state_hash"], jb["state_hash"]);
  EXPECT_EQ(ja["rods"], jb["rods"]);
  EXPECT_NEAR(ja["deployment"]["deployed_mm"].get<double>(), 5.0, 1e-9);
  EXPECT_NEAR(ja["deployment"]["twist_deg"].get<double>(), 45.0, 1e-9);
  // The hash sees a different history: the same pushes without the twist.
  const Files c = write("replay_c", timeline(R"({"t_s": 0, "push": {"speed_mm_s": 20, "distance_mm": 6}},
                                                 {"t_s": 0.3, "pull": {"speed_mm_s": 5, "distance_mm": 1}})"));
  ASSERT_EQ(run(c).code, 0);
  EXPECT_NE(readJson(c.out)["state_hash"], ja["state_hash"]);
}

TEST(Deployment, RefusedCommandsAreReportedAndTheRunGoesOn) {
  const Files f = write("refused", timeline(R"(
    {"t_s": 0, "push": {"speed_mm_s": 50, "distance_mm": 40}},
    {"t_s": 0.01, "detach": {}},
    {"t_s": 0.02, "push": {"speed_mm_s": 50, "distance_mm": 30}},
    {"t_s": 0.7, "detach": {}},
    {"t_s": 0.8, "pull": {"speed_mm_s": 5, "distance_mm": 1}})"));
  const Exec r = run(f, {"--duration", "0.9"});
  ASSERT_EQ(r.code, 0) << r.err;
  // Each refusal says why, on stderr and in the result.
  EXPECT_CONTAINS(r.err, "timeline.json: /commands/0 (push at 50 mm/s by 40 mm) at t = 0 s: refused: ");
  EXPECT_CONTAINS(r.err, "timeline.json: /commands/4 (pull at 5 mm/s by 1 mm) at t = 0.8 s: refused: ");
  EXPECT_CONTAINS(r.err, "would pass the coil's end");
  EXPECT_CONTAINS(r.err, "not fully out");
  EXPECT_CONTAINS(r.err, "detached");
  const json result = readJson(f.out);
  EXPECT_EQ(result["status"], "ok");
  ASSERT_EQ(result["warnings"].size(), 3u) << result["warnings"];
  EXPECT_CONTAINS(result["warnings"][0].get<std::string>(), "would pass the coil's end");
  EXPECT_CONTAINS(result["warnings"][1].get<std::string>(), "not fully out");
  EXPECT_CONTAINS(result["warnings"][2].get<std::string>(), "detached");
  EXPECT_EQ(result["deployment"]["detached"], true);
  EXPECT_NEAR(result["deployment"]["deployed_mm"].get<double>(), 30.0, 1e-9);
  // After detach the coil is its own rod, all 31 nodes, and the pusher's chain is the tip alone.
  EXPECT_EQ(result["rods"][1]["nodes_mm"].size(), 31u);
  EXPECT_FALSE(result["rods"][1].contains("active"));
}

TEST(Deployment, MalformedTimelineExits2NamingTheFile) {
  const Files f = write("bad_timeline", timeline(R"({"t_s": 0, "push": {"speed_mm_s": -5}})"));
  const Exec r = run(f);
  EXPECT_EQ(r.code, 2);
  EXPECT_CONTAINS(r.err, f.timeline.string() + ": /commands/0/push/speed_mm_s: expected a finite number > 0, got -5");
  EXPECT_FALSE(fs::exists(f.out));
  const Files g = write("broken_timeline", "{\"format\": \"coilsim-timeline/1\", \"commands\": [");
  const Exec rg = run(g);
  EXPECT_EQ(rg.code, 2);
  EXPECT_CONTAINS(rg.err, g.timeline.string() + ": line 1, column");
  const Files h = write("missing_timeline", timeline(""));
  fs::remove(h.timeline);
  const Exec rh = run(h);
  EXPECT_EQ(rh.code, 2);
  EXPECT_CONTAINS(rh.err, h.timeline.string() + ": cannot open the file");
}

TEST(Deployment, TimelineOnASceneWithoutDeploymentExits2) {
  const Files f = write("no_deployment", timeline(R"({"t_s": 0, "stop": {}})"));
  const Exec r = coilsim({"run", scene("helix-rest.json"), "--headless", "--input", f.timeline.string()}, f.dir);
  EXPECT_EQ(r.code, 2);
  EXPECT_CONTAINS(r.err, f.timeline.string() + ": a timeline drives a coil deployment, but");
  EXPECT_CONTAINS(r.err, "has no \"deployment\" block");
  const Exec missing = coilsim({"run", scene("helix-rest.json"), "--headless", "--input"}, f.dir);
  EXPECT_EQ(missing.code, 2);
  EXPECT_CONTAINS(missing.err, "--input needs a timeline file");
}

TEST(Deployment, CommandsAfterTheEndAreReported) {
  const Files f = write("late", timeline(R"({"t_s": 0, "push": {"speed_mm_s": 10}}, {"t_s": 5, "stop": {}})"));
  const Exec r = run(f, {"--duration", "0.05"});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_CONTAINS(r.err, "timeline.json: /commands/1/t_s: 5 s is not before the end of the run (0.05 s): not run");
  EXPECT_EQ(readJson(f.out)["warnings"].size(), 1u);
}

// The shipped bench scene and its timeline, for the first second (5 mm out).
TEST(Deployment, ShippedHelixSceneAndTimelineRun) {
  const fs::path dir = scratch("shipped_helix");
  const Exec r = coilsim({"run", scene("free-deploy-helix.json"), "--headless", "--input",
                          kSource + "/timelines/push-helix.json", "--duration", "1", "--out", (dir / "r.json").string()},
                         dir);
  ASSERT_EQ(r.code, 0) << r.err;
  const json result = readJson(dir / "r.json");
  EXPECT_NEAR(result["deployment"]["deployed_mm"].get<double>(), 5.0, 1e-9);
  EXPECT_CONTAINS(r.err, "push-helix.json: /commands/1/t_s: 31 s is not before the end of the run (1 s): not run");
  // Without a timeline the scene runs as it starts: nothing pushed.
  const Exec still = coilsim({"run", scene("free-deploy-helix.json"), "--headless", "--steps", "10", "--out",
                              (dir / "still.json").string()},
                             dir);
  ASSERT_EQ(still.code, 0) << still.err;
  EXPECT_EQ(readJson(dir / "still.json")["deployment"]["deployed_mm"], 0.0);
}

}  // namespace
