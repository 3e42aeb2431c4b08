// Buoyancy (Archimedes): the displaced fluid's weight, -rho_f A l g per node.
#include "physics/effects/builtin.h"
#include "physics/model.h"
#include "physics/state.h"

namespace coilsim {
namespace {

constexpr ParamSpec kParams[] = {
    {"medium_density_g_cm3", "g/cm3", "density of the fluid around the coil (water 1.0, blood 1.06)", 1.0, 0.0, 25.0,
     1000.0},
};

class Buoyancy final : public Effect {
 public:
  std::string_view name() const override { return "buoyancy"; }
  std::string_view description() const override { return "upthrust of the surrounding fluid"; }
  std::span<const ParamSpec> params() const override { return kParams; }
  void apply(const EffectContext& c, std::span<const double> p, RodForces& out) const override {
    const double rhoA = p[0] * c.rod.section.area;
    for (int i = 0; i < c.rod.nnode; ++i) out.force[i].head<3>() -= c.loadFactor * rhoA * c.rod.nodeLength[i] * c.model.gravity;
  }
  double energy(const EffectContext& c, std::span<const double> p) const override {
    double e = 0;
    for (int i = 0; i < c.rod.nnode; ++i)
      e += p[0] * c.rod.section.area * c.rod.nodeLength[i] * c.model.gravity.dot(c.state.x[i]);
    return e;
  }
};

}  // namespace

std::unique_ptr<Effect> makeBuoyancyEffect() { return std::make_unique<Buoyancy>(); }

}  // namespace coilsim
