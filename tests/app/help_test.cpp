// Help and completion, tested by running the real binary: every command
// answers --help and `help CMD` with its full usage; the completion script
// bash sources offers the commands, options, choices and the catalogue's
// coils (the reference: the coil files in assets/coils).
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <set>
#include <string>

#include "app/commands.h"
#include "app/run_binary.h"
#include "physics/rod_quantities.h"

namespace apptest {
namespace {

using coilsim::app::commands;
using coilsim::app::CommandSpec;
using coilsim::app::OptionSpec;

TEST(Help, EveryCommandPrintsItsFullUsage) {
  const fs::path dir = scratch("help_each");
  for (const CommandSpec& c : commands()) {
    const std::string name(c.name);
    const Exec a = coilsim({name, "--help"}, dir);
    const Exec b = coilsim({"help", name}, dir);
    ASSERT_EQ(a.code, 0) << name << ": " << a.err;
    ASSERT_EQ(b.code, 0) << name << ": " << b.err;
    EXPECT_EQ(a.out, b.out) << name;
    EXPECT_EQ(a.out.rfind("usage: coilsim " + name, 0), 0u) << a.out;
    for (const OptionSpec& o : c.options) EXPECT_CONTAINS(a.out, std::string(o.name));
    EXPECT_EQ(coilsim({name, "-h"}, dir).out, a.out) << name;
  }
}

TEST(Help, MainHelpListsTheOptionsOfPracticePlanAndValidate) {
  const fs::path dir = scratch("help_main");
  const Exec r = coilsim({"help"}, dir);
  ASSERT_EQ(r.code, 0);
  for (const char* name : {"practice", "plan", "validate"})
    for (const OptionSpec& o : coilsim::app::findCommand(name)->options) EXPECT_CONTAINS(r.out, std::string(o.name));
  EXPECT_EQ(coilsim({"--help"}, dir).out, r.out);
}

// Each rod quantity's key, unit and range come from its one declaration;
// the same key is the scene file's (the reference: a shipped scene).
TEST(Help, ListsEveryRodQuantityWithUnitAndRange) {
  const fs::path dir = scratch("help_rod_quantities");
  const Exec r = coilsim({"help"}, dir);
  ASSERT_EQ(r.code, 0);
  EXPECT_CONTAINS(r.out, "rod quantities:");
  for (const coilsim::rodq::Quantity* q : coilsim::rodq::kAll) {
    const std::string name(q->spec.name);
    const size_t at = r.out.find("\n  " + name + " ");
    ASSERT_NE(at, std::string::npos) << name;
    const std::string line = r.out.substr(at + 1, r.out.find('\n', at + 1) - at - 1);
    EXPECT_CONTAINS(line, std::string(q->spec.unit));
    EXPECT_CONTAINS(line, std::string(q->spec.description));
  }
  EXPECT_CONTAINS(coilsim({"validate", "--help"}, dir).out, "young_modulus_gpa  *");
  const std::string sceneText = slurp(scene("cantilever-static.json"));
  for (const char* key : {"\"young_modulus_gpa\"", "\"length_mm\"", "\"density_g_cm3\""}) EXPECT_CONTAINS(sceneText, key);
}

TEST(Help, AnOptionIsNeverTakenAsAValueByTheBinary) {
  const fs::path dir = scratch("help_out_headless");
  const Exec r = coilsim({"run", scene("cantilever-static.json"), "--out", "--headless"}, dir);
  EXPECT_EQ(r.code, 2);
  EXPECT_CONTAINS(r.err, "--out needs");
  EXPECT_FALSE(fs::exists(dir / "--headless"));
  EXPECT_FALSE(fs::exists(fs::current_path() / "--headless"));
  const Exec p = coilsim({"plan", "x.json", "--jobs", "2x"}, dir);
  EXPECT_EQ(p.code, 2);
  EXPECT_CONTAINS(p.err, "--jobs needs a whole number in [1, 256], got \"2x\"");
}

TEST(Help, UnknownCommandsAndOptionsSuggestTheNearest) {
  const fs::path dir = scratch("help_nearest");
  Exec r = coilsim({"runn", "scenes/default.json"}, dir);
  EXPECT_EQ(r.code, 2);
  EXPECT_CONTAINS(r.err, "unknown command \"runn\" (did you mean run?)");
  r = coilsim({"diagnos", "x.json"}, dir);
  EXPECT_CONTAINS(r.err, "did you mean diagnose?");
  r = coilsim({"help", "plna-merge"}, dir);
  EXPECT_EQ(r.code, 2);
  r = coilsim({"practice", "c.json", "--replya", "s.json"}, dir);
  EXPECT_EQ(r.code, 2);
  EXPECT_CONTAINS(r.err, "did you mean --replay?");
}

// Completes `line` (the cursor at its end) with the script `coilsim completion bash` prints.
std::set<std::string> complete(const fs::path& dir, const std::string& line) {
  const fs::path script = dir / "coilsim.bash";
  const Exec gen = coilsim({"completion", "bash"}, dir);
  EXPECT_EQ(gen.code, 0) << gen.err;
  std::ofstream(script) << gen.out;
  // COMP_WORDS as bash splits the line; a trailing space starts an empty word.
  const std::string driver =
      "source " + quote(script.string()) + "; line=" + quote(line) +
      "; read -ra COMP_WORDS <<< \"$line\"; [[ $line == *' ' ]] && COMP_WORDS+=(''); COMP_WORDS[0]=" +
      quote(COILSIM_BINARY) + "; COMP_CWORD=$((${#COMP_WORDS[@]} - 1)); _coilsim; printf '%s\\n' \"${COMPREPLY[@]}\"";
  const fs::path out = dir / "completed.txt";
  const int status =
      std::system(("cd " + quote(kSource) + " && bash -c " + quote(driver) + " >" + quote(out.string())).c_str());
  EXPECT_EQ(status, 0);
  std::set<std::string> words;
  std::istringstream in(slurp(out));
  for (std::string w; std::getline(in, w);)
    if (!w.empty()) words.insert(w);
  return words;
}

TEST(Completion, CommandsOptionsChoicesAndCoils) {
  const fs::path dir = scratch("completion");
  EXPECT_EQ(complete(dir, "coilsim pl"), (std::set<std::string>{"plan", "plan-merge"}));
  EXPECT_EQ(complete(dir, "coilsim run scenes/default.json --vi"), (std::set<std::string>{"--view"}));
  EXPECT_EQ(complete(dir, "coilsim run scenes/default.json --view "), (std::set<std::string>{"3d", "xray", "biplane"}));
  EXPECT_TRUE(complete(dir, "coilsim run scenes/def").count("scenes/default.json"));
  // Coils: the names in the catalogue's files, after the last ',' or '+'.
  std::set<std::string> framing;
  for (const auto& e : fs::directory_iterator(fs::path(kSource) / "assets/coils")) {
    const std::string name = readJson(e.path())["name"];
    if (name.rfind("framing", 0) == 0) framing.insert("finishing-2x10+" + name);
  }
  ASSERT_FALSE(framing.empty());
  EXPECT_EQ(complete(dir, "coilsim plan c.json --coils finishing-2x10+fram"), framing);
}

}  // namespace
}  // namespace apptest
