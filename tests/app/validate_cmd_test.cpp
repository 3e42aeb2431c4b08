// `coilsim validate` and `coilsim diagnose` run as a user runs them, on the
// shared control file (independent simulator) and on broken files.
#include "app/run_binary.h"

namespace apptest {
namespace {

const std::string kControl = kSource + "/../shared/data/measurements/control-helix-a.json";

TEST(ValidateCommand, ControlFileReportHasTheIssuesFields) {
  if (!fs::exists(kControl)) GTEST_SKIP() << kControl << " is absent (../shared/data not present): nothing checked";
  const fs::path dir = scratch("validate_control");
  const Exec r = coilsim({"validate", kControl, "--fit", "young_modulus", "--out", (dir / "out").string()}, dir);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_CONTAINS(r.err, "fit: evaluation");  // progress on stderr
  EXPECT_CONTAINS(r.err, "--fit young_modulus is the old name of young_modulus_gpa");
  const nlohmann::json j = readJson(dir / "out" / "report.json");
  ASSERT_EQ(j["stages"].size(), 3u);
  for (const auto& s : j["stages"]) {
    for (const char* k : {"name", "node_error_mean", "node_error_sd", "stage_error", "mean_displacement_mm", "mean_distance_mm"})
      EXPECT_TRUE(s.contains(k)) << k;
    // The independent simulator's README: a correct model with E fitted is within ~1 %.
    EXPECT_LT(s["stage_error"].get<double>(), 0.05);
  }
  // The fit moved E off the nominal 7.32 GPa and said how sure it is.
  const auto& e = j["fitted"]["young_modulus"];
  EXPECT_GT(e["sigma"].get<double>(), 0.0);
  EXPECT_GT(std::abs(e["value"].get<double>() - 7.32), 3 * e["sigma"].get<double>());
  EXPECT_EQ(j["effects"].size(), 0u);
  EXPECT_TRUE(fs::exists(dir / "out" / "report.md"));
  for (const auto& png : j["images"]) EXPECT_GT(fs::file_size(dir / "out" / png.get<std::string>()), 1000u);
}

TEST(ValidateCommand, WithoutFitNothingIsFitted) {
  if (!fs::exists(kControl)) GTEST_SKIP() << kControl << " is absent (../shared/data not present): nothing checked";
  const fs::path dir = scratch("validate_nofit");
  const Exec r = coilsim({"validate", kControl, "--effects", "buoyancy", "--out", (dir / "out").string(), "--no-plots"}, dir);
  ASSERT_EQ(r.code, 0) << r.err;
  const nlohmann::json j = readJson(dir / "out" / "report.json");
  EXPECT_TRUE(j["fitted"].empty());
  EXPECT_EQ(j["effects"], nlohmann::json::array({"buoyancy"}));
}

TEST(DiagnoseCommand, ControlFileHasNoSignificantEffect) {
  if (!fs::exists(kControl)) GTEST_SKIP() << kControl << " is absent (../shared/data not present): nothing checked";
  const fs::path dir = scratch("diagnose_control");
  const Exec r = coilsim({"diagnose", kControl, "--out", (dir / "out").string(), "--no-plots"}, dir);
  ASSERT_EQ(r.code, 0) << r.err;
  const nlohmann::json j = readJson(dir / "out" / "diagnosis.json");
  EXPECT_TRUE(j["baseline"]["fitted"].contains("young_modulus_gpa"));  // the scene key
  ASSERT_EQ(j["candidates"].size(), 5u);
  double previous = 2;
  for (const auto& c : j["candidates"]) {
    EXPECT_FALSE(c["significant"].get<bool>()) << c["effect"];
    EXPECT_LE(c["explained_fraction"].get<double>(), previous);  // best first
    previous = c["explained_fraction"].get<double>();
    if (c["refitted"].get<bool>()) {
      EXPECT_EQ(c["stage_error_after"].size(), 3u);
    }
  }
  EXPECT_TRUE(j["fingerprint"].contains("summary"));
}

// Several files of one coil: the same coil in water and in air (the
// independent reference rod's files). One E cannot fit both; buoyancy at
// each file's declared medium makes one E fit them, and the report says so.
TEST(DiagnoseCommand, TwoFilesOfOneCoilAreFittedJointly) {
  const fs::path dir = scratch("diagnose_joint");
  const std::string ref = kSource + "/tests/data/reference/";
  const Exec r = coilsim({"diagnose", ref + "buoyancy-water.json", ref + "buoyancy-air.json", "--candidates",
                          "buoyancy", "--out", (dir / "out").string(), "--no-plots", "--quiet"},
                         dir);
  ASSERT_EQ(r.code, 0) << r.err;
  const nlohmann::json j = readJson(dir / "out" / "diagnosis.json");
  ASSERT_EQ(j["files"].size(), 2u);
  for (const auto& f : j["files"]) {
    EXPECT_TRUE(f["baseline"].contains("prior_check"));
    EXPECT_TRUE(f["adequacy"].contains("verdict"));
    EXPECT_TRUE(f["prediction"]["done"].get<bool>());
  }
  const auto& joint = j["joint"];
  EXPECT_TRUE(joint["spread"][0]["must_differ"].get<bool>()) << joint["verdict"];
  ASSERT_FALSE(joint["effects"].empty());
  EXPECT_EQ(joint["effects"][0]["effect"], "buoyancy");
  EXPECT_TRUE(joint["effects"][0]["removes_spread"].get<bool>());
  EXPECT_CONTAINS(r.out, "joint: young_modulus_gpa must differ");
}

TEST(ValidateCommand, BadFileNamesTheFieldAndExits2) {
  const fs::path dir = scratch("validate_bad");
  std::ofstream(dir / "bad.json") << R"({"format": "coil-measurement/1", "name": "x", "coil": {"length_mm": "long"}})";
  const Exec r = coilsim({"validate", (dir / "bad.json").string(), "--out", (dir / "out").string()}, dir);
  EXPECT_EQ(r.code, 2);
  EXPECT_CONTAINS(r.err, "bad.json");
  EXPECT_CONTAINS(r.err, "/coil/");
  const Exec d = coilsim({"diagnose", (dir / "missing.json").string(), "--out", (dir / "out").string()}, dir);
  EXPECT_EQ(d.code, 2);
  EXPECT_CONTAINS(d.err, "missing.json");
}

TEST(ValidateCommand, BadOptionsExit2) {
  const fs::path dir = scratch("validate_opts");
  if (!fs::exists(kControl)) GTEST_SKIP() << kControl << " is absent (../shared/data not present): nothing checked";
  EXPECT_EQ(coilsim({"validate", kControl}, dir).code, 2);  // no --out
  const Exec e = coilsim({"validate", kControl, "--effects", "warp_drive", "--out", (dir / "o").string()}, dir);
  EXPECT_EQ(e.code, 2);
  EXPECT_CONTAINS(e.err, "warp_drive");
  const Exec f = coilsim({"validate", kControl, "--fit", "colour", "--out", (dir / "o").string()}, dir);
  EXPECT_EQ(f.code, 2);
  EXPECT_CONTAINS(f.err, "colour");
}

const std::string kExample = kSource + "/examples/measurements/soft-catheter-helix.json";

// --size as run reads it (the same refusal, word for word), for the panel only.
TEST(ValidatePanel, SizeIsCheckedAsRunChecksItAndNeedsThePanel) {
  const fs::path dir = scratch("validate_panel_size");
  const Exec r = coilsim({"run", kSource + "/scenes/default.json", "--size", "8x480"}, dir);
  const Exec v = coilsim({"validate", kExample, "--window", "--size", "8x480"}, dir);
  EXPECT_EQ(v.code, 2);
  const std::string said = "--size needs WIDTHxHEIGHT in pixels, each in [16, 16384], got \"8x480\"";
  EXPECT_CONTAINS(r.err, said);
  EXPECT_CONTAINS(v.err, said);
  const Exec n = coilsim({"validate", kExample, "--size", "640x480", "--out", (dir / "o").string()}, dir);
  EXPECT_EQ(n.code, 2);
  EXPECT_CONTAINS(n.err, "--size sizes the panel");
}

TEST(ValidatePanel, ScriptOptionsNeedThePanel) {
  const fs::path dir = scratch("validate_panel_opts");
  const Exec r = coilsim({"validate", kExample, "--toggle", "drag", "--out", (dir / "o").string()}, dir);
  EXPECT_EQ(r.code, 2);
  EXPECT_CONTAINS(r.err, "--window");
  const Exec u = coilsim({"validate", kExample, "--screenshot", (dir / "p.png").string(), "--toggle", "warp_drive"}, dir);
  EXPECT_EQ(u.code, 2);
  EXPECT_CONTAINS(u.err, "warp_drive");
}

}  // namespace
}  // namespace apptest
