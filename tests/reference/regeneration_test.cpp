// The committed reference measurements are what the generator makes, byte
// for byte, and every one of them is a well-formed coil-measurement/1 file.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

#include "experiment.h"
#include "noise.h"

namespace refrod {
namespace {

std::string slurp(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  std::ostringstream s;
  s << f.rdbuf();
  return s.str();
}

const std::string kDir = REFERENCE_DATA_DIR;

// control-1 is a cheap file (about 1.5 s): it goes through the whole
// chain (push continuation, contact search, sampling, noise, formatting).
// The dynamic files take tens of seconds and are regenerated only by
// scripts/make-reference-measurements.
TEST(ReferenceFiles, RegenerateControl1BitForBit) {
  for (const Scenario& sc : referenceScenarios()) {
    if (sc.name != "control-1") continue;
    const auto r = runExperiment(sc);
    EXPECT_EQ(measurementJson(sc, r), slurp(kDir + "/control-1.json"))
        << "regenerate with scripts/make-reference-measurements";
    EXPECT_EQ(truthJson(sc, r, std::vector<double>(sc.stages.size(), 0.0)), slurp(kDir + "/control-1.truth.json"));
    return;
  }
  FAIL() << "no control-1 scenario";
}

// The fields the format requires, with the promised ranges.
TEST(ReferenceFiles, EveryFileIsAWellFormedMeasurement) {
  std::set<std::string> names;
  for (const Scenario& sc : referenceScenarios()) {
    names.insert(sc.name);
    const std::string text = slurp(kDir + "/" + sc.name + ".json");
    ASSERT_FALSE(text.empty()) << sc.name;
    const auto j = nlohmann::json::parse(text);
    EXPECT_EQ(j.at("format"), "coil-measurement/1");
    EXPECT_EQ(j.at("name"), sc.name);
    const auto& coil = j.at("coil");
    const double E = coil.at("young_modulus_gpa");
    const double off = std::abs(E / sc.trueYoungGpa - 1);
    EXPECT_TRUE(off >= 0.15 && off <= 0.30) << sc.name << ": nominal E off by " << off;
    EXPECT_EQ(coil.at("density_g_cm3"), 21.45);
    const auto& stages = j.at("stages");
    ASSERT_GE(stages.size(), 3u) << sc.name;
    for (const auto& st : stages) {
      const auto& cl = st.at("centerline_mm");
      EXPECT_GE(cl.size(), 20u);
      EXPECT_LE(cl.size(), 60u);
      EXPECT_LE(double(st.at("deployed_length_mm")), double(coil.at("length_mm")));
      const double sigma = st.at("point_sigma_mm");
      EXPECT_TRUE(sigma >= 0.05 && sigma <= 0.1);
      if (st.contains("push_history")) {
        EXPECT_TRUE(st.at("capture_time_s").is_number());
      }
    }
    const auto truth = nlohmann::json::parse(slurp(kDir + "/" + sc.name + ".truth.json"));
    EXPECT_EQ(double(truth.at("coil").at("young_modulus_gpa")), sc.trueYoungGpa);
  }
  EXPECT_EQ(names.size(), 10u);
}

// The noise does not depend on the standard library: fixed values.
TEST(Noise, SequenceIsFixed) {
  // splitmix64's published first output for seed 0, and one for seed 42.
  Rng r0(0), r(42);
  EXPECT_EQ(r0.next(), 0xE220A8397B1DCDAFull);
  EXPECT_EQ(r.next(), 0xBDD732262FEB6E95ull);
  Rng g(7);
  double m = 0, v = 0;
  const int n = 20000;
  for (int i = 0; i < n; ++i) {
    const double x = g.normal();
    m += x, v += x * x;
  }
  m /= n, v = v / n - m * m;
  EXPECT_NEAR(m, 0.0, 0.03);  // 4 standard errors
  EXPECT_NEAR(v, 1.0, 0.04);
}

}  // namespace
}  // namespace refrod
