// Reading a command line against the command table: the references are the
// table's own bounds and the standard definitions (Levenshtein distance of
// textbook pairs), not output of the parser pasted in.
#include "app/options.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace coilsim::app {
namespace {

const CommandSpec& run() { return *findCommand("run"); }

std::string errorOf(const CommandSpec& c, const std::vector<std::string>& args) {
  try {
    parseArgs(c, args);
  } catch (const UsageError& e) {
    return e.what();
  }
  return "";
}

TEST(Options, AnOptionIsNeverTakenAsAValue) {
  const std::string e = errorOf(run(), {"scene.json", "--out", "--headless"});
  EXPECT_NE(e.find("--out needs"), std::string::npos) << e;
  EXPECT_NE(e.find("\"--headless\""), std::string::npos) << e;
  // The same for every option that takes a value, of every command.
  for (const CommandSpec& c : commands())
    for (const OptionSpec& o : c.options)
      if (o.kind != ValueKind::None) {
        const std::string why = errorOf(c, {"x.json", std::string(o.name), "--help"});
        EXPECT_EQ(why.rfind(std::string(o.name) + " needs", 0), 0u) << c.name << " " << o.name << ": " << why;
      }
}

TEST(Options, NegativeNumbersAreValuesNotOptions) {
  const std::string e = errorOf(run(), {"scene.json", "--duration", "-1"});
  EXPECT_NE(e.find("--duration needs a number in (0, 3600]"), std::string::npos) << e;
}

TEST(Options, NumbersAreReadWholeAndWithinTheirBounds) {
  for (const char* bad : {"1.5s", "1,5", "", "nan", "inf", "0x10", "1e400"})
    EXPECT_NE(errorOf(run(), {"scene.json", "--duration", bad}), "") << bad;
  EXPECT_NE(errorOf(run(), {"scene.json", "--duration", "0"}), "");  // (0, inf): 0 excluded
  const ParsedArgs p = parseArgs(run(), {"scene.json", "--duration=2.5", "--steps", "7", "--size", "640x480"});
  EXPECT_EQ(p.number("--duration"), 2.5);
  EXPECT_EQ(p.integer("--steps"), 7);
  EXPECT_EQ(p.size("--size"), std::make_pair(640, 480));
  // The table's bounds, at and beyond each end.
  const OptionSpec& steps = *findOption(run(), "--steps");
  EXPECT_EQ(errorOf(run(), {"s.json", "--steps", std::to_string(long(steps.max))}), "");
  EXPECT_NE(errorOf(run(), {"s.json", "--steps", std::to_string(long(steps.max) + 1)}), "");
  EXPECT_NE(errorOf(run(), {"s.json", "--steps", "2.5"}), "");
  EXPECT_NE(errorOf(run(), {"s.json", "--size", "640x480x3"}), "");
  EXPECT_NE(errorOf(run(), {"s.json", "--size", "8x480"}), "");
  EXPECT_NE(errorOf(*findCommand("plan"), {"c.json", "--jobs", "0"}), "");
  EXPECT_EQ(errorOf(*findCommand("plan"), {"c.json", "--jobs", "256"}), "");
}

TEST(Options, ChoicesAndFlags) {
  EXPECT_NE(errorOf(run(), {"s.json", "--view", "top"}).find("--view needs 3d, xray or biplane"), std::string::npos);
  EXPECT_NE(errorOf(run(), {"s.json", "--headless=yes"}).find("takes no value"), std::string::npos);
  EXPECT_TRUE(parseArgs(run(), {"s.json", "--headless"}).has("--headless"));
}

TEST(Options, UnknownOptionsSuggestTheNearest) {
  const std::string e = errorOf(run(), {"s.json", "--outt", "r.json"});
  EXPECT_NE(e.find("unknown option \"--outt\""), std::string::npos) << e;
  EXPECT_NE(e.find("did you mean --out?"), std::string::npos) << e;
  EXPECT_EQ(errorOf(run(), {"s.json", "--frobnicate"}).find("did you mean"), std::string::npos);
}

TEST(Options, OperandsAreCounted) {
  EXPECT_NE(errorOf(run(), {}), "");
  EXPECT_NE(errorOf(run(), {"a.json", "b.json"}).find("\"a.json\" and \"b.json\""), std::string::npos);
  EXPECT_EQ(parseArgs(*findCommand("plan"), {"a.json", "b.json", "--out", "d"}).operands.size(), 2u);
  EXPECT_TRUE(parseArgs(run(), {"--help"}).help);  // help needs no operand
}

TEST(Options, NormalisedArgumentsSplitEquals) {
  const ParsedArgs p = parseArgs(*findCommand("plan"), {"c.json", "--out=d", "--no-screenshots"});
  EXPECT_EQ(p.normalised(), (std::vector<std::string>{"c.json", "--out", "d", "--no-screenshots"}));
}

TEST(EditDistance, TextbookPairs) {
  EXPECT_EQ(editDistance("kitten", "sitting"), 3u);  // Levenshtein's classic example
  EXPECT_EQ(editDistance("flaw", "lawn"), 2u);
  EXPECT_EQ(editDistance("", "abc"), 3u);
  EXPECT_EQ(editDistance("run", "run"), 0u);
}

TEST(EditDistance, NearestCommand) {
  std::vector<std::string_view> names;
  for (const CommandSpec& c : commands()) names.push_back(c.name);
  EXPECT_EQ(nearest("runn", names), "run");
  EXPECT_EQ(nearest("validat", names), "validate");
  EXPECT_EQ(nearest("plan-merg", names), "plan-merge");
  EXPECT_EQ(nearest("xyzzy", names), "");
}

}  // namespace
}  // namespace coilsim::app
