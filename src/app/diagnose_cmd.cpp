// `coilsim diagnose`: the candidate effects ranked by how much of the base
// model's residual each explains once fitted (docs/validation.md).
#include "app/diagnose_cmd.h"
#include "app/format.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>

#include "app/exit_codes.h"
#include "app/progress.h"
#include "app/validate_cmd.h"
#include "io/json_reader.h"
#include "io/json_writer.h"
#include "io/measurement.h"
#include "io/units.h"

namespace coilsim::app {
namespace {

using nlohmann::ordered_json;
using namespace validation;

int usage(const std::string& message) {
  std::fprintf(stderr,
               "coilsim diagnose: %s\n"
               "usage: coilsim diagnose FILE [--fit young_modulus,...] --out DIR [--candidates a,b]\n"
               "         [--spacing MM] [--push-increment MM] [--no-plots] [--quiet]\n"
               "(docs/validation.md)\n",
               message.c_str());
  return kExitUsage;
}

}  // namespace

int runDiagnose(const std::vector<std::string>& argsIn) {
  // --candidates is diagnose's own; the rest is shared with validate.
  std::vector<std::string> args, candidateNames;
  for (size_t i = 0; i < argsIn.size(); ++i) {
    if (argsIn[i] == "--candidates") {
      if (i + 1 >= argsIn.size()) return usage("--candidates needs a list of effects, e.g. buoyancy,gravity_tilt");
      candidateNames = splitList(argsIn[++i]);
      if (candidateNames.empty()) return usage("--candidates needs at least one effect");
    } else {
      args.push_back(argsIn[i]);
    }
  }
  WorkbenchArgs a;
  if (const std::string e = parseWorkbenchArgs(args, false, a); !e.empty()) return usage(e);
  auto say = [&](const std::string& s) {
    if (!a.quiet) std::fprintf(stderr, "%s\n", s.c_str());
  };
  Measurement m;
  DiagnoseOptions o;
  try {
    m = io::readMeasurement(a.file);
    o.fit = expandFitNames(a.fit, m);
    const ModelParams p = ModelParams::nominal(m);
    for (const std::string& f : o.fit) {
      std::string why;
      if (f != "young_modulus" && !describeParam(f, p, m, why)) return usage("--fit: " + why + " (diagnose fits model parameters only)");
    }
    for (const std::string& c : candidateNames) {
      (void)EffectRegistry::global().use(c);  // throws naming an unknown effect
      o.candidates.push_back(candidateFor(c, m));
    }
  } catch (const io::InputError& e) {
    std::fprintf(stderr, "coilsim: %s\n", e.what());
    return kExitUsage;
  } catch (const std::invalid_argument& e) {
    return usage(std::string("--candidates: ") + e.what());
  }
  if (!makeOutputDirectory("diagnose", a.out)) return kExitUsage;
  StageSimulator sim(m, simOptionsOf(a));
  const Comparison cmp(m);
  say("diagnose: " + a.file + ": " + std::to_string(m.stages.size()) + " stage(s), " + std::to_string(sim.beams()) + " beams");
  Progress progress("diagnose " + a.file, 0, "phases");
  int phases = 0;
  o.progress = [&](const std::string& s) {
    progress.update(++phases, s);
    if (!a.quiet) progress.line("diagnose: " + s);
  };
  const Diagnosis d = diagnose(sim, cmp, ModelParams::nominal(m), o);
  if (!d.ok) {
    std::fprintf(stderr, "coilsim diagnose: %s\n", d.message.c_str());
    return kExitFailure;
  }

  ordered_json j;
  j["format"] = "coilsim-diagnosis/1";
  j["file"] = a.file;
  j["measurement"] = m.name;
  j["discretisation"] = {{"beams", sim.beams()}, {"spacing_mm", a.spacingMm}, {"push_increment_mm", a.pushIncrementMm}};
  ordered_json base;
  base["stages"] = stagesJson(cmp, d.baselineStages);
  base["fitted"] = fittedJson(d.baseline.fitted);
  base["effects"] = ordered_json::array();
  base["rss_mm2"] = d.baseline.rss * 1e6;
  j["baseline"] = base;
  ordered_json cands = ordered_json::array();
  for (const CandidateResult& c : d.candidates) {
    ordered_json cj;
    cj["effect"] = c.effect;
    cj["explained_fraction"] = std::stod(fmt("%.6g", c.explainedFraction));
    cj["screened_fraction"] = std::stod(fmt("%.6g", c.screenedFraction));
    cj["refitted"] = c.refitted;
    cj["fitted"] = fittedJson(c.fit.fitted);
    ordered_json after = ordered_json::array();
    for (double e : c.stageErrorAfter) after.push_back(std::stod(fmt("%.6g", e)));
    cj["stage_error_after"] = after;
    cj["significant"] = c.significant;
    if (!c.note.empty()) cj["note"] = c.note;
    cands.push_back(cj);
  }
  j["candidates"] = cands;
  j["fingerprint"] = fingerprintJson(d.fingerprint);
  j["verdict"] = d.verdict;
  std::vector<std::string> written, warnings;
  if (a.plots) writePlots(a.out, m, d.baselineStages, written, warnings);
  j["images"] = written;
  j["warnings"] = warnings;

  std::ostringstream md;
  md << "# Diagnosis of " << m.name << "\n\nFile `" << a.file << "`, " << sim.beams() << " beams.\n\n"
     << "## Baseline (the paper's model, fitted: ";
  for (const FittedValue& v : d.baseline.fitted) md << v.name << " = " << fmt("%.5g", v.value / v.toSI) << unitSuffix(v.unit) << " " << plusMinus(v.sigma / v.toSI, v.unit) << "; ";
  md << ")\n\n" << stageTable(m, d.baselineStages, {}) << "\n";
  md << "## Candidates, best first\n\n| effect | explained | significant | fitted | stage error after | note |\n|---|---|---|---|---|---|\n";
  for (const CandidateResult& c : d.candidates) {
    md << "| " << c.effect << " | " << fmt("%.1f %%", 100 * c.explainedFraction) << (c.refitted ? "" : " (screened)") << " | "
       << (c.significant ? "yes" : "no") << " | ";
    for (const FittedValue& v : c.fit.fitted)
      if (v.name != "young_modulus") md << v.name << " = " << fmt("%.4g", v.value / v.toSI) << unitSuffix(v.unit) << " " << plusMinus(v.sigma / v.toSI, v.unit) << " ";
    md << "|";
    for (double e : c.stageErrorAfter) md << " " << fmt("%.4f", e);
    md << " | " << c.note << " |\n";
  }
  md << "\n**Verdict:** " << d.verdict << "\n\n**Fingerprint of the baseline residual:** " << d.fingerprint.summary << "\n\n";
  for (const std::string& w : written) md << "![" << w << "](" << w << ")\n";
  for (const std::string& w : warnings) md << "\nWarning: " << w << "\n";
  try {
    io::writeFileAtomic((std::filesystem::path(a.out) / "diagnosis.json").string(), io::formatJson(j));
    io::writeFileAtomic((std::filesystem::path(a.out) / "diagnosis.md").string(), md.str());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "coilsim diagnose: %s\n", e.what());
    return kExitUsage;
  }
  std::printf("baseline:\n%s", stageTable(m, d.baselineStages, {}).c_str());
  for (const CandidateResult& c : d.candidates) {
    std::printf("  %-20s explains %5.1f %%%s%s\n", c.effect.c_str(), 100 * c.explainedFraction, c.significant ? "  significant" : "",
                c.note.empty() ? "" : ("  (" + c.note + ")").c_str());
  }
  std::printf("%s\n%s\ndiagnosis: %s\n", d.verdict.c_str(), d.fingerprint.summary.c_str(),
              (std::filesystem::path(a.out) / "diagnosis.json").string().c_str());
  return kExitOk;
}

}  // namespace coilsim::app
