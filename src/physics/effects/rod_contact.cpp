// Rod contact: segments of different rods (a coil and an earlier, detached
// coil; a coil and the catheter) as capsules pushing each other apart, with
// Coulomb friction per material pair. Model and reasons:
// physics/contact/response.h; broad phase: physics/contact/detect.h.
#include "physics/contact/detect.h"
#include "physics/effects/builtin.h"
#include "physics/model.h"

namespace coilsim {
namespace {

constexpr ParamSpec kParams[] = {
    {"stiffness_n_mm", "N/mm", "penalty stiffness of one segment pair", 50.0, 0.0, 1e4, 1e3},
    {"damping_ratio", "1", "normal (and sticking) damping as a fraction of critical for the node mass", 1.0, 0.0, 10.0,
     1.0},
    {"margin_mm", "mm", "distance at which a pair is tracked before it touches", 0.05, 0.0, 5.0, 1e-3},
    {"friction_static", "1", "static Coulomb coefficient coil-coil", 0.15, 0.0, 5.0, 1.0},
    {"friction_dynamic", "1", "dynamic Coulomb coefficient coil-coil", 0.1, 0.0, 5.0, 1.0},
    {"catheter_friction_static", "1", "static Coulomb coefficient coil-catheter", 0.1, 0.0, 5.0, 1.0},
    {"catheter_friction_dynamic", "1", "dynamic Coulomb coefficient coil-catheter", 0.05, 0.0, 5.0, 1.0},
    {"friction_stiffness_ratio", "1", "stick spring stiffness over normal stiffness (regularised Coulomb)", 0.5, 0.01,
     10.0, 1.0},
};

constexpr size_t kStiffness = paramIndex(kParams, "stiffness_n_mm"), kDamping = paramIndex(kParams, "damping_ratio"),
                 kMargin = paramIndex(kParams, "margin_mm"), kStatic = paramIndex(kParams, "friction_static"),
                 kDynamic = paramIndex(kParams, "friction_dynamic"),
                 kCatheterStatic = paramIndex(kParams, "catheter_friction_static"),
                 kCatheterDynamic = paramIndex(kParams, "catheter_friction_dynamic"),
                 kStick = paramIndex(kParams, "friction_stiffness_ratio");

ContactLaw coilLaw(std::span<const double> p) {
  return {p[kStiffness], p[kDamping], p[kStatic], p[kDynamic], p[kStick], 2.0};
}
ContactLaw catheterLaw(std::span<const double> p) {
  return {p[kStiffness], p[kDamping], p[kCatheterStatic], p[kCatheterDynamic], p[kStick], 2.0};
}

class RodContact final : public Effect {
 public:
  std::string_view name() const override { return "rod_contact"; }
  std::string_view description() const override { return "coil-coil and coil-catheter contact, with friction"; }
  std::span<const ParamSpec> params() const override { return kParams; }
  void beginStep(const Model& model, std::span<const double> p, State& state, double h) const override {
    detectRodContacts(model, state, h, false, p[kMargin], coilLaw(p), catheterLaw(p));
  }
  std::optional<Failure> endStep(const Model& model, std::span<const double> p, const State& state,
                                 double) const override {
    return checkRodContacts(model, state, false, p[kMargin]);
  }
  void apply(const EffectContext& c, std::span<const double> p, RodForces& out) const override {
    const ContactLaw coil = coilLaw(p), catheter = catheterLaw(p);
    const auto& list = c.state.contact.rod;
    for (size_t i = 0; i < list.size(); ++i) {
      const bool withCatheter = c.rod.role == RodRole::Catheter || c.model.rods[list[i].other].role == RodRole::Catheter;
      applyContacts(std::span(list).subspan(i, 1), c, withCatheter ? catheter : coil, out);
    }
  }
  double limitStaticUpdate(const Model&, std::span<const double>, const State& state, int rod,
                           std::span<const Vec3> dx) const override {
    return safeStaticFraction(state, rod, dx, false);
  }
};

}  // namespace

std::unique_ptr<Effect> makeRodContactEffect() { return std::make_unique<RodContact>(); }

}  // namespace coilsim
