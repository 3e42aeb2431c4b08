#include "physics/effect.h"
#include "physics/failure.h"

#include <stdexcept>

namespace coilsim {

double EffectUse::value(std::string_view param) const {
  const auto specs = effect->params();
  for (size_t i = 0; i < specs.size(); ++i)
    if (specs[i].name == param) return values[i];
  throw std::out_of_range("effect '" + std::string(name()) + "' has no parameter '" + std::string(param) + "'");
}

void EffectUse::set(std::string_view param, double si) {
  const auto specs = effect->params();
  for (size_t i = 0; i < specs.size(); ++i)
    if (specs[i].name == param) {
      values[i] = si;
      return;
    }
  throw std::out_of_range("effect '" + std::string(name()) + "' has no parameter '" + std::string(param) + "'");
}

EffectRegistry& EffectRegistry::global() {
  static EffectRegistry* registry = [] {
    auto* r = new EffectRegistry;
    registerBuiltinEffects(*r);
    return r;
  }();
  return *registry;
}

const Effect* EffectRegistry::add(std::unique_ptr<Effect> effect) {
  if (find(effect->name())) throw PhysicsError(badDefinition("effect '" + std::string(effect->name()) + "'", "is registered twice"));
  effects_.push_back(std::move(effect));
  return effects_.back().get();
}

const Effect* EffectRegistry::find(std::string_view name) const {
  for (const auto& e : effects_)
    if (e->name() == name) return e.get();
  return nullptr;
}

std::vector<const Effect*> EffectRegistry::all() const {
  std::vector<const Effect*> out;
  for (const auto& e : effects_) out.push_back(e.get());
  return out;
}

EffectUse EffectRegistry::use(std::string_view name) const {
  const Effect* e = find(name);
  if (!e) {
    std::string known;
    for (const auto& k : effects_) known += (known.empty() ? "" : ", ") + std::string(k->name());
    throw PhysicsError(badDefinition({}, "unknown effect '" + std::string(name) + "' (known: " + known + ")"));
  }
  EffectUse u;
  u.effect = e;
  for (const ParamSpec& p : e->params()) u.values.push_back(p.defaultValue * p.toSI);
  return u;
}

}  // namespace coilsim
