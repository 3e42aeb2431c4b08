// `coilsim validate`: the model against a measurement, before and after
// switching effects on and fitting parameters (docs/validation.md).
#include "app/validate_cmd.h"
#include "app/format.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <sstream>

#include "app/commands.h"
#include "app/exit_codes.h"
#include "app/options.h"
#include "app/progress.h"
#include "app/stop_signal.h"
#include "app/validate_plots.h"
#include "app/validate_window.h"
#include "io/json_reader.h"
#include "io/json_writer.h"
#include "io/measurement.h"
#include "io/units.h"

namespace coilsim::app {
namespace {

using nlohmann::ordered_json;
using namespace validation;

// Why one of the `fit` names cannot be fitted for `m` from `start` (empty: all can).
std::string unknownFitName(const std::vector<std::string>& fit, const ModelParams& start, const Measurement& m) {
  for (const std::string& f : fit) {
    std::string why;
    if (!describeParam(f, start, m, why)) return why;
  }
  return "";
}

int usage(const std::string& message) {
  std::fprintf(stderr,
               "coilsim validate: %s\n"
               "usage: coilsim validate FILE... [--effects a,b] [--fit young_modulus_gpa,...] --out DIR\n"
               "         [--spacing MM] [--push-increment MM] [--no-plots] [--quiet]\n"
               "       coilsim validate FILE --window [--effects a,b] [--fit ...] [--size WxH]   (the panel)\n"
               "       coilsim validate FILE --screenshot PNG [--toggle a,b] [--auto-fit] [--size WxH]   (the panel off-screen)\n"
               "(docs/validation.md)\n",
               message.c_str());
  return kExitUsage;
}

// Rounds to 6 significant digits for the report (the data hold 3 or 4).
double r6(double v) { return std::isfinite(v) ? std::stod(fmt("%.6g", v)) : v; }

}  // namespace

SimOptions simOptionsOf(const WorkbenchArgs& a) {
  SimOptions so;
  so.spacing = units::mmToM(a.spacingMm);
  so.pushIncrement = units::mmToM(a.pushIncrementMm);
  return so;
}

bool makeOutputDirectory(const std::string& command, const std::string& dir) {
  try {
    std::filesystem::create_directories(dir);
    return true;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "coilsim %s: cannot create the output directory %s: %s\n", command.c_str(), dir.c_str(), e.what());
    return false;
  }
}

std::string parseWorkbenchArgs(const std::vector<std::string>& args, bool allowEffects, WorkbenchArgs& a) {
  for (size_t i = 0; i < args.size(); ++i) {
    const std::string& arg = args[i];
    std::string v;
    auto value = [&]() {
      if (i + 1 >= args.size()) return false;
      v = args[++i];
      return true;
    };
    auto millimetres = [&](double& out) -> std::string {
      double d = 0;
      if (!value()) return arg + " needs a length in mm";
      const auto [end, ec] = std::from_chars(v.data(), v.data() + v.size(), d);
      if (ec != std::errc() || end != v.data() + v.size() || !std::isfinite(d) || !(d > 0) || d > 100)
        return arg + " needs a length in mm in (0, 100], got \"" + v + "\"";
      out = d;
      return "";
    };
    if (arg == "--out") {
      if (!value() || v.empty()) return "--out needs a directory";
      a.out = v;
    } else if (arg == "--effects" && allowEffects) {
      if (!value()) return "--effects needs a list of effects, e.g. buoyancy,drag";
      a.effects = splitList(v);
    } else if (arg == "--fit") {
      if (!value()) return "--fit needs a list of parameters, e.g. young_modulus_gpa,buoyancy";
      a.fit = splitList(v);
      for (const std::string& n : a.fit)
        if (const std::string note = oldFitNameNote(n); !note.empty()) std::fprintf(stderr, "coilsim: note: %s\n", note.c_str());
    } else if (arg == "--spacing") {
      if (std::string e = millimetres(a.spacingMm); !e.empty()) return e;
    } else if (arg == "--push-increment") {
      if (std::string e = millimetres(a.pushIncrementMm); !e.empty()) return e;
    } else if (arg == "--no-plots") {
      a.plots = false;
    } else if (arg == "--quiet") {
      a.quiet = true;
    } else if (arg.size() > 1 && arg[0] == '-') {
      return "unknown option \"" + arg + "\"";
    } else {
      a.files.push_back(arg);
    }
  }
  if (a.files.empty()) return "a measurement file (coil-measurement/1) is needed";
  a.file = a.files.front();
  if (a.out.empty()) return "--out DIR is needed";
  return "";
}

std::vector<std::string> expandFitNames(const std::vector<std::string>& names, const Measurement& m) {
  std::vector<std::string> out;
  // A parameter named twice (young_modulus and young_modulus_gpa) is fitted once, under its first name.
  auto add = [&](const std::string& n) {
    for (const std::string& o : out)
      if (canonicalFitName(o) == canonicalFitName(n)) return;
    out.push_back(n);
  };
  for (const std::string& n : names) {
    if (n.find('.') == std::string::npos && EffectRegistry::global().find(n)) {
      for (const std::string& p : candidateFor(n, m).params) add(p);
    } else {
      add(n);
    }
  }
  return out;
}

ordered_json stagesJson(const Comparison& cmp, const std::vector<StageComparison>& stages) {
  const Measurement& m = cmp.measurement();
  const Fingerprint f = fingerprint(cmp, stages);
  ordered_json out = ordered_json::array();
  for (size_t k = 0; k < stages.size(); ++k) {
    const StageComparison& s = stages[k];
    const StageMetrics& q = s.metrics;
    ordered_json j;
    j["name"] = m.stages[k].name;
    j["deployed_length_mm"] = r6(units::mToMm(m.stages[k].deployed));
    j["ok"] = s.ok();
    if (!s.ok()) {
      j["message"] = s.message();
      out.push_back(j);
      continue;
    }
    j["node_error_mean"] = r6(q.nodeErrorMean);
    j["node_error_sd"] = r6(q.nodeErrorSd);
    j["nodes_counted"] = q.nodesCounted;
    j["stage_error"] = r6(q.stageError);
    j["mean_displacement_mm"] = r6(units::mToMm(q.meanDisplacement));
    j["mean_distance_mm"] = r6(units::mToMm(q.meanDistance));
    j["point_sigma_mm"] = r6(units::mToMm(s.sigma));
    // Where the residual lies: its RMS per node split along gravity, along
    // the coil (horizontal) and across; its share in each third of the arc
    // length; and whether it is above the noise floor (RMS per coordinate > 1.5 sigma).
    j["rms_residual_mm"] = r6(units::mToMm(f.rmsTotal[k]));
    j["rms_along_gravity_mm"] = r6(units::mToMm(f.rmsAlongGravity[k]));
    j["rms_along_coil_mm"] = r6(units::mToMm(f.rmsAlongCoil[k]));
    j["rms_across_mm"] = r6(units::mToMm(f.rmsAcross[k]));
    j["share_proximal"] = r6(f.shareProximal[k]);
    j["share_middle"] = r6(f.shareMiddle[k]);
    j["share_distal"] = r6(f.shareDistal[k]);
    j["above_noise"] = f.rmsTotal[k] / std::sqrt(3.0) > 1.5 * s.sigma;
    out.push_back(j);
  }
  return out;
}

ordered_json fittedJson(const std::vector<FittedValue>& fitted) {
  ordered_json j = ordered_json::object();
  for (const FittedValue& v : fitted) {
    j[v.name] = {{"value", r6(v.value / v.toSI)},
                 {"sigma", v.identifiable ? ordered_json(r6(v.sigma / v.toSI)) : ordered_json(nullptr)},
                 {"unit", v.unit},
                 {"identifiable", v.identifiable}};
    if (v.prior.known)
      j[v.name]["prior"] = {{"nominal", r6(v.prior.nominal / v.toSI)},
                            {"plausible_low", r6(v.prior.low / v.toSI)},
                            {"plausible_high", r6(v.prior.high / v.toSI)},
                            {"deviation", r6(v.priorDeviation)},
                            {"plausible", v.plausible}};
  }
  return j;
}

std::string priorCheckText(const std::vector<FittedValue>& fitted) {
  std::string out;
  for (const FittedValue& v : fitted)
    if (v.prior.known && !v.plausible)
      out += (out.empty() ? "" : "; ") + v.name + " = " + fmt("%.4g", v.value / v.toSI) + unitSuffix(v.unit) + " is " +
             fmt("%.2f", v.value / v.prior.nominal) + "x its nominal " + fmt("%.4g", v.prior.nominal / v.toSI) +
             ", outside the plausible " + fmt("%.4g", v.prior.low / v.toSI) + "-" + fmt("%.4g", v.prior.high / v.toSI) +
             unitSuffix(v.unit);
  return out.empty() ? out : "Implausible: " + out + ": evidence that the model lacks something the fit absorbs.";
}

ordered_json adequacyJson(const Adequacy& a) {
  ordered_json j;
  j["explained"] = a.explained;
  j["verdict"] = a.verdict;
  ordered_json st = ordered_json::array();
  for (const StageAdequacy& s : a.stages)
    st.push_back({{"name", s.stage}, {"reduced_chi2", r6(s.reducedChi2)}, {"critical_999", r6(s.critical)},
                  {"noise_floor_rms_mm", r6(units::mToMm(s.noiseFloor))}, {"at_noise", s.atNoise}});
  j["stages"] = st;
  j["remaining_fingerprint"] = fingerprintJson(a.remaining);
  return j;
}

ordered_json predictionJson(const PredictionCheck& p) {
  ordered_json j;
  j["done"] = p.done;
  j["message"] = p.message;
  if (p.done) {
    j["stage"] = p.stage;
    j["fitted_stage_error"] = r6(p.fittedError);
    j["predicted_stage_error"] = r6(p.predictedError);
    j["predicted_over_fitted"] = r6(p.ratio);
  }
  return j;
}

std::string adequacyMarkdown(const Adequacy& a, const PredictionCheck& p) {
  std::ostringstream md;
  md << "## Adequacy (chi-square per stage against the noise)\n\n"
     << "| stage | reduced chi2 | noise floor (mm per node) | 99.9 % bound | at the noise |\n|---|---|---|---|---|\n";
  for (const StageAdequacy& s : a.stages)
    md << "| " << s.stage << " | " << fmt("%.3g", s.reducedChi2) << " | " << fmt("%.4f", units::mToMm(s.noiseFloor)) << " | "
       << fmt("%.3g", s.critical) << " | " << (s.atNoise ? "yes" : "no") << " |\n";
  md << "\n**" << a.verdict << "**\n\n## Prediction check\n\n" << p.message << ".\n\n";
  return md.str();
}

ordered_json jointJson(const JointDiagnosis& d, const std::vector<std::string>& files) {
  ordered_json j;
  j["files"] = files;
  j["ok"] = d.ok;
  if (!d.ok) {
    j["message"] = d.message;
    return j;
  }
  j["fitted_jointly"] = fittedJson(d.joint.fitted);
  j["rss_joint_mm2"] = r6(units::m2ToMm2(d.joint.rss));
  ordered_json sp = ordered_json::array();
  for (const ParameterSpread& s : d.spread) {
    ordered_json per = ordered_json::array(), sig = ordered_json::array();
    for (size_t i = 0; i < s.perFile.size(); ++i) {
      per.push_back(r6(s.perFile[i] / s.toSI));
      sig.push_back(std::isfinite(s.sigmaPerFile[i]) ? ordered_json(r6(s.sigmaPerFile[i] / s.toSI)) : ordered_json(nullptr));
    }
    sp.push_back({{"param", s.param}, {"unit", s.unit}, {"joint", r6(s.joint / s.toSI)}, {"per_file", per},
                  {"sigma_per_file", sig}, {"explained_by_differing", r6(s.explainedFraction)}, {"must_differ", s.mustDiffer}});
  }
  j["spread"] = sp;
  ordered_json ef = ordered_json::array();
  for (const JointEffect& e : d.effects) {
    ordered_json per = ordered_json::array();
    for (double v : e.perFileAfter) per.push_back(r6(v / (d.spread.empty() ? 1 : d.spread[0].toSI)));
    ef.push_back({{"effect", e.effect}, {"explained_fraction", r6(e.explainedFraction)}, {"significant", e.significant},
                  {"removes_spread", e.removesSpread}, {"fitted_jointly", fittedJson(e.fit.fitted)}, {"per_file_after", per}});
  }
  j["effects"] = ef;
  j["verdict"] = d.verdict;
  return j;
}

std::string jointMarkdown(const JointDiagnosis& d, const std::vector<std::string>& files) {
  std::ostringstream md;
  md << "## Joint fit of " << files.size() << " files of one coil\n\n";
  if (!d.ok) return md.str() + d.message + "\n";
  md << "| parameter | joint |";
  for (const std::string& f : files) md << " " << std::filesystem::path(f).filename().string() << " alone |";
  md << "\n|---|---|";
  for (size_t i = 0; i < files.size(); ++i) md << "---|";
  md << "\n";
  for (const ParameterSpread& s : d.spread) {
    md << "| " << s.param << " | " << fmt("%.4g", s.joint / s.toSI) << unitSuffix(s.unit) << " |";
    for (size_t i = 0; i < s.perFile.size(); ++i)
      md << " " << fmt("%.4g", s.perFile[i] / s.toSI) << " " << plusMinus(s.sigmaPerFile[i] / s.toSI, s.unit) << " |";
    md << "\n";
  }
  for (const JointEffect& e : d.effects)
    md << "\n- " << e.effect << " on in every file: explains " << fmt("%.1f", 100 * e.explainedFraction) << " % of the joint residual"
       << (e.significant ? " (significant)" : "") << (e.removesSpread ? ", and one value then fits all files" : "") << ".";
  md << "\n\n**" << d.verdict << "**\n\n";
  return md.str();
}

ordered_json fingerprintJson(const Fingerprint& f) {
  ordered_json j;
  j["summary"] = f.summary;
  j["above_noise"] = f.aboveNoise;
  j["growth_exponent"] = r6(f.growthExponent);
  auto mm = [](const std::vector<double>& v) {
    ordered_json a = ordered_json::array();
    for (double x : v) a.push_back(r6(units::mToMm(x)));
    return a;
  };
  auto plain = [](const std::vector<double>& v) {
    ordered_json a = ordered_json::array();
    for (double x : v) a.push_back(r6(x));
    return a;
  };
  j["rms_residual_mm"] = mm(f.rmsTotal);
  j["rms_along_gravity_mm"] = mm(f.rmsAlongGravity);
  j["rms_along_coil_mm"] = mm(f.rmsAlongCoil);
  j["rms_across_mm"] = mm(f.rmsAcross);
  j["share_proximal"] = plain(f.shareProximal);
  j["share_middle"] = plain(f.shareMiddle);
  j["share_distal"] = plain(f.shareDistal);
  return j;
}

std::string stageTable(const Measurement& m, const std::vector<StageComparison>& before,
                       const std::vector<StageComparison>& after) {
  std::ostringstream t;
  auto cells = [&](const StageComparison& s) {
    if (!s.ok()) return std::string(" failed | | | |");
    const StageMetrics& q = s.metrics;
    char buf[160];
    std::snprintf(buf, sizeof buf, " %.4f | %.3f +- %.3f | %.3f | %.3f |", q.stageError, q.nodeErrorMean, q.nodeErrorSd,
                  units::mToMm(q.meanDisplacement), units::mToMm(q.meanDistance));
    return std::string(buf);
  };
  const bool two = !after.empty();
  t << "| stage | deployed (mm) | stage error | node error mean +- SD | mean displacement (mm) | mean distance (mm) |"
    << (two ? " stage error after | node error after | mean displacement after (mm) | mean distance after (mm) |" : "") << "\n";
  t << "|---|---|---|---|---|---|" << (two ? "---|---|---|---|" : "") << "\n";
  for (size_t k = 0; k < before.size(); ++k) {
    t << "| " << m.stages[k].name << " | " << fmt("%.1f", units::mToMm(m.stages[k].deployed)) << " |" << cells(before[k]);
    if (two) t << cells(after[k]);
    t << "\n";
  }
  return t.str();
}

void writePlots(const std::string& dir, const Measurement& m, const std::vector<StageComparison>& stages,
                std::vector<std::string>& written, std::vector<std::string>& warnings) {
  namespace fs = std::filesystem;
  std::vector<std::string> names;
  for (const Stage& s : m.stages) names.push_back(s.name);
  std::string err;
  const std::string arc = (fs::path(dir) / "error_along_arc.png").string();
  if (savePng(arc, plotErrorAlongArc(stages, names), err)) written.push_back("error_along_arc.png");
  else return warnings.push_back(err);
  for (size_t k = 0; k < stages.size(); ++k) {
    if (!stages[k].ok()) continue;
    const std::string name = "overlay_stage" + std::to_string(k + 1) + ".png";
    const std::string title = m.name + ", " + m.stages[k].name + ": stage error " + fmt("%.4f", stages[k].metrics.stageError);
    if (savePng((fs::path(dir) / name).string(), plotOverlay(stages[k], m.stages[k], m.gravity, m.tip.direction, title), err))
      written.push_back(name);
    else
      warnings.push_back(err);
  }
}

namespace {

// Several files of one coil: the fitted parameters shared, each file its own
// setup and its effects' values from that setup (joint.h).
int runValidateJoint(const WorkbenchArgs& a) {
  auto say = [&](const std::string& s) {
    if (!a.quiet) std::fprintf(stderr, "%s\n", s.c_str());
  };
  std::vector<Measurement> ms;
  std::vector<ModelParams> starts;
  std::vector<std::string> fit;
  try {
    for (const std::string& file : a.files) {
      ms.push_back(io::readMeasurement(file));
      ModelParams p = ModelParams::nominal(ms.back());
      if (!starts.empty()) p.coil.youngModulus = starts[0].coil.youngModulus, p.coil.poissonRatio = starts[0].coil.poissonRatio;  // one coil
      for (const std::string& e : a.effects) p.effects.push_back(effectFromFile(e, ms.back()));
      starts.push_back(p);
    }
    fit = expandFitNames(a.fit, ms[0]);
    if (const std::string why = unknownFitName(fit, starts[0], ms[0]); !why.empty()) return usage("--fit: " + why);
  } catch (const io::InputError& e) {
    std::fprintf(stderr, "coilsim: %s\n", e.what());
    return kExitUsage;
  } catch (const std::invalid_argument& e) {
    return usage(std::string("--effects: ") + e.what());
  }
  if (!makeOutputDirectory("validate", a.out)) return kExitUsage;
  std::vector<std::unique_ptr<StageSimulator>> sims;
  std::vector<std::unique_ptr<Comparison>> cmps;
  std::vector<JointFile> jf;
  for (size_t i = 0; i < ms.size(); ++i) {
    sims.push_back(std::make_unique<StageSimulator>(ms[i], simOptionsOf(a)));
    cmps.push_back(std::make_unique<Comparison>(ms[i]));
    jf.push_back({sims.back().get(), cmps.back().get(), starts[i]});
  }
  JointDiagnosis jd;
  std::vector<ModelParams> fitted = starts;
  if (!fit.empty()) {
    jd = diagnoseJoint(jf, fit, [&](const std::string& s) { say("validate: " + s); });
    if (jd.ok) fitted = jd.joint.memberParams;
  }
  ordered_json j, per = ordered_json::array();
  j["format"] = "coilsim-validation-report/1";
  j["effects"] = a.effects;
  j["fit"] = fit;
  std::ostringstream md, text;
  md << "# Validation of " << ms.size() << " files of one coil\n\nEffects on: "
     << (a.effects.empty() ? std::string("none (the base model)") : ordered_json(a.effects).dump())
     << "; fitted jointly: " << (fit.empty() ? std::string("nothing (nominal values)") : ordered_json(fit).dump()) << ".\n\n";
  if (!fit.empty()) md << jointMarkdown(jd, a.files);
  // The first failure decides the exit code (exitCodeOf): the joint fit's, else a stage's.
  int code = !fit.empty() && !jd.ok ? exitCodeOf(jd.failure) : kExitOk;
  for (size_t i = 0; i < ms.size(); ++i) {
    const std::vector<StageComparison> before = cmps[i]->compare(sims[i]->run(ModelParams::nominal(ms[i]), false));
    const std::vector<StageComparison> after = cmps[i]->compare(sims[i]->run(fitted[i], false));
    const Adequacy adq = adequacy(*cmps[i], after);
    ordered_json f;
    f["file"] = a.files[i];
    f["measurement"] = ms[i].name;
    f["stages"] = stagesJson(*cmps[i], after);
    f["stages_before"] = stagesJson(*cmps[i], before);
    f["adequacy"] = adequacyJson(adq);
    per.push_back(f);
    md << "## " << ms[i].name << " (`" << a.files[i] << "`)\n\n" << stageTable(ms[i], before, after) << "\n**"
       << adq.verdict << "**\n\n";
    text << a.files[i] << "\n" << stageTable(ms[i], before, after) << "adequacy: " << adq.verdict << "\n";
    for (const StageComparison& s : after)
      if (!s.ok() && code == kExitOk) code = exitCodeOf(*s.failure);
  }
  j["files"] = per;
  if (!fit.empty()) j["joint"] = jointJson(jd, a.files);
  try {
    io::writeFileAtomic((std::filesystem::path(a.out) / "report.json").string(), io::formatJson(j));
    io::writeFileAtomic((std::filesystem::path(a.out) / "report.md").string(), md.str());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "coilsim validate: %s\n", e.what());
    return kExitUsage;
  }
  std::printf("%s", text.str().c_str());
  if (!fit.empty()) {
    if (jd.ok)
      for (const FittedValue& v : jd.joint.fitted)
        std::printf("%s = %.5g%s %s (joint)\n", v.name.c_str(), v.value / v.toSI, unitSuffix(v.unit).c_str(),
                    plusMinus(v.sigma / v.toSI, v.unit).c_str());
    std::printf("joint: %s\n", jd.ok ? jd.verdict.c_str() : jd.message.c_str());
  }
  std::printf("report: %s\n", (std::filesystem::path(a.out) / "report.json").string().c_str());
  return code;
}

}  // namespace

int runValidate(const std::vector<std::string>& args) {
  // The panel's own options first; the rest are the workbench's.
  WindowArgs w;
  std::vector<std::string> rest;
  bool sized = false;
  for (size_t i = 0; i < args.size(); ++i) {
    if (args[i] == "--window") {
      w.window = true;
    } else if (args[i] == "--auto-fit") {
      w.autoFit = true;
    } else if (args[i] == "--screenshot" || args[i] == "--toggle" || args[i] == "--size") {
      if (i + 1 >= args.size() || args[i + 1].empty()) return usage(args[i] + " needs a value");
      if (args[i] == "--screenshot") {
        w.screenshot = args[++i];
      } else if (args[i] == "--toggle") {
        w.toggle = splitList(args[++i]);
      } else {
        std::string why;
        const auto wh = parseSize(*findOption(*findCommand("validate"), "--size"), args[++i], why);
        if (!wh) return usage(why);
        w.width = wh->first, w.height = wh->second, sized = true;
      }
    } else {
      rest.push_back(args[i]);
    }
  }
  const bool panel = w.window || !w.screenshot.empty();
  if (!panel && (w.autoFit || !w.toggle.empty())) return usage("--toggle and --auto-fit drive the panel: add --window or --screenshot PNG");
  if (!panel && sized) return usage("--size sizes the panel: add --window or --screenshot PNG");
  WorkbenchArgs a;
  if (panel) rest.insert(rest.end(), {"--out", "."});  // the panel writes no report
  if (const std::string e = parseWorkbenchArgs(rest, true, a); !e.empty()) return usage(e);
  if (panel) {
    try {
      for (const std::string& e : a.effects) effectFromFile(e, Measurement{});
      for (const std::string& e : w.toggle) effectFromFile(e, Measurement{});
    } catch (const std::invalid_argument& e) {
      return usage(std::string("--effects/--toggle: ") + e.what());
    }
    return runValidateWindow(a, w);
  }
  if (a.files.size() > 1) return runValidateJoint(a);
  auto say = [&](const std::string& s) {
    if (!a.quiet) std::fprintf(stderr, "%s\n", s.c_str());
  };
  Measurement m;
  ModelParams base, start;
  std::vector<std::string> fit;
  try {
    m = io::readMeasurement(a.file);
    base = start = ModelParams::nominal(m);
    for (const std::string& e : a.effects) start.effects.push_back(effectFromFile(e, m));
    fit = expandFitNames(a.fit, m);
    if (const std::string why = unknownFitName(fit, start, m); !why.empty()) return usage("--fit: " + why);
  } catch (const io::InputError& e) {
    std::fprintf(stderr, "coilsim: %s\n", e.what());
    return kExitUsage;
  } catch (const std::invalid_argument& e) {
    return usage(std::string("--effects: ") + e.what());
  }
  if (!makeOutputDirectory("validate", a.out)) return kExitUsage;
  StageSimulator sim(m, simOptionsOf(a));
  const Comparison cmp(m);
  say("validate: " + a.file + ": " + std::to_string(m.stages.size()) + " stage(s), " + std::to_string(sim.beams()) +
      " beams; the base model at the file's nominal values...");
  const std::vector<StageComparison> before = cmp.compare(sim.run(base, false));
  FitOptions fo;
  fo.params = fit;
  Progress progress("validate " + a.file, fit.empty() ? 0 : fo.maxEvaluations, "fit evaluations");
  fo.progress = [&](int k, double rms) {
    progress.update(k, "at most; a converged fit ends sooner");
    if (!a.quiet) progress.line("  fit: evaluation " + std::to_string(k) + ", RMS residual " + fmt("%.4f", units::mToMm(rms)) + " mm");
  };
  fo.stop = [] { return stopRequested(); };  // Ctrl-C: the report of the fit so far, marked not finished
  if (!fit.empty()) say("validate: fitting " + std::to_string(fit.size()) + " parameter(s)...");
  else if (!a.effects.empty()) say("validate: the model with the effects on...");
  FitResult r = identify(sim, cmp, start, fo);
  std::vector<StageComparison> after = cmp.compare(sim.run(r.ok ? r.params : start, false));

  ordered_json j;
  j["format"] = "coilsim-validation-report/1";
  j["file"] = a.file;
  j["measurement"] = m.name;
  j["effects"] = a.effects;
  j["fit"] = fit;
  j["discretisation"] = {{"beams", sim.beams()}, {"spacing_mm", a.spacingMm}, {"push_increment_mm", a.pushIncrementMm}};
  j["stages"] = stagesJson(cmp, after);
  j["stages_before"] = stagesJson(cmp, before);
  j["fitted"] = fittedJson(r.fitted);
  if (!r.ok) j["fit_error"] = r.message;
  ordered_json it = ordered_json::array();
  for (size_t k = 0; k < r.history.size(); ++k) it.push_back(r6(units::mToMm(r.history[k])));
  j["iterations_rms_residual_mm"] = it;
  j["chi2"] = r6(r.chi2);
  j["residual_count"] = r.residual.size();
  const Fingerprint fp = fingerprint(cmp, after);
  j["fingerprint"] = fingerprintJson(fp);
  const std::string priorText = priorCheckText(r.fitted);
  j["prior_check"] = priorText.empty() ? std::string("every fitted value is inside its plausible band") : priorText;
  const Adequacy adq = adequacy(cmp, after);
  j["adequacy"] = adequacyJson(adq);
  PredictionCheck pred;
  pred.message = "nothing fitted: no prediction check";
  if (r.ok && !fit.empty() && m.stages.size() >= 2) {
    say("validate: prediction check (fitting all stages but the last)...");
    pred = predictLastStage(cmp, sim.options(), start, fit, after.back().metrics.stageError, false);
  }
  j["prediction"] = predictionJson(pred);
  std::vector<std::string> written, warnings;
  if (a.plots) writePlots(a.out, m, after, written, warnings);
  j["images"] = written;
  j["warnings"] = warnings;

  std::ostringstream md;
  md << "# Validation of " << m.name << "\n\nFile `" << a.file << "`; effects on: "
     << (a.effects.empty() ? std::string("none (the base model)") : ordered_json(a.effects).dump())
     << "; fitted: " << (fit.empty() ? std::string("nothing (nominal values)") : ordered_json(fit).dump()) << "; "
     << sim.beams() << " beams.\n\n";
  md << "Before: the base model at the file's nominal values. After: the effects on, the parameters fitted.\n\n";
  md << stageTable(m, before, after) << "\n";
  if (!r.fitted.empty()) {
    md << "| fitted | value | sigma (1 SD) |\n|---|---|---|\n";
    for (const FittedValue& v : r.fitted)
      md << "| " << v.name << " | " << fmt("%.5g", v.value / v.toSI) << unitSuffix(v.unit) << " | "
         << plusMinus(v.sigma / v.toSI, v.unit) << " |\n";
    md << "\nRMS residual per coordinate (mm) along the optimiser's evaluations:";
    for (double h : r.history) md << " " << fmt("%.4f", units::mToMm(h));
    md << "\n\n";
  }
  md << "Where the remaining residual lies: " << fp.summary << "\n\n";
  md << "**Prior check:** " << (priorText.empty() ? "every fitted value is inside its plausible band." : priorText) << "\n\n";
  md << adequacyMarkdown(adq, pred);
  for (const std::string& w : written) md << "![" << w << "](" << w << ")\n";
  for (const std::string& w : warnings) md << "\nWarning: " << w << "\n";
  try {
    io::writeFileAtomic((std::filesystem::path(a.out) / "report.json").string(), io::formatJson(j));
    io::writeFileAtomic((std::filesystem::path(a.out) / "report.md").string(), md.str());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "coilsim validate: %s\n", e.what());
    return kExitUsage;
  }
  // The summary on stdout: the per-stage table before and after.
  std::printf("%s", stageTable(m, before, after).c_str());
  for (const FittedValue& v : r.fitted)
    std::printf("%s = %.5g%s %s\n", v.name.c_str(), v.value / v.toSI, unitSuffix(v.unit).c_str(),
                plusMinus(v.sigma / v.toSI, v.unit).c_str());
  if (!priorText.empty()) std::printf("%s\n", priorText.c_str());
  std::printf("adequacy: %s\nprediction: %s\n", adq.verdict.c_str(), pred.message.c_str());
  std::printf("report: %s\n", (std::filesystem::path(a.out) / "report.json").string().c_str());
  for (const StageComparison& s : after)
    if (!s.ok()) {
      std::fprintf(stderr, "coilsim validate: a stage failed: %s\n", s.message().c_str());
      return exitCodeOf(*s.failure);
    }
  if (!r.ok) {
    std::fprintf(stderr, "coilsim validate: %s\n", stopRequested() ? stopReason() : r.message.c_str());
    return stopRequested() ? stopExitCode() : exitCodeOf(r.failure);
  }
  return kExitOk;
}

}  // namespace coilsim::app
