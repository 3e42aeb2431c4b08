// Buoyancy (Archimedes): the displaced fluid's weight, -rho_f A l g per node.
#include <algorithm>
#include <cmath>

#include "physics/effects/builtin.h"
#include "physics/model.h"
#include "physics/state.h"

namespace coilsim {
namespace {

constexpr ParamSpec kParams[] = {
    {"medium_density_g_cm3", "g/cm3", "density of the fluid around the coil (water 1.0, blood 1.06)", 1.0, 0.0, 25.0,
     1000.0},
};

constexpr size_t kDensity = paramIndex(kParams, "medium_density_g_cm3");

// The fluid displaced by a node's piece of rod (a cylinder of its outer radius).
double displacedVolume(const NodeProps& n) { return M_PI * n.radius * n.radius * n.length; }

class Buoyancy final : public Effect {
 public:
  std::string_view name() const override { return "buoyancy"; }
  std::string_view description() const override { return "upthrust of the surrounding fluid"; }
  std::span<const ParamSpec> params() const override { return kParams; }
  void apply(const EffectContext& c, std::span<const double> p, RodForces& out) const override {
    for (int i = 0; i < c.state.activeNodes; ++i)
      out.force[i].head<3>() -= c.loadFactor * p[kDensity] * displacedVolume(c.state.nodes[i]) * c.model.gravity;
  }
  double energy(const EffectContext& c, std::span<const double> p) const override {
    double e = 0;
    for (int i = 0; i < c.state.activeNodes; ++i)
      e += p[kDensity] * displacedVolume(c.state.nodes[i]) * c.model.gravity.dot(c.state.x[i]);
    return e;
  }
  // Fitted from none (off) to water at least; plausible from air to contrast agent (1.4 g/cm3).
  std::optional<Diagnosable> diagnosis(const SetupHint& setup) const override {
    Diagnosable d;
    d.fit = {{kParams[kDensity].name, 0.0, std::max(setup.mediumDensity, 1000.0), 0.0, 1500.0}};
    d.fromSetup = {{kParams[kDensity].name, setup.mediumDensity}};
    return d;
  }
};

}  // namespace

std::unique_ptr<Effect> makeBuoyancyEffect() { return std::make_unique<Buoyancy>(); }

}  // namespace coilsim
