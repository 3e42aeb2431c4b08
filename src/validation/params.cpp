#include "validation/params.h"

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
  if (name == "young_modulus") return FitParam{name, "GPa", 1e9, 0.05e9, 1000e9, true};
  if (name == "poisson_ratio") return FitParam{name, "1", 1, 0.0, 0.5, false};
  if (name == "loop_diameter" || name == "pitch") {
    if (!helix) {
      why = name + " needs a helical rest shape";
      return std::nullopt;
    }
    if (name == "loop_diameter") return FitParam{name, "mm", 1e-3, 0.5 * p.loopDiameter, 2.0 * p.loopDiameter, false};
    return FitParam{name, "mm", 1e-3, 0.0, 3.0 * p.pitch + 1e-3, false};
  }
  size_t k = 0;
  if (const EffectUse* e = effectParam(p, name, k)) {
    const ParamSpec& s = e->effect->params()[k];
    const bool wide = s.min > 0 && s.max / s.min > 100;
    return FitParam{name, std::string(s.unit), s.toSI, s.min * s.toSI, s.max * s.toSI, wide};
  }
  why = "unknown parameter \"" + name +
        "\" (known: young_modulus, poisson_ratio, loop_diameter, pitch, or EFFECT.PARAM of an effect switched on)";
  return std::nullopt;
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
  if (const std::optional<Diagnosable> d = u.effect->diagnosis(setupHint(m)))
    for (const auto& [param, value] : d->fromSetup) u.set(param, value);
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
