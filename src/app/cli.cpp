// The `coilsim` command line: finds the command in the table (app/commands.h),
// checks its arguments there (app/options.h), answers --help from it
// (app/help.h), and runs the command.
#include "app/cli.h"

#include <algorithm>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "app/bench.h"
#include "app/case_cmd.h"
#include "app/commands.h"
#include "app/data_paths.h"
#include "app/diagnose_cmd.h"
#include "app/experiment_cmd.h"
#include "app/help.h"
#include "app/mesh_cmd.h"
#include "app/options.h"
#include "app/phantom_cmd.h"
#include "app/plan_cmd.h"
#include "app/practice_cmd.h"
#include "app/progress.h"
#include "app/run_scene.h"
#include "app/stop_signal.h"
#include "app/validate_cmd.h"
#include "io/coil_catalogue.h"
#include "planning/case_file.h"

// The build passes the project version; this fallback only serves builds
// that do not (see the report of issue 2).
#ifndef COILSIM_VERSION
#define COILSIM_VERSION "0.1.0"
#endif

namespace coilsim {
namespace {

using app::kExitOk;
using app::kExitUsage;

int usageError(std::string_view command, const std::string& message) {
  std::fprintf(stderr, "coilsim%s%s: %s\n", command.empty() ? "" : " ", std::string(command).c_str(), message.c_str());
  return kExitUsage;
}

std::vector<std::string_view> commandNames() {
  std::vector<std::string_view> names;
  for (const app::CommandSpec& c : app::commands()) names.push_back(c.name);
  return names;
}

app::RunOptions runOptions(const app::ParsedArgs& p) {
  app::RunOptions o;
  o.scene = p.operands.front();
  o.headless = p.has("--headless");
  o.out = p.text("--out").value_or("");
  o.input = p.text("--input").value_or("");
  o.durationS = p.number("--duration");
  o.steps = p.integer("--steps");
  o.screenshot = p.text("--screenshot").value_or("");
  o.view = p.text("--view");
  if (const auto size = p.size("--size")) o.width = size->first, o.height = size->second;
  return o;
}

// The command's own reader gets the checked arguments; --quiet has been
// taken (Progress::setQuiet) unless the command reads it itself.
std::vector<std::string> forwarded(const app::ParsedArgs& p, bool keepQuiet) {
  std::vector<std::string> a = p.normalised();
  if (!keepQuiet) a.erase(std::remove(a.begin(), a.end(), "--quiet"), a.end());
  return a;
}

int completion(const std::string& what) {
  if (what == "bash") {
    std::fputs(app::bashCompletion().c_str(), stdout);
    return kExitOk;
  }
  if (what == "coils") {  // for the completion script: the catalogue's names, one a line
    for (const io::CoilSpec& c : io::loadCatalogue(planning::defaultCatalogue())) std::printf("%s\n", c.name.c_str());
    return kExitOk;
  }
  return usageError("completion", "knows bash (the script) and coils (the catalogue's names), got \"" + what + "\"");
}

// Commands that stop cleanly on SIGINT/SIGTERM (they ask stopRequested()
// between steps); the others, and windows, keep the default: end at once.
bool stopsCleanly(const app::CommandSpec& c, const app::ParsedArgs& p) {
  const std::string_view n = c.name;
  if (n == "run") return p.has("--headless") || !app::haveDisplay();
  if (n == "practice" || n == "validate") return !p.has("--window");
  return n == "plan";
}

int dispatch(const app::CommandSpec& c, const app::ParsedArgs& p) {
  const std::string_view n = c.name;
  if (stopsCleanly(c, p)) app::installStopHandlers();
  if (n == "run") {
    if (p.number("--duration") && p.integer("--steps"))
      return usageError("run", "give --duration or --steps, not both");
    return app::runScene(runOptions(p));
  }
  if (n == "bench") return runBench(forwarded(p, false));
  if (n == "mesh") return app::runMeshCommand(forwarded(p, false));
  if (n == "phantom") return app::runPhantomCommand(forwarded(p, false));
  if (n == "plan") return app::runPlan(forwarded(p, false));
  if (n == "plan-merge") return app::runPlanMerge(forwarded(p, false));
  if (n == "experiment") return app::runExperiment(p);
  if (n == "practice") return app::runPractice(forwarded(p, false));
  if (n == "validate") return app::runValidate(forwarded(p, true));
  if (n == "diagnose") return app::runDiagnose(forwarded(p, true));
  if (n == "case") return app::runCaseCommand(forwarded(p, false));
  if (n == "completion") return completion(p.operands.front());
  if (n == "help") {
    if (p.operands.empty()) {
      app::printMainHelp(stdout);
      return kExitOk;
    }
    const app::CommandSpec* about = app::findCommand(p.operands.front());
    if (!about)
      return usageError(
          "help", "no command \"" + p.operands.front() + "\"" + app::didYouMean(p.operands.front(), commandNames()));
    app::printCommandHelp(*about, stdout);
    return kExitOk;
  }
  return usageError("", "no command \"" + std::string(n) + "\"");
}

// `coilsim SCENE ...` is `coilsim run SCENE ...`: a first word that is no
// command names a scene when it is a file or looks like a path.
bool namesAScene(const std::string& word) {
  std::error_code ec;
  return word.find('/') != std::string::npos || word.find('.') != std::string::npos ||
         std::filesystem::exists(word, ec);
}

}  // namespace

int runCli(int argc, char** argv) {
  app::useDataDirectory();
  std::vector<std::string> args(argv + std::min(argc, 1), argv + argc);
  if (args.empty()) {
    app::printMainHelp(stderr);
    return kExitUsage;
  }
  const std::string first = args.front();
  if (first == "--help" || first == "-h") args.front() = "help";
  if (first == "--version" || first == "version") {
    std::printf("coilsim %s\n", COILSIM_VERSION);
    return kExitOk;
  }
  const app::CommandSpec* command = app::findCommand(args.front());
  if (command) {
    args.erase(args.begin());
  } else {
    const app::CommandSpec& run = *app::findCommand("run");
    const std::string option = first.substr(0, first.find('='));
    const bool runOption = first.size() > 1 && first[0] == '-' && app::findOption(run, option);
    if (!runOption && (first[0] == '-' || !namesAScene(first)))
      return usageError("", "unknown command \"" + first + "\"" + app::didYouMean(first, commandNames()) +
                                "; coilsim help lists the commands");
    command = &run;
  }
  try {
    const app::ParsedArgs parsed = app::parseArgs(*command, args);
    if (parsed.help) {
      app::printCommandHelp(*command, stdout);
      return kExitOk;
    }
    if (parsed.has("--quiet")) app::Progress::setQuiet(true);
    return dispatch(*command, parsed);
  } catch (const app::UsageError& e) {
    return usageError(command->name, e.what());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "coilsim %s: %s\n", std::string(command->name).c_str(), e.what());
    return app::kExitFailure;
  }
}

}  // namespace coilsim
