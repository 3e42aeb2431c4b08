// Self-contact: non-adjacent segments of one rod (the loops of a coil) as
// capsules pushing each other apart, with Coulomb friction. Model and
// reasons: physics/contact/response.h; broad phase: physics/contact/detect.h.
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
    {"friction_stiffness_ratio", "1", "stick spring stiffness over normal stiffness (regularised Coulomb)", 0.5, 0.01,
     10.0, 1.0},
    {"contact_radius_scale", "1",
     "contact distance over twice the wire radius (a wound coil's outer radius over its stiffness-equivalent one)", 1.0,
     0.0, 5.0, 1.0},
};

constexpr size_t kStiffness = paramIndex(kParams, "stiffness_n_mm"), kDamping = paramIndex(kParams, "damping_ratio"),
                 kMargin = paramIndex(kParams, "margin_mm"), kStatic = paramIndex(kParams, "friction_static"),
                 kDynamic = paramIndex(kParams, "friction_dynamic"), kStick = paramIndex(kParams, "friction_stiffness_ratio"),
                 kRadiusScale = paramIndex(kParams, "contact_radius_scale");

ContactLaw lawOf(std::span<const double> p) {
  return {p[kStiffness], p[kDamping], p[kStatic], p[kDynamic], p[kStick], 2.0, p[kRadiusScale]};
}

class SelfContact final : public Effect {
 public:
  std::string_view name() const override { return "self_contact"; }
  std::string_view description() const override { return "non-adjacent segments of one rod, with friction"; }
  std::span<const ParamSpec> params() const override { return kParams; }
  void beginStep(const Model& model, std::span<const double> p, State& state, double h) const override {
    const ContactLaw law = lawOf(p);
    detectRodContacts(model, state, h, true, p[kMargin], law, law);
  }
  // A loop snapping onto another within one step, from a start where the
  // pair was beyond the margin and not closing, is outside the step's
  // implicit solve: the step is retaken in substeps (as for rod_contact).
  std::optional<Failure> endStep(const Model& model, std::span<const double> p, const State& state,
                                 double) const override {
    return checkRodContacts(model, state, true, p[kMargin], p[kRadiusScale]);
  }
  void apply(const EffectContext& c, std::span<const double> p, RodForces& out) const override {
    applyContacts(c.state.contact.self, c, lawOf(p), out, true);
  }
  double limitStaticUpdate(const Model&, std::span<const double> p, const State& state, int rod,
                           std::span<const Vec3> dx) const override {
    return safeStaticFraction(state, rod, dx, true, p[kRadiusScale]);
  }
  // Its magnitude is where loops touch: at 0 they pass through each other
  // (off), at 1 the wire's own diameter; a wound coil's outer diameter is
  // up to about twice its stiffness-equivalent wire's. (Its penalty
  // stiffness only sets how far they press in: well under a micrometre.)
  // Held in validation: frictionless, as static equilibria are solved (one
  // with Coulomb friction depends on the path to it), so that static and
  // dynamic stages of one file share one model; and a penalty of 5 N/mm,
  // below which a 1 ms dynamic step gives the answer of steps 4x shorter
  // (the default 50 N/mm does not on a 0.1 mm wire: docs/validation.md)
  // while loops resting under gravity still press in by under 0.1 um.
  std::optional<Diagnosable> diagnosis(const SetupHint&) const override {
    return Diagnosable{{{kParams[kRadiusScale].name, 0.0, 1.0, 0.9, 2.2}},
                       {},
                       {{kParams[kStatic].name, 0.0},
                        {kParams[kDynamic].name, 0.0},
                        {kParams[kStiffness].name, 5.0 * kParams[kStiffness].toSI}}};
  }
};

}  // namespace

std::unique_ptr<Effect> makeSelfContactEffect() { return std::make_unique<SelfContact>(); }

}  // namespace coilsim
