#include "validation/params.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "physics/rod_quantities.h"


namespace coilsim::validation {
namespace {

// A rod quantity identification may fit: its declaration (physics/
// rod_quantities.h: fit name = scene key, unit, SI factor, physical bounds),
// the name --fit knew it by before, where the coil's RodSpec holds it, and
// what a fit searches: a band narrower than the physical bounds around the
// file's value, and the prior (params.h).
struct RodFit {
  const rodq::Quantity* quantity;
  std::string_view oldName;
  double& (*value)(RodSpec& coil);
  bool helixOnly;
  void (*band)(const ModelParams& p, const Measurement& m, FitParam& f);
};

const RodFit kRodFits[] = {
    {&rodq::kYoungModulus, "young_modulus", [](RodSpec& c) -> double& { return c.youngModulus; }, false,
     [](const ModelParams& p, const Measurement& m, FitParam& f) {
       const double e0 = m.coil.youngModulus > 0 ? m.coil.youngModulus : p.coil.youngModulus;
       f.prior = {e0 > 0, e0, 0.5 * e0, 2.0 * e0};
     }},
    // Metals: 0.28-0.42 (platinum 0.39, nitinol 0.33).
    {&rodq::kPoissonRatio, "", [](RodSpec& c) -> double& { return c.poissonRatio; }, false,
     [](const ModelParams&, const Measurement& m, FitParam& f) {
       f.lo = 0.0, f.hi = 0.5;
       f.prior = {true, m.coil.poissonRatio, 0.28, 0.42};
     }},
    // Shape-set loops relax or tighten a little after heat setting: +-15 %.
    {&rodq::kLoopDiameter, "loop_diameter", [](RodSpec& c) -> double& { return c.rest.loopDiameter; }, true,
     [](const ModelParams& p, const Measurement& m, FitParam& f) {
       const double d0 = m.coil.rest.loopDiameter;
       f.lo = 0.5 * p.coil.rest.loopDiameter, f.hi = 2.0 * p.coil.rest.loopDiameter;
       f.prior = {true, d0, 0.85 * d0, 1.15 * d0};
     }},
    {&rodq::kPitch, "pitch", [](RodSpec& c) -> double& { return c.rest.pitch; }, true,
     [](const ModelParams& p, const Measurement& m, FitParam& f) {
       const double h0 = m.coil.rest.pitch;
       f.lo = 0.0, f.hi = 3.0 * p.coil.rest.pitch + 1e-3;
       f.prior = {true, h0, std::max(0.0, 0.85 * h0 - 0.1e-3), 1.15 * h0 + 0.1e-3};
     }},
};

const RodFit* rodFit(const std::string& name) {
  for (const RodFit& r : kRodFits)
    if (name == r.quantity->spec.name || (!r.oldName.empty() && name == r.oldName)) return &r;
  return nullptr;
}

// "effect.param" -> the effect use and the index of its parameter, or nullptr.
template <class Params>
auto effectParam(Params& p, const std::string& name, size_t& index) -> decltype(p.effect(name)) {
  const size_t dot = name.find('.');
  if (dot == std::string::npos) return nullptr;
  auto* e = p.effect(name.substr(0, dot));
  if (!e) return nullptr;
  const auto specs = e->effect->params();
  for (size_t i = 0; i < specs.size(); ++i)
    if (specs[i].name == name.substr(dot + 1)) {
      index = i;
      return e;
    }
  return nullptr;
}

}  // namespace

std::string canonicalFitName(const std::string& name) {
  const RodFit* r = rodFit(name);
  return r ? std::string(r->quantity->spec.name) : name;
}

std::string oldFitNameNote(const std::string& name) {
  const RodFit* r = rodFit(name);
  if (!r || name != r->oldName) return {};
  return "--fit " + name + " is the old name of " + std::string(r->quantity->spec.name) +
         " (the scene file's key); both fit the same quantity";
}

std::vector<const rodq::Quantity*> rodFitQuantities() {
  std::vector<const rodq::Quantity*> out;
  for (const RodFit& r : kRodFits) out.push_back(r.quantity);
  return out;
}

std::optional<FitParam> describeParam(const std::string& name, const ModelParams& p, const Measurement& m,
                                      std::string& why) {
  if (const RodFit* r = rodFit(name)) {
    const ParamSpec& s = r->quantity->spec;
    if (r->helixOnly && m.coil.rest.type != RestShapeDef::Type::Helix) {
      why = name + " needs a helical rest shape";
      return std::nullopt;
    }
    const bool wide = s.min > 0 && s.max / s.min > 100;
    FitParam f{name, std::string(s.unit), s.toSI, s.min * s.toSI, s.max * s.toSI, wide, {}};
    r->band(p, m, f);
    // The search band never leaves what is physical.
    f.lo = std::max(f.lo, s.min * s.toSI), f.hi = std::min(f.hi, s.max * s.toSI);
    return f;
  }
  size_t k = 0;
  if (const EffectUse* e = effectParam(p, name, k)) {
    const ParamSpec& s = e->effect->params()[k];
    const bool wide = s.min > 0 && s.max / s.min > 100;
    FitParam f{name, std::string(s.unit), s.toSI, s.min * s.toSI, s.max * s.toSI, wide, {}};
    if (const std::optional<Diagnosable> d = e->effect->diagnosis(setupHint(m)))
      for (const FitSpec& fs : d->fit)
        if (fs.param == s.name && fs.plausibleHigh > fs.plausibleLow)
          f.prior = {true, std::clamp(fs.typical, fs.plausibleLow, fs.plausibleHigh), fs.plausibleLow, fs.plausibleHigh};
    return f;
  }
  std::string known;
  for (const RodFit& r : kRodFits) known.append(r.quantity->spec.name).append(", ");
  why = "unknown parameter \"" + name + "\" (known: " + known + "or EFFECT.PARAM of an effect switched on)";
  return std::nullopt;
}

double priorDeviation(const FitParam& f, double v) {
  const Prior& q = f.prior;
  if (!q.known) return 0;
  if (f.logScale && q.low > 0 && v > 0) {
    const double d = std::log(v / q.nominal);
    return d >= 0 ? d / std::max(std::log(q.high / q.nominal), 1e-12) : d / std::max(std::log(q.nominal / q.low), 1e-12);
  }
  const double d = v - q.nominal;
  return d >= 0 ? d / std::max(q.high - q.nominal, 1e-300) : d / std::max(q.nominal - q.low, 1e-300);
}

double getParam(const ModelParams& p, const std::string& name) {
  if (const RodFit* r = rodFit(name)) {
    RodSpec coil = p.coil;  // value() needs a RodSpec it could write to: read a copy
    return r->value(coil);
  }
  size_t k = 0;
  if (const EffectUse* e = effectParam(p, name, k)) return e->values[k];
  throw std::invalid_argument("unknown parameter " + name);
}

void setParam(ModelParams& p, const std::string& name, double v) {
  if (const RodFit* r = rodFit(name)) {
    r->value(p.coil) = v;
    return;
  }
  size_t k = 0;
  EffectUse* e = effectParam(p, name, k);
  if (!e) throw std::invalid_argument("unknown parameter " + name);
  e->values[k] = v;
}

SetupHint setupHint(const Measurement& m) { return {m.mediumDensity, m.mediumViscosity}; }

EffectUse effectFromFile(const std::string& name, const Measurement& m) {
  EffectUse u = EffectRegistry::global().use(name);
  if (const std::optional<Diagnosable> d = u.effect->diagnosis(setupHint(m))) {
    for (const auto& [param, value] : d->held) u.set(param, value);
    for (const auto& [param, value] : d->fromSetup) u.set(param, value);
  }
  return u;
}

bool releasesClamp(const EffectUse& use) {
  const std::optional<Diagnosable> d = use.effect ? use.effect->diagnosis({}) : std::nullopt;
  return d && d->releasesClamp;
}

std::vector<std::string> splitList(const std::string& list) {
  std::vector<std::string> out;
  size_t start = 0;
  while (start <= list.size()) {
    const size_t end = std::min(list.find(',', start), list.size());
    if (end > start) out.push_back(list.substr(start, end - start));
    start = end + 1;
  }
  return out;
}

}  // namespace coilsim::validation
