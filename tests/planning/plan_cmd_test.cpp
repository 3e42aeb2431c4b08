// `coilsim plan` and `coilsim practice` run as a user runs them.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <unistd.h>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

namespace {

namespace fs = std::filesystem;
const std::string kBinary = COILSIM_BINARY;
const std::string kSource = COILSIM_SOURCE_DIR;

// A path of this process alone: ctest runs these tests in parallel processes, and builds side by side run them too.
fs::path scratch(const std::string& name) {
  return fs::path(testing::TempDir()) / (name + "." + std::to_string(::getpid()));
}

int run(const std::string& args, std::string* output = nullptr) {
  const std::string log = scratch("coilsim-plan-test.log").string();
  const int status = std::system((kBinary + " " + args + " > " + log + " 2>&1").c_str());
  if (output) {
    std::ifstream in(log);
    std::stringstream s;
    s << in.rdbuf();
    *output = s.str();
  }
  return WEXITSTATUS(status);
}

// Whether this build draws (plan's pictures): CMake says, from the build's
// file sets (tests/planning/CMakeLists.txt).
bool haveUi() { return COILSIM_TESTS_HAVE_UI != 0; }

TEST(PlanCommand, TwoCoilsGiveTheTableAndTheImages) {
  const fs::path out = scratch("coilsim-plan-test");
  fs::remove_all(out);
  std::string log;
  const int code = run("plan " + kSource + "/scenes/cases/sphere-7mm-wide-neck.json --coils finishing-2x10,finishing-3x40 " +
                           "--jobs 2 --speed 10 --size 320x240 --out " + out.string(),
                       &log);
  ASSERT_EQ(code, 0) << log;
  std::ifstream in(out / "plan.json");
  const nlohmann::json plan = nlohmann::json::parse(in);
  ASSERT_EQ(plan["coils"].size(), 2u);
  // The spherical sac closed by the neck plane: 4/3 pi R^3 minus the cap of height R + z.
  const double R = 3.5, hc = R - 2.5;
  const double sac = 4.0 / 3.0 * M_PI * R * R * R - M_PI * hc * hc * (3 * R - hc) / 3.0;
  const bool ui = haveUi();
  for (const auto& c : plan["coils"]) {
    EXPECT_TRUE(c["ok"].get<bool>()) << c.dump();
    EXPECT_NEAR(c["sac_volume_mm3"].get<double>(), sac, 0.01 * sac);
    const double pd = c["packing_percent"].get<double>() / 100;
    EXPECT_GE(pd, 0.0);
    EXPECT_LE(pd, 1.0);
    // Packing is the coil volume over the sac volume, and the coil volume pi r^2 l of what is inside.
    EXPECT_NEAR(pd, c["coil_volume_mm3"].get<double>() / c["sac_volume_mm3"].get<double>(), 1e-4 * pd + 1e-9);
    EXPECT_NEAR(c["coil_volume_mm3"].get<double>(), M_PI * 0.127 * 0.127 * c["coil_length_in_sac_mm"].get<double>(),
                1e-4 * c["coil_volume_mm3"].get<double>() + 1e-9);
    EXPECT_TRUE(c.contains("protruding") && c["protruding"].is_boolean());
    EXPECT_TRUE(c["placed"].get<bool>()) << c.dump();
    // Deployed with wall contact: a wall force is measured, not left unknown.
    ASSERT_FALSE(c["max_wall_force_mN"].is_null()) << c.dump();
    EXPECT_GE(c["max_wall_force_mN"].get<double>(), 0.0);
    // And the wire stayed out of the wall: under 10 % of its radius (the
    // contact issue's bound), the record of every step's detection.
    ASSERT_TRUE(c["max_wall_penetration_of_radius"].is_number()) << c.dump();
    EXPECT_LT(c["max_wall_penetration_of_radius"].get<double>(), 0.1) << c.dump();
    EXPECT_NEAR(c["max_wall_penetration_um"].get<double>(), 1e3 * 0.127 * c["max_wall_penetration_of_radius"].get<double>(),
                0.01 + 1e-3 * c["max_wall_penetration_um"].get<double>());
    EXPECT_TRUE(c.contains("kickback_mm"));
    if (ui) {
      ASSERT_TRUE(c.contains("screenshot")) << c.dump();
      EXPECT_GT(fs::file_size(out / c["screenshot"].get<std::string>()), 1000u);
    }
  }
  EXPECT_EQ(plan["coils"][0]["name"], "finishing-2x10");
  EXPECT_TRUE(fs::exists(out / "plan.md"));

  // Two halves of a sweep merge into one table.
  const fs::path out2 = scratch("coilsim-plan-test-merged");
  fs::remove_all(out2);
  ASSERT_EQ(run("plan-merge " + out.string() + " " + out.string() + " --out " + out2.string(), &log), 0) << log;
  std::ifstream in2(out2 / "plan.json");
  EXPECT_EQ(nlohmann::json::parse(in2)["coils"].size(), 4u);
  fs::remove_all(out);
  fs::remove_all(out2);
}

nlohmann::json readPlan(const fs::path& dir) {
  std::ifstream in(dir / "plan.json");
  return nlohmann::json::parse(in);
}

TEST(PlanCommand, SequenceKeepsEarlierCoilsAndMergeEqualsOneRun) {
  const std::string c = kSource + "/scenes/cases/sphere-7mm-wide-neck.json";
  const std::string opts = " --speed 10 --no-screenshots --out ";
  const fs::path one = scratch("coilsim-plan-seq-one"), a = scratch("coilsim-plan-seq-a"), b = scratch("coilsim-plan-seq-b"),
                 merged = scratch("coilsim-plan-seq-merged");
  for (const fs::path& d : {one, a, b, merged}) fs::remove_all(d);
  std::string log;
  // One run of two candidates on two threads: a coil, and the same coil twice in a row.
  ASSERT_EQ(run("plan " + c + " --coils finishing-2x10,finishing-2x10+finishing-2x10 --jobs 2" + opts + one.string(), &log), 0)
      << log;
  // The same as two "array tasks", merged.
  ASSERT_EQ(run("plan " + c + " --coils finishing-2x10" + opts + a.string(), &log), 0) << log;
  ASSERT_EQ(run("plan " + c + " --coils finishing-2x10+finishing-2x10" + opts + b.string(), &log), 0) << log;
  ASSERT_EQ(run("plan-merge " + a.string() + " " + b.string() + " --out " + merged.string(), &log), 0) << log;
  nlohmann::json whole = readPlan(one), parts = readPlan(merged);
  ASSERT_EQ(whole["coils"].size(), 2u);
  ASSERT_EQ(parts["coils"].size(), 2u);
  EXPECT_EQ(parts["scene"], whole["scene"]);
  EXPECT_EQ(parts["sac_volume_mm3"], whole["sac_volume_mm3"]);
  for (size_t i = 0; i < 2; ++i) {
    nlohmann::json w = whole["coils"][i], p = parts["coils"][i];
    // Wall-clock times of the run and of its parts: the only things that may differ.
    for (const char* clock : {"wall_s", "step_wall_s", "operator_wall_s"}) w.erase(clock), p.erase(clock);
    EXPECT_EQ(w, p) << w.dump() << "\n" << p.dump();
  }
  // Both coils stay in the closed surface (the wall holds them), so what is in the sac plus what
  // protrudes below the neck plane is all the coil: 10 mm for one coil, 20 mm for the sequence.
  const auto& single = whole["coils"][0];
  const auto& sequence = whole["coils"][1];
  EXPECT_EQ(sequence["name"], "finishing-2x10 + finishing-2x10");
  EXPECT_TRUE(single["placed"].get<bool>()) << single.dump();
  EXPECT_TRUE(sequence["placed"].get<bool>()) << sequence.dump();
  for (const auto& [coil, length] : {std::pair{single, 10.0}, std::pair{sequence, 20.0}}) {
    const double inside = coil["coil_length_in_sac_mm"].get<double>() + coil["protruding_length_mm"].get<double>();
    EXPECT_NEAR(inside, length, 0.02 * length) << coil.dump();
    EXPECT_FALSE(coil["max_wall_force_mN"].is_null()) << "plans run with wall contact";
  }
  for (const fs::path& d : {one, a, b, merged}) fs::remove_all(d);
}

TEST(PlanCommand, ACoilThatMeetsResistanceEverywhereIsReportedNotPlaced) {
  // A threshold of 1 uN: any load on the tip is "resistance". The operator twists three times,
  // pulls back and re-advances three times, then gives the coil up instead of pushing for ever.
  const fs::path out = scratch("coilsim-plan-not-placed");
  fs::remove_all(out);
  std::string log;
  ASSERT_EQ(run("plan " + kSource + "/scenes/cases/sphere-7mm-wide-neck.json --coils finishing-2x10 --speed 10 " +
                    "--force-threshold 0.001 --no-screenshots --out " + out.string(),
                &log),
            0)
      << "not placed is an outcome of the plan, not a failure\n" << log;
  const auto c = readPlan(out)["coils"][0];
  EXPECT_TRUE(c["ok"].get<bool>()) << c.dump();
  EXPECT_FALSE(c["placed"].get<bool>()) << c.dump();
  ASSERT_TRUE(c.contains("not_placed")) << c.dump();
  EXPECT_NE(c["not_placed"].get<std::string>().find("does not fit"), std::string::npos) << c.dump();
  EXPECT_EQ(c["pull_backs"].get<int>(), 3) << c.dump();
  EXPECT_LT(c["deployed_mm"].get<double>(), 10.0);
  // Given up by the operator, well before the time limit (60 s + 4 L / speed = 64 s) would stop it.
  EXPECT_LT(c["simulated_s"].get<double>(), 30.0) << c.dump();
  std::ifstream md(out / "plan.md");
  std::stringstream text;
  text << md.rdbuf();
  EXPECT_NE(text.str().find("not placed: the coil does not fit"), std::string::npos) << text.str();
  fs::remove_all(out);
}

// The 7 mm case with its own sequences replaced: written beside the test's plans.
fs::path caseWithSequences(const std::string& name, const nlohmann::json& sequences) {
  std::ifstream in(kSource + "/scenes/cases/sphere-7mm-wide-neck.json");
  nlohmann::json doc = nlohmann::json::parse(in);
  doc["sequences"] = sequences;
  const fs::path file = scratch(name) / "case.json";
  fs::create_directories(file.parent_path());
  std::ofstream(file) << doc.dump(1);
  return file;
}

TEST(PlanCommand, ACasesSequenceIsPlannedByNameOrFirst) {
  const nlohmann::json sequences = {{{"name", "short"}, {"coils", {"finishing-2x10", "finishing-2x10"}}},
                                    {{"name", "other"}, {"coils", {"finishing-2x10"}}}};
  const fs::path c = caseWithSequences("coilsim-plan-sequences", sequences);
  const fs::path first = c.parent_path() / "first", named = c.parent_path() / "named";
  std::string log;
  // No --coils: the case's first sequence, as one run into one sac.
  ASSERT_EQ(run("plan " + c.string() + " --no-screenshots --out " + first.string(), &log), 0) << log;
  const nlohmann::json a = readPlan(first)["coils"];
  ASSERT_EQ(a.size(), 1u) << a.dump();
  EXPECT_EQ(a[0]["name"], "finishing-2x10 + finishing-2x10");
  EXPECT_EQ(a[0]["sequence"], "short");
  EXPECT_TRUE(a[0]["placed"].get<bool>()) << a.dump();
  ASSERT_EQ(run("plan " + c.string() + " --sequence other --no-screenshots --out " + named.string(), &log), 0) << log;
  const nlohmann::json b = readPlan(named)["coils"];
  ASSERT_EQ(b.size(), 1u) << b.dump();
  EXPECT_EQ(b[0]["name"], "finishing-2x10");
  EXPECT_EQ(b[0]["sequence"], "other");
  fs::remove_all(c.parent_path());
}

TEST(PlanCommand, AnUnknownSequenceOrACoilOutsideTheSetExitsTwo) {
  const fs::path c = caseWithSequences("coilsim-plan-bad-sequence", {{{"name", "s"}, {"coils", {"finishing-2x10"}}}});
  const std::string out = " --out " + (c.parent_path() / "plan").string();
  std::string log;
  EXPECT_EQ(run("plan " + c.string() + " --sequence nope" + out, &log), 2);
  EXPECT_NE(log.find(c.string() + ": no sequence called \"nope\""), std::string::npos) << log;
  EXPECT_NE(log.find("it has: s"), std::string::npos) << log;
  EXPECT_EQ(run("plan " + c.string() + " --sequence s --coils finishing-2x10" + out, &log), 2);
  EXPECT_NE(log.find("not both"), std::string::npos) << log;
  const fs::path bad = caseWithSequences("coilsim-plan-bad-sequence2",
                                         {{{"name", "s"}, {"coils", {"finishing-2x10", "framing-complex-10x300"}}}});
  EXPECT_EQ(run("plan " + bad.string() + out, &log), 2);
  EXPECT_NE(log.find(bad.string() + ": /sequences/0/coils/1"), std::string::npos) << log;
  EXPECT_NE(log.find("not in the case's coil set"), std::string::npos) << log;
  fs::remove_all(c.parent_path());
  fs::remove_all(bad.parent_path());
}

TEST(PlanCommand, BadInputExitsTwoNamingTheProblem) {
  std::string log;
  EXPECT_EQ(run("plan " + kSource + "/scenes/cases/sphere-7mm-wide-neck.json --coils no-such-coil --out /tmp/x", &log), 2);
  EXPECT_NE(log.find("no-such-coil"), std::string::npos) << log;
  EXPECT_EQ(run("plan " + kSource + "/scenes/free-deploy-helix.json --coils finishing-2x10 --out /tmp/x", &log), 2);
  EXPECT_NE(log.find("--sac"), std::string::npos) << log;
  EXPECT_EQ(run("plan --out /tmp/x", &log), 2);
  EXPECT_EQ(run("practice " + kSource + "/scenes/cases/sphere-7mm-wide-neck.json --out /tmp/x.json", &log), 2);
  // An unwritable session or score file is refused before the session (a
  // window would otherwise lose a whole practice to a typo at its end); a
  // build without graphics checks it on a scripted session.
  const std::string session = haveUi() ? " --window "
                                       : " --coil finishing-2x10 --input " + kSource + "/timelines/practice-finishing-3x40.json ";
  for (const char* opt : {"--record", "--out"}) {
    const std::string other = std::string(opt) == "--out" ? "" : " --out " + (scratch("coilsim-practice-out") / "s.json").string();
    EXPECT_EQ(run("practice " + kSource + "/scenes/cases/sphere-7mm-wide-neck.json" + session + std::string(opt) +
                      " /no-such-dir/s.json" + (haveUi() ? "" : other),
                  &log),
              2)
        << opt;
    EXPECT_NE(log.find("/no-such-dir/s.json: the directory /no-such-dir does not exist"), std::string::npos) << log;
  }
}

TEST(PracticeCommand, ReplayWritesTheSameScoreSheet) {
  const fs::path dir = scratch("coilsim-practice-test");
  fs::remove_all(dir);
  fs::create_directories(dir);
  {
    std::ofstream t(dir / "timeline.json");
    t << R"({"format": "coilsim-timeline/1", "commands": [
      {"t_s": 0.0, "push": {"speed_mm_s": 10}}, {"t_s": 1.5, "detach": {}}]})";
  }
  const std::string c = kSource + "/scenes/cases/sphere-7mm-wide-neck.json";
  std::string log;
  const bool ui = haveUi();
  const std::string shot = ui ? " --screenshot " + (dir / "xray.png").string() : std::string();
  ASSERT_EQ(run("practice " + c + " --coil finishing-2x10 --view xray --input " + (dir / "timeline.json").string() +
                    " --record " + (dir / "session.json").string() + shot + " --out " + (dir / "score.json").string(),
                &log),
            0)
      << log;
  // The last frame in the X-ray view, with the live read-outs in the panel.
  if (ui) {
    EXPECT_GT(fs::file_size(dir / "xray.png"), 1000u);
  }
  // The window records a session by hand (or typed by --input); replaying one is headless.
  EXPECT_EQ(run("practice " + c + " --window --replay " + (dir / "session.json").string(), &log), 2);
  EXPECT_NE(log.find("--replay"), std::string::npos) << log;
  ASSERT_EQ(run("practice " + c + " --replay " + (dir / "session.json").string() + " --out " +
                    (dir / "replayed.json").string(),
                &log),
            0)
      << log;
  auto read = [](const fs::path& p) {
    std::ifstream in(p);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
  };
  EXPECT_EQ(read(dir / "score.json"), read(dir / "replayed.json"));
  EXPECT_NE(read(dir / "score.json").find("\"fluoroscopy_time_s\": 2.5"), std::string::npos) << read(dir / "score.json");
  fs::remove_all(dir);
}

}  // namespace
