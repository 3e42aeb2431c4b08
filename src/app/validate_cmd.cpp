// `coilsim validate`: the model against a measurement, before and after
// switching effects on and fitting parameters (docs/validation.md).
#include "app/validate_cmd.h"
#include "app/format.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>

#include "app/exit_codes.h"
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

int usage(const std::string& message) {
  std::fprintf(stderr,
               "coilsim validate: %s\n"
               "usage: coilsim validate FILE [--effects a,b] [--fit young_modulus,...] --out DIR\n"
               "         [--spacing MM] [--push-increment MM] [--no-plots] [--quiet]\n"
               "       coilsim validate FILE --window [--effects a,b] [--fit ...]   (the panel)\n"
               "       coilsim validate FILE --screenshot PNG [--toggle a,b] [--auto-fit]   (the panel off-screen)\n"
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
      if (!value()) return "--fit needs a list of parameters, e.g. young_modulus,buoyancy";
      a.fit = splitList(v);
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
    } else if (a.file.empty()) {
      a.file = arg;
    } else {
      return "one measurement file, got \"" + a.file + "\" and \"" + arg + "\"";
    }
  }
  if (a.file.empty()) return "a measurement file (coil-measurement/1) is needed";
  if (a.out.empty()) return "--out DIR is needed";
  return "";
}

std::vector<std::string> expandFitNames(const std::vector<std::string>& names, const Measurement& m) {
  std::vector<std::string> out;
  for (const std::string& n : names) {
    if (n.find('.') == std::string::npos && EffectRegistry::global().find(n)) {
      const Candidate c = candidateFor(n, m);
      out.insert(out.end(), c.params.begin(), c.params.end());
    } else {
      out.push_back(n);
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
    j["ok"] = s.ok;
    if (!s.ok) {
      j["message"] = s.message;
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
  for (const FittedValue& v : fitted)
    j[v.name] = {{"value", r6(v.value / v.toSI)},
                 {"sigma", v.identifiable ? ordered_json(r6(v.sigma / v.toSI)) : ordered_json(nullptr)},
                 {"unit", v.unit},
                 {"identifiable", v.identifiable}};
  return j;
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
    if (!s.ok) return std::string(" failed | | | |");
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
    if (!stages[k].ok) continue;
    const std::string name = "overlay_stage" + std::to_string(k + 1) + ".png";
    const std::string title = m.name + ", " + m.stages[k].name + ": stage error " + fmt("%.4f", stages[k].metrics.stageError);
    if (savePng((fs::path(dir) / name).string(), plotOverlay(stages[k], m.stages[k], m.gravity, m.tip.direction, title), err))
      written.push_back(name);
    else
      warnings.push_back(err);
  }
}

int runValidate(const std::vector<std::string>& args) {
  // The panel's own options first; the rest are the workbench's.
  WindowArgs w;
  std::vector<std::string> rest;
  for (size_t i = 0; i < args.size(); ++i) {
    if (args[i] == "--window") {
      w.window = true;
    } else if (args[i] == "--auto-fit") {
      w.autoFit = true;
    } else if (args[i] == "--screenshot" || args[i] == "--toggle") {
      if (i + 1 >= args.size() || args[i + 1].empty()) return usage(args[i] + " needs a value");
      if (args[i] == "--screenshot") w.screenshot = args[++i];
      else w.toggle = splitList(args[++i]);
    } else {
      rest.push_back(args[i]);
    }
  }
  const bool panel = w.window || !w.screenshot.empty();
  if (!panel && (w.autoFit || !w.toggle.empty())) return usage("--toggle and --auto-fit drive the panel: add --window or --screenshot PNG");
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
    for (const std::string& f : fit) {
      std::string why;
      if (!describeParam(f, start, m, why)) return usage("--fit: " + why);
    }
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
    if (!a.quiet) progress.line("  fit: evaluation " + std::to_string(k) + ", RMS residual " + fmt("%.4f", rms * 1e3) + " mm");
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
    for (double h : r.history) md << " " << fmt("%.4f", h * 1e3);
    md << "\n\n";
  }
  md << "Where the remaining residual lies: " << fp.summary << "\n\n";
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
  std::printf("report: %s\n", (std::filesystem::path(a.out) / "report.json").string().c_str());
  for (const StageComparison& s : after)
    if (!s.ok) {
      std::fprintf(stderr, "coilsim validate: a stage failed: %s\n", s.message.c_str());
      return kExitFailure;
    }
  if (!r.ok) {
    std::fprintf(stderr, "coilsim validate: %s\n", stopRequested() ? stopReason() : r.message.c_str());
    return stopRequested() ? stopExitCode() : kExitFailure;
  }
  return kExitOk;
}

}  // namespace coilsim::app
