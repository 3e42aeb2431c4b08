// Result files: the final state in millimetres, written atomically.
#include "io/result.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <unistd.h>

#include "io/json_writer.h"
#include "io/expect_error.h"

namespace coilsim::io {
namespace {

namespace fs = std::filesystem;

// A straight 10 mm rod of 2 beams, clamped at node 0, nothing acting on it.
Model smallModel() {
  ModelDef d;
  RodDef r;
  r.name = "wire";
  r.length = 0.01;
  r.beams = 2;
  r.rest = makeStraight(r.length, r.beams);
  r.material = {1e9, shearModulusOf(1e9, 0.3), 1000};
  r.section = circularSection(1e-4, 0.3);
  r.constraints.push_back({0, kAllDofs});
  r.placement.position = Vec3(0.001, 0, 0);
  d.rods.push_back(r);
  return compileModel(d);
}

fs::path freshDir(const std::string& name) {
  const fs::path dir = fs::path(testing::TempDir()) / ("coilsim_io_" + name + "." + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

TEST(Result, HoldsNodesInMillimetresAndRotationsWFirst) {
  const Model m = smallModel();
  State s = makeState(m);
  s.rods[0].q[2] = Quat(Eigen::AngleAxisd(M_PI / 2, Vec3::UnitZ()));
  RunRecord run;
  run.scene = "scenes/x.json";
  run.sceneName = "x";
  run.warnings = {"scene warning"};
  s.warnings = {"state warning"};
  const nlohmann::ordered_json j = resultJson(m, s, run);
  EXPECT_EQ(j["format"], "coilsim-result/1");
  EXPECT_EQ(j["scene"], "scenes/x.json");
  EXPECT_EQ(j["status"], "ok");
  EXPECT_FALSE(j.contains("static"));
  EXPECT_FALSE(j.contains("error"));
  const auto& rod = j["rods"][0];
  EXPECT_EQ(rod["name"], "wire");
  ASSERT_EQ(rod["nodes_mm"].size(), 3u);
  EXPECT_DOUBLE_EQ(rod["nodes_mm"][0][0].get<double>(), 1.0);
  EXPECT_DOUBLE_EQ(rod["nodes_mm"][2][0].get<double>(), 11.0);
  EXPECT_NEAR(rod["rotations"][2][0].get<double>(), std::sqrt(0.5), 1e-15);  // w
  EXPECT_NEAR(rod["rotations"][2][3].get<double>(), std::sqrt(0.5), 1e-15);  // z
  for (const char* key : {"kinetic_J", "elastic_J", "potential_J", "total_J"}) EXPECT_TRUE(j["energy"].contains(key));
  for (const char* key : {"mean_step_us", "max_step_us", "newton_iterations", "blowups"}) EXPECT_TRUE(j["stats"].contains(key));
  ASSERT_EQ(j["warnings"].size(), 2u);
  EXPECT_EQ(j["warnings"][1], "state warning");
}

TEST(Result, StaticRunsReportTheSolver) {
  const Model m = smallModel();
  State s = makeState(m);
  RunRecord run;
  run.solve = SolveMode::Static;
  run.statics = StaticReport{4, 9, 1.0, std::nullopt};  // converged: no failure
  const nlohmann::ordered_json j = resultJson(m, s, run);
  EXPECT_EQ(j["solve"], "static");
  EXPECT_EQ(j["static"]["converged"], true);
  EXPECT_EQ(j["static"]["increments"], 4);
  EXPECT_EQ(j["static"]["iterations"], 9);
}

TEST(Result, StateHashSeesEveryBitAndOnlyTheState) {
  const Model m = smallModel();
  State a = makeState(m), b = makeState(m);
  EXPECT_EQ(stateHash(a), stateHash(b));
  EXPECT_EQ(stateHash(a).size(), 16u);
  b.time = 5;  // not part of the hash: poses and velocities are
  EXPECT_EQ(stateHash(a), stateHash(b));
  for (int field = 0; field < 4; ++field) {
    State c = makeState(m);
    // The smallest change a double can make, in each array.
    double& v = field == 0 ? c.rods[0].x[1].y() : field == 1 ? c.rods[0].q[1].x() : field == 2 ? c.rods[0].v[2].z() : c.rods[0].w[0].x();
    v = std::nextafter(v, 1.0);
    EXPECT_NE(stateHash(a), stateHash(c)) << "field " << field;
  }
  // FNV-1a 64 of no bytes is its offset basis.
  EXPECT_EQ(stateHash(State{}), "cbf29ce484222325");
  EXPECT_EQ(resultJson(m, a, RunRecord{})["state_hash"], stateHash(a));
}

TEST(Result, ListsActiveNodesAndTheDeployment) {
  const Model m = smallModel();
  State s = makeState(m);
  s.rods[0].activeNodes = 2;
  RunRecord run;
  run.deployment = DeviceState{};
  run.deployment->deployed = 0.0125;
  run.deployment->twist = M_PI / 2;
  run.deployment->tipOffset = 0.001;
  const nlohmann::ordered_json j = resultJson(m, s, run);
  EXPECT_EQ(j["rods"][0]["nodes_mm"].size(), 2u);
  EXPECT_EQ(j["rods"][0]["rotations"].size(), 2u);
  EXPECT_FALSE(j["rods"][0].contains("active"));
  EXPECT_DOUBLE_EQ(j["deployment"]["deployed_mm"].get<double>(), 12.5);
  EXPECT_DOUBLE_EQ(j["deployment"]["twist_deg"].get<double>(), 90.0);
  EXPECT_EQ(j["deployment"]["detached"], false);
  EXPECT_DOUBLE_EQ(j["deployment"]["tip_offset_mm"].get<double>(), 1.0);
  s.rods[0].active = false;
  const nlohmann::ordered_json k = resultJson(m, s, RunRecord{});
  EXPECT_EQ(k["rods"][0]["active"], false);
  EXPECT_TRUE(k["rods"][0]["nodes_mm"].empty());
  EXPECT_FALSE(k.contains("deployment"));
}

TEST(Result, IsWrittenAtomicallyAndReadsBack) {
  const fs::path dir = freshDir("atomic");
  const fs::path file = dir / "result.json";
  const Model m = smallModel();
  const State s = makeState(m);
  RunRecord run;
  run.scene = "x.json";
  writeResult(file.string(), m, s, run);
  writeResult(file.string(), m, s, run);  // replacing an existing result works too
  const nlohmann::json back = readJsonFile(file.string());
  EXPECT_EQ(back["rods"][0]["nodes_mm"].size(), 3u);
  int files = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir)) ++files;
  EXPECT_EQ(files, 1) << "a temporary file was left behind";
}

TEST(Result, UnwritablePathThrowsNamingIt) {
  try {
    writeFileAtomic("/nonexistent/dir/result.json", "{}");
    ADD_FAILURE() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_CONTAINS(e.what(), "/nonexistent/dir/result.json");
  }
}

TEST(Result, FormattingKeepsPointsOnOneLineAndRoundTrips) {
  const nlohmann::json j = nlohmann::json::parse(R"({"a": [[1.5, 2, 3], [4, 5, 6]], "b": {"c": "d"}, "e": []})");
  const std::string text = formatJson(j);
  EXPECT_CONTAINS(text, "[1.5, 2, 3]");
  EXPECT_EQ(nlohmann::json::parse(text), j);
}

}  // namespace
}  // namespace coilsim::io
