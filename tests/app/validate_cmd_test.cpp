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
  EXPECT_TRUE(j["baseline"]["fitted"].contains("young_modulus"));
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

}  // namespace
}  // namespace apptest
