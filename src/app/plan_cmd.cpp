// `coilsim plan`: candidate coils deployed automatically into one aneurysm,
// compared in DIR/plan.json, DIR/plan.md and a screenshot per coil.
#include "app/plan_cmd.h"

#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <sstream>

#include "app/exit_codes.h"
#include "app/format.h"
#include "app/graphics.h"
#include "app/plan_runner.h"
#include "app/stop_signal.h"
#include "io/json_writer.h"
#include "io/units.h"
#include "planning/case_file.h"
#include "physics/sleep.h"
#include "planning/plan.h"

namespace coilsim::app {
namespace {

using planning::Candidate;
using planning::CandidateResult;
using planning::PlanSetup;

int usage(const std::string& message) {
  std::fprintf(stderr,
               "coilsim plan: %s\n"
               "usage: coilsim plan SCENE|CASE... --out DIR [--coils a,b+c | --sequence NAME] [--jobs N] [--sac FILE]\n"
               "         [--catalogue DIR] [--speed MM_S] [--force-threshold MN] [--spacing MM] [--max-time S]\n"
               "         [--sensitivity SHIFT_MM,TILT_DEG] [--sleep on|off|auto] [--no-screenshots] [--size WxH]\n"
               "       coilsim plan-merge DIR... --out DIR\n"
               "(docs/planning.md)\n",
               message.c_str());
  return kExitUsage;
}

bool number(const std::string& s, double& out) {
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), out);
  return ec == std::errc() && end == s.data() + s.size() && std::isfinite(out);
}

std::vector<std::string> split(const std::string& s, char sep) {
  std::vector<std::string> out;
  std::stringstream in(s);
  for (std::string item; std::getline(in, item, sep);)
    if (!item.empty()) out.push_back(item);
  return out;
}

struct PlanArgs {
  std::string input, out, sac, catalogue, coils, sequence;
  std::vector<std::string> inputs;  // several cases: one plan each, in DIR/<case name>/
  int jobs = 1;
  bool screenshots = true;
  int width = 960, height = 720;
  std::optional<double> speedMmS, thresholdMn, spacingMm, maxTime;
  std::optional<std::pair<double, double>> sensitivity;
  // Placed coils at rest sleep (physics/sleep.h): on, off, auto (on for
  // sequences), or "" (not given): as the scene says, off unless it has a
  // "sleep" block that switches it on. Not on by default until it is shown
  // to pay in a plan (docs/contact.md, "Sleeping coils").
  std::string sleep;
};

// Parses plan's arguments; returns an error message or "".
std::string parseArgs(const std::vector<std::string>& args, PlanArgs& a) {
  for (size_t i = 0; i < args.size(); ++i) {
    const std::string& arg = args[i];
    // An option's value is never the next option (`--out --jobs` names no directory).
    auto value = [&](std::string& v) {
      if (i + 1 >= args.size() || args[i + 1].rfind("--", 0) == 0) return false;
      v = args[++i];
      return true;
    };
    // A number in (0, max]: the bounds say what the operator and the solver can run.
    auto inRange = [&](std::optional<double>& out, const char* what, double max) -> std::string {
      std::string v;
      double d = 0;
      if (!value(v) || !number(v, d) || !(d > 0) || !(d <= max))
        return arg + " needs " + what + " in (0, " + fmt("%g", max) + "], got \"" + v + "\"";
      out = d;
      return "";
    };
    std::string v, err;
    if (arg == "--out") {
      if (!value(a.out) || a.out.empty()) return "--out needs a directory";
    } else if (arg == "--coils") {
      if (!value(a.coils) || split(a.coils, ',').empty()) return "--coils needs names, e.g. --coils framing-3d-5x100,filling-helical-4x80";
    } else if (arg == "--sequence") {
      if (!value(a.sequence) || a.sequence.empty()) return "--sequence needs the name of one of the case's \"sequences\"";
    } else if (arg == "--jobs") {
      double d = 0;
      if (!value(v) || !number(v, d) || d < 1 || d > 256 || d != std::floor(d)) return "--jobs needs an integer in [1, 256], got \"" + v + "\"";
      a.jobs = int(d);
    } else if (arg == "--sac") {
      if (!value(a.sac)) return "--sac needs a JSON file holding {\"sac\": {...}}";
    } else if (arg == "--catalogue") {
      if (!value(a.catalogue)) return "--catalogue needs a directory of coil files";
    } else if (arg == "--speed") {
      if (!(err = inRange(a.speedMmS, "a push speed in mm/s", 1000)).empty()) return err;
    } else if (arg == "--force-threshold") {
      if (!(err = inRange(a.thresholdMn, "a tip force in mN", 10000)).empty()) return err;
    } else if (arg == "--spacing") {
      if (!(err = inRange(a.spacingMm, "a beam length in mm", 5)).empty()) return err;
      if (*a.spacingMm < 0.05) return "--spacing needs a beam length in [0.05, 5] mm, got \"" + args[i] + "\"";
    } else if (arg == "--max-time") {
      if (!(err = inRange(a.maxTime, "a number of seconds", 3600)).empty()) return err;
    } else if (arg == "--sensitivity") {
      const std::vector<std::string> parts = value(v) ? split(v, ',') : std::vector<std::string>{};
      double s = 0, t = 0;
      // A catheter tip moved by more than a sac's radius, or tilted past 45 deg, is another plan.
      if (parts.size() != 2 || !number(parts[0], s) || !number(parts[1], t) || !(s >= 0 && s <= 5) ||
          !(t >= 0 && t <= 45) || s + t == 0)
        return "--sensitivity needs SHIFT_MM,TILT_DEG (shift in [0, 5] mm, tilt in [0, 45] deg, not both 0), e.g. "
               "0.5,5; got \"" + v + "\"";
      a.sensitivity = std::make_pair(s, t);
    } else if (arg == "--sleep") {
      if (!value(v) || (v != "on" && v != "off" && v != "auto"))
        return "--sleep needs on, off or auto (on for sequences of coils), got \"" + v + "\"";
      a.sleep = v;
    } else if (arg == "--no-screenshots") {
      a.screenshots = false;
    } else if (arg == "--size") {
      const size_t x = value(v) ? v.find('x') : std::string::npos;
      double w = 0, h = 0;
      if (x == std::string::npos || !number(v.substr(0, x), w) || !number(v.substr(x + 1), h) || w < 16 || h < 16 ||
          w > 8192 || h > 8192)
        return "--size needs WIDTHxHEIGHT, each in [16, 8192], got \"" + v + "\"";
      a.width = int(w), a.height = int(h);
    } else if (!arg.empty() && arg[0] == '-') {
      return "unknown option \"" + arg + "\"";
    } else {
      a.inputs.push_back(arg);
    }
  }
  if (a.inputs.empty()) return "plan needs a scene or case file, e.g. coilsim plan scenes/cases/sphere-7mm-wide-neck.json";
  if (a.inputs.size() > 1 && !a.sac.empty()) return "--sac belongs to one scene: plan several case files, or one scene with --sac";
  if (!a.sequence.empty() && !a.coils.empty()) return "give --coils or --sequence, not both";
  a.input = a.inputs.front();
  if (a.out.empty()) return "plan needs --out DIR";
  return "";
}

bool screenshot(const PlanSetup& setup, const CandidateResult& r, const PlanArgs& a, const std::string& path,
                std::string& error) {
  return planPicture(r.model, r.state, setup.label + " - " + r.name + " (" + r.variant + ")", a.width, a.height,
                     setup.sac, path, error);
}

std::string fileSafe(std::string s) {
  for (char& c : s)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-' && c != '_' && c != '.') c = '_';
  return s;
}

int plan(const PlanArgs& a) {
  PlanSetup setup;
  setup.label = a.input;
  std::vector<std::vector<io::CoilSpec>> chosen;  // each a coil or a sequence
  std::string sequenceName;                        // the case's name of chosen's sequence, if it is one
  const nlohmann::json doc = io::readJsonFile(a.input);
  const bool isCase = doc.is_object() && doc.value("format", std::string()) == planning::kCaseFormat;
  const std::vector<io::CoilSpec> catalogue =
      io::loadCatalogue(a.catalogue.empty() ? planning::defaultCatalogue() : a.catalogue);
  if (isCase) {
    const planning::PracticeCase c = planning::parseCase(doc, a.input);
    setup.scene = c.scene;
    setup.sac = a.sac.empty() ? c.sac : planning::loadSac(a.sac);
    setup.spacingMm = c.spacingMm;
    setup.deploy.wallForceThreshold = c.goal.maxWallForce;
    // No coils named: the sequence asked for, else the case's first, else each coil of its set.
    if (!a.sequence.empty() || (a.coils.empty() && !c.sequences.empty())) {
      const planning::CoilSequence& s =
          a.sequence.empty() ? c.sequences.front() : planning::findSequence(c, a.sequence);
      chosen.push_back(s.coils);
      sequenceName = s.name;
    } else if (a.coils.empty())
      for (const io::CoilSpec& coil : c.coils) chosen.push_back({coil});
  } else {
    if (!a.sequence.empty())
      return usage(a.input + " is a scene: --sequence names a sequence of a case file (its \"sequences\")");
    setup.scene = io::loadScene(a.input);
    if (!setup.scene.deployment)
      return usage(a.input + " has no \"deployment\" block: plan needs a catheter to deploy the coils from");
    if (a.sac.empty())
      return usage(a.input + " is a scene: give the sac and neck plane with --sac FILE, or plan a case file (scenes/cases/*.json)");
    setup.sac = planning::loadSac(a.sac);
  }
  // "a,b": two candidates; "a+b": one sequence (a, then b into the same sac).
  for (const std::string& item : split(a.coils, ',')) {
    std::vector<io::CoilSpec> sequence;
    for (const std::string& name : split(item, '+')) sequence.push_back(io::findCoil(catalogue, name));
    if (!sequence.empty()) chosen.push_back(std::move(sequence));
  }
  if (chosen.empty()) return usage("no coils to plan: give --coils a,b,c");
  if (a.spacingMm) setup.spacingMm = *a.spacingMm;
  if (a.speedMmS) setup.deploy.pushSpeed = units::mmPerSToMPerS(*a.speedMmS);
  if (a.thresholdMn) setup.deploy.forceThreshold = units::mnToN(*a.thresholdMn);
  if (a.maxTime) setup.deploy.maxTime = *a.maxTime;
  try {
    planning::prepareSac(setup);
  } catch (const std::exception& e) {
    return usage(a.input + ": " + e.what());
  }
  // Placed coils at rest sleep (physics/sleep.h, docs/contact.md "Sleeping
  // coils") when asked; auto: in sequences only. A scene's own "sleep"
  // thresholds stay. Off, a plan is as it was without sleeping.
  bool sequence = false;
  for (const std::vector<io::CoilSpec>& c : chosen) sequence = sequence || c.size() > 1;
  if (!a.sleep.empty()) setup.scene.sleep = a.sleep == "on" || (a.sleep == "auto" && sequence);
  std::vector<Candidate> candidates;
  for (const std::vector<io::CoilSpec>& c : chosen) {
    if (a.sensitivity) {
      for (Candidate& v : planning::sensitivityVariants(c, a.sensitivity->first, a.sensitivity->second))
        candidates.push_back(std::move(v));
    } else {
      candidates.push_back({c, "nominal", Vec3::Zero(), 0, {}});
    }
  }
  for (Candidate& c : candidates) c.sequence = sequenceName;
  std::error_code ec;
  std::filesystem::create_directories(a.out, ec);
  if (ec) return usage("cannot create " + a.out + ": " + ec.message());
  std::fprintf(stderr, "coilsim plan: %zu run(s) on %d thread(s), sac %.1f mm^3\n", candidates.size(), a.jobs,
               units::m3ToMm3(setup.sacVolume));
  const std::vector<CandidateResult> results = runCandidatesShowingProgress(setup, candidates, a.jobs, a.input);
  if (stopRequested())  // what ran is written below; the exit code says it is not all
    std::fprintf(stderr, "coilsim plan: %s: %zu of %zu run(s) finished, written\n", stopReason(), results.size(),
                 candidates.size());
  // What sleeping did, for whoever weighs its cost (docs/contact.md, "Sleeping coils").
  if (setup.scene.sleep)
    for (const CandidateResult& r : results)
      std::fprintf(stderr,
                   "coilsim plan: %s (%s): sleeping on: %d rod(s) asleep at the end; the last coil's run put %ld to "
                   "sleep and woke %ld\n",
                   r.name.c_str(), r.variant.c_str(), sleepingRods(r.state), r.state.sleep.sleeps, r.state.sleep.wakes);
  nlohmann::ordered_json pj = planning::planJson(setup, results);
  bool allOk = true;
  for (size_t i = 0; i < results.size(); ++i) {
    const CandidateResult& r = results[i];
    allOk = allOk && r.ok;
    if (!r.ok) std::fprintf(stderr, "coilsim plan: %s (%s): %s\n", r.name.c_str(), r.variant.c_str(), r.error.c_str());
    // A build without graphics writes the plan without pictures.
    if (!a.screenshots || r.state.rods.empty() || !haveUi()) continue;
    const std::string name = fileSafe(r.name + (r.variant == "nominal" ? "" : "-" + r.variant)) + ".png";
    std::string error;
    if (screenshot(setup, r, a, (std::filesystem::path(a.out) / name).string(), error))
      pj["coils"][i]["screenshot"] = name;
    else
      std::fprintf(stderr, "coilsim plan: no screenshot of %s: %s\n", r.name.c_str(), error.c_str());
  }
  io::writeFileAtomic((std::filesystem::path(a.out) / "plan.json").string(), io::formatJson(pj));
  const std::string md = planning::planMarkdown(pj);
  io::writeFileAtomic((std::filesystem::path(a.out) / "plan.md").string(), md);
  std::fputs(md.c_str(), stdout);
  if (stopRequested()) return stopExitCode();
  return allOk ? kExitOk : kExitFailure;
}

}  // namespace

// Several case files (e.g. two phantoms): one plan each in DIR/<case file name>/,
// and DIR/plan.md with every table. Returns the worst exit code.
int plans(const PlanArgs& a) {
  int worst = kExitOk;
  std::string md = "# Coil plans\n\n";
  for (const std::string& input : a.inputs) {
    PlanArgs one = a;
    one.input = input;
    const std::string sub = fileSafe(std::filesystem::path(input).stem().string());
    one.out = (std::filesystem::path(a.out) / sub).string();
    const int code = plan(one);
    if (code == kExitUsage || stopRequested()) return code;
    worst = std::max(worst, code);
    nlohmann::ordered_json pj = nlohmann::ordered_json::parse(io::readJsonFile((std::filesystem::path(one.out) / "plan.json").string()).dump());
    for (auto& c : pj["coils"])
      if (c.contains("screenshot")) c["screenshot"] = sub + "/" + c["screenshot"].get<std::string>();
    md += '#';  // each plan's title one level down; in steps: GCC 12 warns falsely on "#" + string
    md += planning::planMarkdown(pj);
    md += '\n';
  }
  io::writeFileAtomic((std::filesystem::path(a.out) / "plan.md").string(), md);
  return worst;
}

int runPlan(const std::vector<std::string>& args) {
  PlanArgs a;
  if (const std::string err = parseArgs(args, a); !err.empty()) return usage(err);
  try {
    return a.inputs.size() > 1 ? plans(a) : plan(a);
  } catch (const io::InputError& e) {
    std::fprintf(stderr, "coilsim plan: %s\n", e.what());
    return kExitUsage;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "coilsim plan: %s\n", e.what());
    return kExitFailure;
  }
}

int runPlanMerge(const std::vector<std::string>& args) {
  std::vector<std::string> dirs;
  std::string out;
  for (size_t i = 0; i < args.size(); ++i) {
    if (args[i] == "--out") {
      if (i + 1 >= args.size()) return usage("--out needs a directory");
      out = args[++i];
    } else if (!args[i].empty() && args[i][0] == '-') {
      return usage("unknown option \"" + args[i] + "\" for plan-merge");
    } else {
      dirs.push_back(args[i]);
    }
  }
  if (dirs.empty() || out.empty()) return usage("plan-merge needs plan directories and --out DIR");
  try {
    std::vector<std::string> files;
    for (const std::string& d : dirs) files.push_back((std::filesystem::path(d) / "plan.json").string());
    nlohmann::ordered_json merged = planning::mergePlans(files);
    std::error_code ec;
    std::filesystem::create_directories(out, ec);
    if (ec) return usage("cannot create " + out + ": " + ec.message());
    // Screenshots stay where their task wrote them: point at them from the merged table.
    size_t k = 0;
    for (size_t f = 0; f < dirs.size(); ++f) {
      const nlohmann::json part = io::readJsonFile(files[f]);
      for (size_t j = 0; j < part["coils"].size(); ++j, ++k)
        if (merged["coils"][k].contains("screenshot"))
          merged["coils"][k]["screenshot"] =
              std::filesystem::relative(std::filesystem::path(dirs[f]) / merged["coils"][k]["screenshot"].get<std::string>(), out)
                  .string();
    }
    io::writeFileAtomic((std::filesystem::path(out) / "plan.json").string(), io::formatJson(merged));
    const std::string md = planning::planMarkdown(merged);
    io::writeFileAtomic((std::filesystem::path(out) / "plan.md").string(), md);
    std::fputs(md.c_str(), stdout);
    return kExitOk;
  } catch (const io::InputError& e) {
    std::fprintf(stderr, "coilsim plan-merge: %s\n", e.what());
    return kExitUsage;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "coilsim plan-merge: %s\n", e.what());
    return kExitFailure;
  }
}

}  // namespace coilsim::app
