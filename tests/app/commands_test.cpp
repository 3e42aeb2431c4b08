// The command table against what it describes: the options the commands'
// own code reads (found in src/app by their string literals) and the usage
// forms written in the table itself.
#include "app/commands.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <string>

namespace coilsim::app {
namespace {

namespace fs = std::filesystem;

std::set<std::string> tableOptions() {
  std::set<std::string> names;
  for (const CommandSpec& c : commands())
    for (const OptionSpec& o : c.options) names.insert(std::string(o.name));
  return names;
}

TEST(CommandTable, EveryOptionTheCommandsReadIsInTheTable) {
  // A "--name" literal in a command's source is an option it reads (or names
  // in a message); each must be declared, or the parser refuses it.
  const std::set<std::string> known = tableOptions();
  const std::regex literal("\"(--[a-z][a-z0-9-]*)");
  int files = 0;
  for (const auto& entry : fs::directory_iterator(fs::path(COILSIM_SOURCE_DIR) / "src/app")) {
    const std::string name = entry.path().filename().string();
    if (entry.path().extension() != ".cpp" || name == "commands.cpp" || name.rfind("bench", 0) == 0) continue;
    std::ifstream in(entry.path());
    std::stringstream text;
    text << in.rdbuf();
    const std::string s = text.str();
    ++files;
    for (std::sregex_iterator m(s.begin(), s.end(), literal), end; m != end; ++m) {
      const std::string option = (*m)[1];
      if (option == "--help" || option == "--version") continue;
      EXPECT_TRUE(known.count(option)) << name << " reads " << option << ", which app/commands.cpp does not declare";
    }
  }
  EXPECT_GT(files, 8);
}

TEST(CommandTable, UsageFormsNameOnlyDeclaredOptions) {
  const std::regex option("--[a-z][a-z0-9-]*");
  for (const CommandSpec& c : commands()) {
    const std::string forms(c.synopsis);
    for (std::sregex_iterator m(forms.begin(), forms.end(), option), end; m != end; ++m) {
      const std::string o = m->str();
      if (o == "--help" || o == "--version") continue;
      EXPECT_TRUE(findOption(c, o)) << c.name << "'s usage names " << o << ", not among its options";
    }
  }
}

TEST(CommandTable, NamesAreUniqueAndBoundsOrdered) {
  std::set<std::string_view> commandNames;
  for (const CommandSpec& c : commands()) {
    EXPECT_TRUE(commandNames.insert(c.name).second) << c.name;
    EXPECT_FALSE(c.summary.empty()) << c.name;
    std::set<std::string_view> names;
    for (const OptionSpec& o : c.options) {
      EXPECT_TRUE(names.insert(o.name).second) << c.name << " " << o.name << " twice";
      EXPECT_EQ(o.name.rfind("--", 0), 0u) << o.name;
      EXPECT_FALSE(o.help.empty()) << c.name << " " << o.name;
      EXPECT_LT(o.min, o.max) << c.name << " " << o.name;
      EXPECT_EQ(o.kind == ValueKind::None, o.value.empty())
          << c.name << " " << o.name << ": a value needs a placeholder";
      EXPECT_EQ(o.kind == ValueKind::Choice, !o.choices.empty()) << c.name << " " << o.name;
    }
  }
  // The commands the issue names, each in the table.
  for (const char* name :
       {"run", "bench", "mesh", "phantom", "validate", "diagnose", "plan", "plan-merge", "practice", "help"})
    EXPECT_TRUE(findCommand(name)) << name;
}

}  // namespace
}  // namespace coilsim::app
