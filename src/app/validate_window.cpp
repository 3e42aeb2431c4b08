// The validation panel's data: the base model at the file's nominal values,
// and a fit callback that refits with the toggled effects on (young_modulus_gpa
// and each effect's usual parameters, or what --fit names) on a simulator
// of its own, so that it can run on the panel's background thread.
#include "app/validate_window.h"
#include "app/format.h"
#include "app/validate_plots.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>

#include "app/exit_codes.h"
#include "io/json_reader.h"
#include "io/measurement.h"
#include "io/units.h"

#include "ui/validation_panel.h"

namespace coilsim::app {

namespace {

using namespace validation;

// The fixed error scale (app/validate_plots.h), the same as the overlay PNGs'.
Colour errorColour(double errorM) {
  const std::array<float, 3> c = errorScaleColour(errorScalePosition(units::mToMm(errorM)));
  return Colour(c[0], c[1], c[2], 1.0f);
}

// The scale's legend for the panel: 64 colours, ticks at each decade and its 3s.
ui::ErrorColourScale errorLegend() {
  ui::ErrorColourScale s;
  s.legend = errorScaleLegend();
  for (int i = 0; i < 64; ++i) {
    const std::array<float, 3> c = errorScaleColour((i + 0.5) / 64.0);
    s.colours.emplace_back(c[0], c[1], c[2], 1.0f);
  }
  const int decades = int(std::lround(std::log10(kErrorColourHighMm / kErrorColourLowMm)));
  for (int d = 0; d <= decades; ++d)
    for (double m : {1.0, 3.0}) {
      const double mm = kErrorColourLowMm * std::pow(10.0, d) * m;
      if (d == decades && m > 1) continue;
      s.ticks.emplace_back(float(errorScalePosition(mm)), fmt("%g", mm));
    }
  s.ticks.back().second += " mm";
  return s;
}

ui::ValidationStageRow row(const Stage& st, const StageComparison& s) {
  ui::ValidationStageRow r;
  r.name = st.name;
  r.deployedMm = units::mToMm(st.deployed);
  r.ok = s.ok();
  r.message = s.message();
  if (!s.ok()) return r;
  r.stageError = s.metrics.stageError;
  r.nodeErrorMean = s.metrics.nodeErrorMean;
  r.nodeErrorSd = s.metrics.nodeErrorSd;
  r.meanDisplacementMm = units::mToMm(s.metrics.meanDisplacement);
  r.meanDistanceMm = units::mToMm(s.metrics.meanDistance);
  for (size_t i = 0; i < s.sim.size(); ++i) {
    r.arcMm.push_back(float(units::mToMm(s.s[i])));
    r.errorMm.push_back(float(units::mToMm((s.sim[i] - s.meas[i]).norm())));
  }
  r.noiseFloorMm = float(units::mToMm(std::sqrt(3.0) * s.sigma));
  return r;
}

// The simulated coil coloured by node error, the measured centre line (the
// spline at the nodes' arc lengths) as a thin grey tube beside it.
DrawData scene(const Measurement& m, const StageComparison& s) {
  DrawData d;
  if (!s.ok() || s.sim.empty()) return d;
  DrawTube coil;
  coil.name = "coil (simulated)";
  coil.radius = m.coil.wireRadius;
  coil.centre = s.sim;
  for (size_t i = 0; i < s.sim.size(); ++i) coil.colours.push_back(errorColour((s.sim[i] - s.meas[i]).norm()));
  DrawTube meas;
  meas.name = "measured";
  meas.radius = 0.5 * m.coil.wireRadius;
  meas.centre = s.meas;
  meas.colours.assign(s.meas.size(), Colour(0.75f, 0.75f, 0.75f, 1.0f));
  // The catheter's last 5 mm, to show where the coil comes from.
  DrawTube cath;
  cath.name = "catheter";
  cath.role = RodRole::Catheter;
  cath.radius = 2.5 * m.coil.wireRadius;
  cath.centre = {m.tip.position - 5e-3 * m.tip.direction, m.tip.position};
  cath.colours.assign(2, Colour(0.2f, 0.25f, 0.35f, 1.0f));
  d.tubes.push_back(std::move(coil));
  d.tubes.push_back(std::move(meas));
  d.tubes.push_back(std::move(cath));
  return d;
}

ui::ValidationView view(const Measurement& m, const std::vector<StageComparison>& stages) {
  ui::ValidationView v;
  for (size_t k = 0; k < stages.size(); ++k) {
    v.stages.push_back(row(m.stages[k], stages[k]));
    v.scenes.push_back(scene(m, stages[k]));
  }
  return v;
}

}  // namespace

int runValidateWindow(const WorkbenchArgs& a, const WindowArgs& w) {
  Measurement m;
  try {
    m = io::readMeasurement(a.file);
  } catch (const io::InputError& e) {
    std::fprintf(stderr, "coilsim: %s\n", e.what());
    return kExitUsage;
  }
  const SimOptions so = simOptionsOf(a);
  StageSimulator sim(m, so);
  const Comparison cmp(m);
  std::fprintf(stderr, "validate: %s: the base model at the file's nominal values...\n", a.file.c_str());
  const std::vector<StageComparison> before = cmp.compare(sim.run(ModelParams::nominal(m), false));

  ui::ValidationHooks h;
  h.title = m.name + " (" + a.file + ")";
  for (const char* e : {"buoyancy", "drag", "gravity_tilt", "catheter_compliance", "self_contact"})
    if (const Effect* eff = EffectRegistry::global().find(e)) {
      h.effects.push_back(e);
      h.descriptions.push_back(std::string(eff->description()));
    }
  // Effects registered beyond those (e.g. a user's own) are offered too.
  for (const Effect* e : EffectRegistry::global().all()) {
    const std::string n(e->name());
    if (std::find(h.effects.begin(), h.effects.end(), n) == h.effects.end() && n != "gravity" &&
        n != "wall_contact" && n != "rod_contact") {
      h.effects.push_back(n);
      h.descriptions.push_back(std::string(e->description()));
    }
  }
  for (const std::vector<std::string>* list : {&a.effects, &w.toggle})
    for (const std::string& e : *list)
      if (std::find(h.effects.begin(), h.effects.end(), e) == h.effects.end()) {
        std::string offered;
        for (const std::string& o : h.effects) offered.append(offered.empty() ? "" : ", ").append(o);
        std::fprintf(stderr, "coilsim validate: the panel has no toggle for '%s' (it offers %s)\n", e.c_str(),
                     offered.c_str());
        return kExitUsage;
      }
  h.initiallyOn = a.effects;
  h.before = view(m, before);
  h.errorScale = errorLegend();
  const std::vector<std::string> baseFit = a.fit.empty() ? std::vector<std::string>{youngModulusFit()} : a.fit;
  std::vector<double> beforeErrors;
  for (const StageComparison& s : before) beforeErrors.push_back(s.ok() ? s.metrics.stageError : NAN);
  h.fit = [m, so, baseFit, beforeErrors, quiet = a.quiet](const std::vector<std::string>& effects, const ui::FitProgress& progress,
                                                       const std::function<bool()>& stop) {
    ui::ValidationView out;
    out.effects = effects;
    try {
      ModelParams start = ModelParams::nominal(m);
      for (const std::string& e : effects) start.effects.push_back(effectFromFile(e, m));
      std::vector<std::string> names = expandFitNames(baseFit, m);
      for (const std::string& n : expandFitNames(effects, m))
        if (std::find(names.begin(), names.end(), n) == names.end()) names.push_back(n);
      for (const std::string& n : names) {
        std::string why;
        if (!describeParam(n, start, m, why)) throw std::invalid_argument(why);
      }
      StageSimulator fsim(m, so);  // its own: this runs beside the drawing thread
      const Comparison fcmp(m);
      FitOptions fo;
      fo.params = names;
      fo.progress = [&](int k, double rms) {
        if (!quiet) std::fprintf(stderr, "  fit: evaluation %d, RMS residual %.4f mm\n", k, units::mToMm(rms));
        progress(k, units::mToMm(rms));
      };
      fo.stop = stop;
      const FitResult r = identify(fsim, fcmp, start, fo);
      const std::vector<StageComparison> after = fcmp.compare(fsim.run(r.ok ? r.params : start, false));
      ui::ValidationView v = view(m, after);
      // One line on stdout per fit, for scripts: each stage's error before -> after.
      std::string line = "validate: fit with effects [";
      for (size_t k = 0; k < effects.size(); ++k) line.append(k ? "," : "").append(effects[k]);
      line.append("]: stage error");
      for (size_t k = 0; k < after.size(); ++k)
        line.append(fmt(" %.4f ->", beforeErrors[k])).append(after[k].ok() ? fmt(" %.4f", after[k].metrics.stageError) : " failed");
      if (!r.ok) line.append(" (fit failed: ").append(r.message).append(")");
      std::printf("%s\n", line.c_str());
      std::fflush(stdout);
      v.effects = effects;
      v.ok = r.ok;
      v.message = r.message;
      for (const FittedValue& f : r.fitted)
        v.fitted.push_back(f.name + " = " + fmt("%.5g", f.value / f.toSI) + unitSuffix(f.unit) + " " + plusMinus(f.sigma / f.toSI, f.unit));
      for (double x : r.history) v.history.push_back(float(units::mToMm(x)));
      return v;
    } catch (const std::exception& e) {
      out.ok = false;
      out.message = e.what();
      return out;
    }
  };

  ui::ValidationWindowOptions o;
  o.toggle = w.toggle;
  o.autoFit = w.autoFit;
  o.screenshotPath = w.screenshot;
  o.width = w.width, o.height = w.height;
  if (w.window) return ui::runValidationWindow(h, o);
  std::string error;
  if (!ui::renderValidationOffscreen(h, o, error)) {
    std::fprintf(stderr, "coilsim: %s\n", error.c_str());
    return kExitFailure;
  }
  return kExitOk;
}

}  // namespace coilsim::app
