// The coil catalogue: every shipped coil reads, its stiffness is the wound
// spring's (checked against the textbook forms), bad files name file and field.
#include "io/coil_catalogue.h"

#include <cmath>
#include <filesystem>

#include <gtest/gtest.h>

namespace coilsim::io {
namespace {

const std::string kCatalogue = std::string(COILSIM_SOURCE_DIR) + "/assets/coils";

TEST(CoilCatalogue, ShippedCoilsReadAndSpanTheClinicalRanges) {
  const std::vector<CoilSpec> coils = loadCatalogue(kCatalogue);
  ASSERT_GE(coils.size(), 6u);
  double minLoop = 1e9, maxLoop = 0, minLen = 1e9, maxLen = 0;
  bool families[3] = {}, shapes[4] = {};
  for (const CoilSpec& c : coils) {
    minLoop = std::min(minLoop, c.loopDiameterMm), maxLoop = std::max(maxLoop, c.loopDiameterMm);
    minLen = std::min(minLen, c.lengthMm), maxLen = std::max(maxLen, c.lengthMm);
    families[int(c.family)] = shapes[int(c.shape)] = true;
    EXPECT_FALSE(c.sources.empty()) << c.file;
  }
  EXPECT_LE(minLoop, 2.0);
  EXPECT_GE(maxLoop, 20.0);
  EXPECT_LE(minLen, 10.0);   // 1 cm
  EXPECT_GE(maxLen, 500.0);  // 50 cm
  for (bool f : families) EXPECT_TRUE(f);
  for (bool s : shapes) EXPECT_TRUE(s);
}

TEST(CoilCatalogue, WoundSpringRigiditiesMatchTheTextbookForms) {
  // Timoshenko & Gere eq. 2-63: beta = 2 l E I / (pi n D (2 + nu)), I = pi d^4 / 64,
  // for a spring of length l with n turns; close-coiled, l = n d. Check with n = 1000 turns.
  const double d = 0.05, primary = 0.254, E = 168.0, nu = 0.38, n = 1000;
  const double D = primary - d, l = n * d, I = M_PI * std::pow(d, 4) / 64, Emm = E * 1e3;
  EXPECT_NEAR(helicalSpringBending(d, primary, E, nu), 2 * l * Emm * I / (M_PI * n * D * (2 + nu)), 1e-12);
  // Wahl: torsion spring rate k = E d^4 / (64 D n) (N mm per rad); rigidity = k l.
  EXPECT_NEAR(helicalSpringTorsion(d, primary, E), Emm * std::pow(d, 4) / (64 * D * n) * l, 1e-12);
  // Metal per length: wire length per turn pi D over the pitch d, times the wire area.
  EXPECT_NEAR(woundMetalArea(d, primary), M_PI * d * d / 4 * (M_PI * D / d), 1e-15);
  // The wound coil is thousands of times softer than solid platinum of the same outer diameter.
  const double solid = Emm * M_PI * std::pow(primary / 2, 4) / 4;
  EXPECT_GT(solid / helicalSpringBending(d, primary, E, nu), 1000.0);
}

TEST(CoilCatalogue, ApplyCoilGivesTheDeploymentTheEffectiveRigidities) {
  const std::vector<CoilSpec> coils = loadCatalogue(kCatalogue);
  const CoilSpec& c = findCoil(coils, "filling-helical-6x150");
  DeploymentSpec dep;
  applyCoil(c, 0.5, dep);
  const double E = c.wireYoungGpa * 1e3, G = E / (2 * (1 + c.wirePoisson));
  EXPECT_NEAR(E * dep.section.inertiaMm4, c.bendingStiffnessNmm2, 1e-12 * c.bendingStiffnessNmm2);
  EXPECT_NEAR(G * dep.section.torsionMm4, c.torsionStiffnessNmm2, 1e-12 * c.torsionStiffnessNmm2);
  EXPECT_EQ(dep.beams, 300);
  EXPECT_DOUBLE_EQ(dep.section.outerRadiusMm, 0.127);
  EXPECT_EQ(dep.rest.type, RestShapeSpec::Type::Helix);
}

std::string coilText(const std::string& replaceKey = "", const std::string& replacement = "") {
  std::string t = R"({"format": "coilsim-coil/1", "name": "x", "family": "filling", "shape": "helical",
    "loop_diameter_mm": 6, "length_mm": 150, "primary_diameter_mm": 0.254,
    "wire": {"diameter_mm": 0.0508, "young_modulus_gpa": 168, "poisson_ratio": 0.38, "density_g_cm3": 21.45},
    "stretch_resistant": true, "bending_stiffness_n_mm2": 0.003673, "torsion_stiffness_n_mm2": 0.00437})";
  if (!replaceKey.empty()) {
    const size_t at = t.find(replaceKey);
    const size_t end = t.find_first_of(",}", at);
    t.replace(at, end - at, replacement);
  }
  return t;
}

void expectError(const std::string& text, const std::string& fragment) {
  try {
    coilFromText(text, "coil.json");
    ADD_FAILURE() << "no error for " << text;
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("coil.json"), std::string::npos) << e.what();
  }
}

TEST(CoilCatalogue, BadFilesNameFileAndField) {
  EXPECT_NO_THROW(coilFromText(coilText(), "coil.json"));
  expectError(coilText("\"bending_stiffness_n_mm2\"", "\"bending_stiffness_n_mm2\": 0.01"), "/bending_stiffness_n_mm2");
  expectError(coilText("\"loop_diameter_mm\"", "\"loop_diameter_mm\": -3"), "/loop_diameter_mm");
  expectError(coilText("\"shape\"", "\"shape\": \"pretzel\""), "/shape");
  expectError(coilText("\"family\"", "\"famly\": \"filling\""), "famly");
  expectError(coilText("\"diameter_mm\"", "\"diameter_mm\": 0.13"), "/wire/diameter_mm");
  expectError("{\"format\": \"coilsim-coil/1\", \"name\": \"x\"", "coil.json");  // malformed JSON
  EXPECT_THROW(loadCatalogue("/nonexistent/coils"), InputError);
  EXPECT_THROW(findCoil(loadCatalogue(kCatalogue), "no-such-coil"), InputError);
}

}  // namespace
}  // namespace coilsim::io
