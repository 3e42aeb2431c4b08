#include "validation/params.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>


namespace coilsim::validation {
namespace {

// "effect.param" -> the effect use and the index of its parameter, or nullptr.
const EffectUse* effectParam(const ModelParams& p, const std::string& name, size_t& index) {
  const size_t dot = name.find('.');
  if (dot == std::string::npos) return nullptr;
  const EffectUse* e = p.effect(name.substr(0, dot));
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

std::optional<FitParam> describeParam(const std::string& name, const ModelParams& p, const Measurement& m,
                                      std::string& why) {
  const bool helix = m.coil.rest.type == RestShapeDef::Type::Helix;
  if (name == "young_modulus") {
    const double e0 = m.coil.hasYoungModulus ? m.coil.youngModulus : p.youngModulus;
    return FitParam{name, "GPa", 1e9, 0.05e9, 1000e9, true, {e0 > 0, e0, 0.5 * e0, 2.0 * e0}};
  }
  // Metals: 0.28-0.42 (platinum 0.39, nitinol 0.33).
  if (name == "poisson_ratio") return FitParam{name, "1", 1, 0.0, 0.5, false, {true, m.coil.poissonRatio, 0.28, 0.42}};
  if (name == "loop_diameter" || name == "pitch") {
    if (!helix) {
      why = name + " needs a helical rest shape";
      return std::nullopt;
    }
    // Shape-set loops relax or tighten a little after heat setting: +-15 %.
    const double d0 = m.coil.rest.loopDiameter, h0 = m.coil.rest.pitch;
    if (name == "loop_diameter")
      return FitParam{name, "mm", 1e-3, 0.5 * p.loopDiameter, 2.0 * p.loopDiameter, false, {true, d0, 0.85 * d0, 1.15 * d0}};
    return FitParam{name, "mm", 1e-3, 0.0, 3.0 * p.pitch + 1e-3, false,
                    {true, h0, std::max(0.0, 0.85 * h0 - 0.1e-3), 1.15 * h0 + 0.1e-3}};
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
  why = "unknown parameter \"" + name +
        "\" (known: young_modulus, poisson_ratio, loop_diameter, pitch, or EFFECT.PARAM of an effect switched on)";
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
  if (name == "young_modulus") return p.youngModulus;
  if (name == "poisson_ratio") return p.poissonRatio;
  if (name == "loop_diameter") return p.loopDiameter;
  if (name == "pitch") return p.pitch;
  size_t k = 0;
  if (const EffectUse* e = effectParam(p, name, k)) return e->values[k];
  throw std::invalid_argument("unknown parameter " + name);
}

void setParam(ModelParams& p, const std::string& name, double v) {
  if (name == "young_modulus") p.youngModulus = v;
  else if (name == "poisson_ratio") p.poissonRatio = v;
  else if (name == "loop_diameter") p.loopDiameter = v;
  else if (name == "pitch") p.pitch = v;
  else {
    size_t k = 0;
    const EffectUse* e = effectParam(p, name, k);
    if (!e) throw std::invalid_argument("unknown parameter " + name);
    const_cast<EffectUse*>(e)->values[k] = v;
  }
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
