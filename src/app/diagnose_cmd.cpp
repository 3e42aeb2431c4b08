// `coilsim diagnose`: the candidate effects ranked by how much of the base
// model's residual each explains once fitted (docs/validation.md).
#include "app/diagnose_cmd.h"
#include "app/format.h"

#include <cmath>
#include <cstdio>
#include <algorithm>
#include <filesystem>
#include <memory>
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
               "usage: coilsim diagnose FILE... [--fit young_modulus_gpa,...] --out DIR [--candidates a,b]\n"
               "         [--spacing MM] [--push-increment MM] [--no-plots] [--quiet]\n"
               "(docs/validation.md)\n",
               message.c_str());
  return kExitUsage;
}

}  // namespace

namespace {

struct OneFile {
  Measurement m;
  std::string file;
};

// The diagnosis of one file: its JSON object, its Markdown, its summary lines.
void reportOne(const WorkbenchArgs& a, const OneFile& f, const StageSimulator& sim, const Comparison& cmp,
               const Diagnosis& d, const std::string& dir, ordered_json& j, std::string& mdOut, std::string& text) {
  const Measurement& m = f.m;
  j["file"] = f.file;
  j["measurement"] = m.name;
  j["discretisation"] = {{"beams", sim.beams()}, {"spacing_mm", a.spacingMm}, {"push_increment_mm", a.pushIncrementMm}};
  ordered_json base;
  base["stages"] = stagesJson(cmp, d.baselineStages);
  base["fitted"] = fittedJson(d.baseline.fitted);
  base["effects"] = ordered_json::array();
  base["rss_mm2"] = units::m2ToMm2(d.baseline.rss);
  base["prior_check"] = {{"implausible", d.implausible},
                         {"verdict", d.priorVerdict.empty() ? std::string("every fitted value is inside its plausible band")
                                                            : d.priorVerdict}};
  base["regularised"] = {{"fitted", fittedJson(d.regularisedBaseline.fitted)}, {"rss_mm2", units::m2ToMm2(d.regularisedBaseline.rss)}};
  j["baseline"] = base;
  auto candidateJson = [&](const CandidateResult& c) {
    ordered_json cj;
    cj["effect"] = c.effect;
    cj["explained_fraction"] = std::stod(fmt("%.6g", c.explainedFraction));
    cj["screened_fraction"] = std::stod(fmt("%.6g", c.screenedFraction));
    cj["refitted"] = c.refitted;
    cj["fitted"] = fittedJson(c.fit.fitted);
    if (c.freeFit.ok) cj["fitted_free"] = fittedJson(c.freeFit.fitted);
    ordered_json after = ordered_json::array();
    for (double e : c.stageErrorAfter) after.push_back(std::stod(fmt("%.6g", e)));
    cj["stage_error_after"] = after;
    cj["significant"] = c.significant;
    if (!c.note.empty()) cj["note"] = c.note;
    return cj;
  };
  ordered_json cands = ordered_json::array();
  for (const CandidateResult& c : d.candidates) cands.push_back(candidateJson(c));
  j["candidates"] = cands;
  ordered_json sel = ordered_json::array();
  for (const SelectionStep& s : d.selected) sel.push_back(candidateJson(s.result));
  j["selected"] = sel;
  j["fingerprint"] = fingerprintJson(d.fingerprint);
  j["final_stages"] = stagesJson(cmp, d.finalStages);
  j["adequacy"] = adequacyJson(d.adequacy);
  j["prediction"] = predictionJson(d.prediction);
  j["verdict"] = d.verdict;
  std::vector<std::string> written, warnings;
  if (a.plots) writePlots(dir, m, d.baselineStages, written, warnings);
  j["images"] = written;
  j["warnings"] = warnings;

  std::ostringstream md;
  md << "# Diagnosis of " << m.name << "\n\nFile `" << f.file << "`, " << sim.beams() << " beams.\n\n"
     << "## Baseline (the paper's model, fitted: ";
  for (const FittedValue& v : d.baseline.fitted) md << v.name << " = " << fmt("%.5g", v.value / v.toSI) << unitSuffix(v.unit) << " " << plusMinus(v.sigma / v.toSI, v.unit) << "; ";
  md << ")\n\n" << stageTable(m, d.baselineStages, {}) << "\n";
  md << "**Prior check:** " << (d.priorVerdict.empty() ? "every fitted value is inside its plausible band." : d.priorVerdict) << "\n\n";
  md << "## Candidates, best first (regularised fits)\n\n| effect | explained | significant | fitted | stage error after | note |\n|---|---|---|---|---|---|\n";
  for (const CandidateResult& c : d.candidates) {
    md << "| " << c.effect << " | " << fmt("%.1f %%", 100 * c.explainedFraction) << (c.refitted ? "" : " (screened)") << " | "
       << (c.significant ? "yes" : "no") << " | ";
    for (const FittedValue& v : c.fit.fitted)
      if (!isYoungModulus(v.name)) md << v.name << " = " << fmt("%.4g", v.value / v.toSI) << unitSuffix(v.unit) << " " << plusMinus(v.sigma / v.toSI, v.unit) << " ";
    md << "|";
    for (double e : c.stageErrorAfter) md << " " << fmt("%.4f", e);
    md << " | " << c.note << " |\n";
  }
  if (!d.selected.empty()) {
    md << "\n## Forward selection\n\n";
    for (size_t k = 0; k < d.selected.size(); ++k) {
      const SelectionStep& s = d.selected[k];
      md << k + 1 << ". " << s.effect << ": explains " << fmt("%.1f", 100 * s.explainedFraction)
         << " % of the residual left before it; fitted (regularised):";
      for (const FittedValue& v : s.result.fit.fitted) md << " " << v.name << " = " << fmt("%.4g", v.value / v.toSI) << unitSuffix(v.unit) << " " << plusMinus(v.sigma / v.toSI, v.unit) << ";";
      md << "\n";
    }
    if (d.selected.back().result.freeFit.ok) {
      md << "\nThe selected model fitted without priors:";
      for (const FittedValue& v : d.selected.back().result.freeFit.fitted) md << " " << v.name << " = " << fmt("%.4g", v.value / v.toSI) << unitSuffix(v.unit) << ";";
      md << "\n";
    }
  }
  md << "\n**Verdict:** " << d.verdict << "\n\n**Fingerprint of the baseline residual:** " << d.fingerprint.summary << "\n\n";
  md << "## The final model\n\n" << stageTable(m, d.finalStages, {}) << "\n" << adequacyMarkdown(d.adequacy, d.prediction);
  for (const std::string& w : written) md << "![" << w << "](" << w << ")\n";
  for (const std::string& w : warnings) md << "\nWarning: " << w << "\n";
  mdOut = md.str();

  std::ostringstream t;
  t << f.file << "\nbaseline:\n" << stageTable(m, d.baselineStages, {});
  for (const FittedValue& v : d.baseline.fitted)
    t << "  " << v.name << " = " << fmt("%.4g", v.value / v.toSI) << unitSuffix(v.unit) << " " << plusMinus(v.sigma / v.toSI, v.unit) << "\n";
  for (const CandidateResult& c : d.candidates)
    t << "  " << c.effect << std::string(c.effect.size() < 20 ? 20 - c.effect.size() : 0, ' ')
      << " explains " << fmt("%5.1f", 100 * c.explainedFraction) << " %" << (c.significant ? "  significant" : "")
      << (c.note.empty() ? "" : "  (" + c.note + ")") << "\n";
  if (!d.selected.empty()) {
    t << "selected model (regularised fit):";
    for (const FittedValue& v : d.selected.back().result.fit.fitted)
      t << " " << v.name << " = " << fmt("%.4g", v.value / v.toSI) << unitSuffix(v.unit) << " " << plusMinus(v.sigma / v.toSI, v.unit) << ";";
    t << "\n";
  }
  t << d.verdict << "\n" << d.fingerprint.summary << "\nadequacy: " << d.adequacy.verdict << "\nprediction: " << d.prediction.message << "\n";
  text = t.str();
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
  std::vector<OneFile> files;
  std::vector<DiagnoseOptions> opts;
  try {
    for (const std::string& file : a.files) {
      OneFile f{io::readMeasurement(file), file};
      DiagnoseOptions o;
      o.fit = expandFitNames(a.fit, f.m);
      const ModelParams p = ModelParams::nominal(f.m);
      for (const std::string& name : o.fit) {
        std::string why;
        if (!isYoungModulus(name) && !describeParam(name, p, f.m, why)) return usage("--fit: " + why + " (diagnose fits model parameters only)");
      }
      for (const std::string& c : candidateNames) {
        (void)EffectRegistry::global().use(c);  // throws naming an unknown effect
        o.candidates.push_back(candidateFor(c, f.m));
      }
      files.push_back(f);
      opts.push_back(o);
    }
  } catch (const io::InputError& e) {
    std::fprintf(stderr, "coilsim: %s\n", e.what());
    return kExitUsage;
  } catch (const std::invalid_argument& e) {
    return usage(std::string("--candidates: ") + e.what());
  }
  if (!makeOutputDirectory("diagnose", a.out)) return kExitUsage;
  const bool several = files.size() > 1;
  std::vector<std::unique_ptr<StageSimulator>> sims;
  std::vector<std::unique_ptr<Comparison>> cmps;
  ordered_json j, perFile = ordered_json::array();
  std::string md, text;
  for (size_t i = 0; i < files.size(); ++i) {
    const OneFile& f = files[i];
    sims.push_back(std::make_unique<StageSimulator>(f.m, simOptionsOf(a)));
    cmps.push_back(std::make_unique<Comparison>(f.m));
    StageSimulator& sim = *sims.back();
    const Comparison& cmp = *cmps.back();
    say("diagnose: " + f.file + ": " + std::to_string(f.m.stages.size()) + " stage(s), " + std::to_string(sim.beams()) + " beams");
    DiagnoseOptions o = opts[i];
    Progress progress("diagnose " + f.file, 0, "phases");
    int phases = 0;
    o.progress = [&](const std::string& s) {
      progress.update(++phases, s);
      if (!a.quiet) progress.line("diagnose: " + s);
    };
    const Diagnosis d = diagnose(sim, cmp, ModelParams::nominal(f.m), o);
    if (!d.ok) {
      std::fprintf(stderr, "coilsim diagnose: %s: %s\n", f.file.c_str(), d.message.c_str());
      return exitCodeOf(d.failure);
    }
    const std::string dir = several ? (std::filesystem::path(a.out) / ("file" + std::to_string(i + 1))).string() : a.out;
    if (several && !makeOutputDirectory("diagnose", dir)) return kExitUsage;
    ordered_json one;
    one["format"] = "coilsim-diagnosis/1";
    std::string m1, t1;
    reportOne(a, f, sim, cmp, d, dir, one, m1, t1);
    if (several) {
      one.erase("format");
      perFile.push_back(one);
    } else {
      j = one;
    }
    md += m1, text += t1;
  }
  if (several) {
    std::vector<JointFile> jf;
    std::vector<std::string> fit = expandFitNames(a.fit, files[0].m);
    if (std::none_of(fit.begin(), fit.end(), isYoungModulus)) fit.insert(fit.begin(), youngModulusFit());
    for (size_t i = 0; i < files.size(); ++i) jf.push_back({sims[i].get(), cmps[i].get(), ModelParams::nominal(files[i].m)});
    // One coil: the first file's nominal coil values for all (each keeps its setup).
    for (JointFile& f : jf) f.start.coil.youngModulus = jf[0].start.coil.youngModulus, f.start.coil.poissonRatio = jf[0].start.coil.poissonRatio;
    const JointDiagnosis jd = diagnoseJoint(jf, fit, [&](const std::string& s) { say("diagnose: " + s); });
    j["format"] = "coilsim-diagnosis/1";
    j["files"] = perFile;
    j["joint"] = jointJson(jd, a.files);
    md = jointMarkdown(jd, a.files) + md;
    text += "joint: " + (jd.ok ? jd.verdict : jd.message) + "\n";
  }
  try {
    io::writeFileAtomic((std::filesystem::path(a.out) / "diagnosis.json").string(), io::formatJson(j));
    io::writeFileAtomic((std::filesystem::path(a.out) / "diagnosis.md").string(), md);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "coilsim diagnose: %s\n", e.what());
    return kExitUsage;
  }
  std::printf("%sdiagnosis: %s\n", text.c_str(), (std::filesystem::path(a.out) / "diagnosis.json").string().c_str());
  return kExitOk;
}

}  // namespace coilsim::app
