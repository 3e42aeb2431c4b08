// A case's "sequences": read in order from the case's coil set, and refused
// naming the file and the field when they name a coil outside it.
#include "planning/case_file.h"

#include <gtest/gtest.h>

#include <string>

#include "io/units.h"

namespace coilsim::planning {
namespace {

const std::string kCase = std::string(COILSIM_SOURCE_DIR) + "/scenes/cases/sphere-7mm-wide-neck.json";

// The shipped 7 mm case with `sequences` in place of its own.
nlohmann::json withSequences(const nlohmann::json& sequences) {
  nlohmann::json doc = io::readJsonFile(kCase);
  doc["sequences"] = sequences;
  return doc;
}

// The message of the InputError parsing `doc` throws, or "" when it parses.
std::string errorOf(const nlohmann::json& doc) {
  try {
    parseCase(doc, "my-case.json");
  } catch (const io::InputError& e) {
    return e.what();
  }
  return "";
}

TEST(CaseFile, SequencesAreReadInOrderFromTheCoilSet) {
  const PracticeCase c = parseCase(withSequences({{{"name", "short"}, {"coils", {"finishing-2x10", "finishing-3x40"}}},
                                                  {{"name", "one"}, {"coils", {"framing-3d-5x100"}}}}),
                                   "my-case.json");
  ASSERT_EQ(c.sequences.size(), 2u);
  EXPECT_EQ(c.sequences[0].name, "short");
  ASSERT_EQ(c.sequences[0].coils.size(), 2u);
  EXPECT_EQ(c.sequences[0].coils[0].name, "finishing-2x10");
  EXPECT_EQ(c.sequences[0].coils[1].name, "finishing-3x40");
  EXPECT_DOUBLE_EQ(c.sequences[0].coils[1].lengthMm, 40);  // the catalogue coil, not just its name
  EXPECT_EQ(findSequence(c, "one").coils.at(0).name, "framing-3d-5x100");
}

TEST(CaseFile, ShippedCasesCarryTheirGoalSequence) {
  for (const char* name : {"sphere-7mm-wide-neck", "sphere-10mm-narrow-neck"}) {
    const PracticeCase c = loadCase(std::string(COILSIM_SOURCE_DIR) + "/scenes/cases/" + name + ".json");
    ASSERT_FALSE(c.sequences.empty()) << name;
    EXPECT_EQ(c.sequences.front().name, "goal") << name;
    // Its coils, all inside the sac, would reach the case's goal (docs/planning.md's table): pi r^2 L / V.
    const double sacMm3 = units::m3ToMm3(sacVolume(c.sac));
    double coilMm3 = 0;
    for (const io::CoilSpec& coil : c.sequences.front().coils)
      coilMm3 += M_PI * 0.25 * coil.primaryDiameterMm * coil.primaryDiameterMm * coil.lengthMm;
    EXPECT_GE(coilMm3 / sacMm3, c.goal.minPackingDensity) << name;
  }
}

TEST(CaseFile, ASequenceOutsideTheCoilSetNamesFileAndField) {
  // framing-complex-10x300 is a catalogue coil, but not of the 7 mm case's set.
  const PracticeCase plain = loadCase(kCase);
  for (const io::CoilSpec& c : plain.coils) ASSERT_NE(c.name, "framing-complex-10x300");
  std::string e = errorOf(withSequences({{{"name", "s"}, {"coils", {"finishing-2x10", "framing-complex-10x300"}}}}));
  EXPECT_NE(e.find("my-case.json: /sequences/0/coils/1"), std::string::npos) << e;
  EXPECT_NE(e.find("framing-complex-10x300"), std::string::npos) << e;
  e = errorOf(withSequences({{{"name", "s"}, {"coils", {"no-such-coil"}}}}));
  EXPECT_NE(e.find("my-case.json: /sequences/0/coils/0"), std::string::npos) << e;
  e = errorOf(withSequences({{{"name", "s"}, {"coils", {"finishing-2x10"}}}, {{"name", "s"}, {"coils", {"finishing-2x10"}}}}));
  EXPECT_NE(e.find("my-case.json: /sequences/1/name"), std::string::npos) << e;
  e = errorOf(withSequences({{{"name", "s"}, {"coils", nlohmann::json::array()}}}));
  EXPECT_NE(e.find("my-case.json: /sequences/0/coils"), std::string::npos) << e;
  e = errorOf(withSequences({{{"name", "s"}, {"coils", {"finishing-2x10"}}, {"colour", "red"}}}));
  EXPECT_NE(e.find("my-case.json: /sequences/0"), std::string::npos) << e;
  EXPECT_NE(e.find("colour"), std::string::npos) << e;
  e = errorOf(withSequences("goal"));
  EXPECT_NE(e.find("my-case.json: /sequences"), std::string::npos) << e;
}

TEST(CaseFile, AnUnknownSequenceNameListsTheCasesOwn) {
  const PracticeCase c = loadCase(kCase);
  try {
    findSequence(c, "no-such-sequence");
    FAIL() << "no error";
  } catch (const io::InputError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find(kCase), std::string::npos) << m;
    EXPECT_NE(m.find("no-such-sequence"), std::string::npos) << m;
    EXPECT_NE(m.find("goal"), std::string::npos) << m;
  }
}

}  // namespace
}  // namespace coilsim::planning
