// Fit names (src/validation/params.cpp): a rod quantity is fitted under its
// scene key, with the unit and SI factor of its one declaration; the old
// --fit names stand for the same quantity. Reference: the SI definitions of
// the units (1 GPa = 1e9 Pa, 1 mm = 1e-3 m) and the measurement's values.
#include "validation/params.h"

#include <gtest/gtest.h>

#include <string>

namespace coilsim::validation {
namespace {

Measurement helixCoil() {
  Measurement m;
  m.coil.length = 0.1;
  m.coil.wireRadius = 0.15e-3;
  m.coil.rest.type = RestShapeDef::Type::Helix;
  m.coil.rest.loopDiameter = 7e-3;
  m.coil.rest.pitch = 1e-3;
  m.coil.youngModulus = 7.5e9;
  m.coil.poissonRatio = 0.39;
  return m;
}

TEST(FitNames, RodQuantitiesGoByTheirSceneKeysInTheirEdgeUnits) {
  const Measurement m = helixCoil();
  const ModelParams p = ModelParams::nominal(m);
  struct Case {
    const char* name;
    const char* unit;
    double toSI;
    double valueSI;
  };
  const Case cases[] = {{"young_modulus_gpa", "GPa", 1e9, 7.5e9},
                        {"poisson_ratio", "1", 1.0, 0.39},
                        {"loop_diameter_mm", "mm", 1e-3, 7e-3},
                        {"pitch_mm", "mm", 1e-3, 1e-3}};
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name);
    std::string why;
    const std::optional<FitParam> f = describeParam(c.name, p, m, why);
    ASSERT_TRUE(f) << why;
    EXPECT_EQ(f->unit, c.unit);
    EXPECT_EQ(f->toSI, c.toSI);
    EXPECT_LE(f->lo, c.valueSI);
    EXPECT_GE(f->hi, c.valueSI);
    EXPECT_DOUBLE_EQ(getParam(p, c.name), c.valueSI);
    EXPECT_EQ(canonicalFitName(c.name), c.name);
    EXPECT_EQ(oldFitNameNote(c.name), "");
  }
}

TEST(FitNames, TheOldNamesFitTheSameQuantityAndSaySo) {
  const Measurement m = helixCoil();
  const ModelParams p = ModelParams::nominal(m);
  const std::pair<const char*, const char*> pairs[] = {
      {"young_modulus", "young_modulus_gpa"}, {"loop_diameter", "loop_diameter_mm"}, {"pitch", "pitch_mm"}};
  for (const auto& [old, key] : pairs) {
    SCOPED_TRACE(old);
    std::string why;
    const std::optional<FitParam> a = describeParam(old, p, m, why), b = describeParam(key, p, m, why);
    ASSERT_TRUE(a && b) << why;
    EXPECT_EQ(a->name, old);  // reports keep the name the user typed
    EXPECT_EQ(a->unit, b->unit);
    EXPECT_EQ(a->toSI, b->toSI);
    EXPECT_EQ(a->lo, b->lo);
    EXPECT_EQ(a->hi, b->hi);
    EXPECT_EQ(a->prior.nominal, b->prior.nominal);
    EXPECT_EQ(canonicalFitName(old), key);
    // Setting through one name is seen through the other.
    ModelParams q = p;
    setParam(q, old, 2 * getParam(p, key));
    EXPECT_EQ(getParam(q, key), 2 * getParam(p, key));
    const std::string note = oldFitNameNote(old);
    EXPECT_NE(note.find(key), std::string::npos) << note;
  }
  EXPECT_TRUE(isYoungModulus("young_modulus"));
  EXPECT_TRUE(isYoungModulus("young_modulus_gpa"));
  EXPECT_FALSE(isYoungModulus("poisson_ratio"));
}

TEST(FitNames, AnUnknownNameListsTheSceneKeys) {
  const Measurement m = helixCoil();
  std::string why;
  EXPECT_FALSE(describeParam("stiffness", ModelParams::nominal(m), m, why));
  for (const char* key : {"young_modulus_gpa", "poisson_ratio", "loop_diameter_mm", "pitch_mm"})
    EXPECT_NE(why.find(key), std::string::npos) << why;
  EXPECT_THROW(getParam(ModelParams::nominal(m), "stiffness"), std::invalid_argument);
}

TEST(FitNames, HelixQuantitiesNeedAHelix) {
  Measurement m = helixCoil();
  m.coil.rest = RestShapeDef{};
  std::string why;
  EXPECT_FALSE(describeParam("pitch_mm", ModelParams::nominal(m), m, why));
  EXPECT_NE(why.find("helical"), std::string::npos) << why;
}

}  // namespace
}  // namespace coilsim::validation
