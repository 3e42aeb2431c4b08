// Viscous drag by resistive-force theory (Gray & Hancock 1955): per length,
// f = -(c_n v_normal + c_t v_tangential), with
//   c_n = 4 pi mu / (ln(2 lambda / r) + 1/2),  c_t = 2 pi mu / (ln(2 lambda / r) - 1/2),
// lambda a characteristic length of the shape (for a coil, its loop size).
// Linear in velocity, so its exact derivative goes into the implicit matrix.
#include <algorithm>
#include <cmath>

#include "physics/effects/builtin.h"
#include "physics/model.h"
#include "physics/state.h"

namespace coilsim {
namespace {

constexpr ParamSpec kParams[] = {
    {"viscosity_pa_s", "Pa s", "dynamic viscosity of the medium (water 0.001, blood ~0.0035)", 0.001, 0.0, 100.0, 1.0},
    {"rft_length_mm", "mm", "characteristic length lambda of resistive-force theory", 7.0, 0.1, 1000.0, 1e-3},
};

constexpr size_t kViscosity = paramIndex(kParams, "viscosity_pa_s");
constexpr size_t kLambda = paramIndex(kParams, "rft_length_mm");

class Drag final : public Effect {
 public:
  std::string_view name() const override { return "drag"; }
  std::string_view description() const override { return "viscous drag of the medium (resistive-force theory)"; }
  std::span<const ParamSpec> params() const override { return kParams; }
  void apply(const EffectContext& c, std::span<const double> p, RodForces& out) const override {
    const double mu = p[kViscosity], lambda = p[kLambda];
    for (int i = 0; i < c.state.activeNodes; ++i) {
      // Keep the logarithm away from its pole for absurdly short lambda.
      const double lg = std::max(std::log(2.0 * lambda / c.state.nodes[i].radius), 1.0);
      const double cn = 4 * M_PI * mu / (lg + 0.5), ct = 2 * M_PI * mu / (lg - 0.5);
      const Vec3 t = c.state.q[i] * Vec3::UnitX();
      const Mat3 tt = t * t.transpose();
      const Mat3 d = c.state.nodes[i].length * (cn * (Mat3::Identity() - tt) + ct * tt);
      out.force[i].head<3>() -= d * c.state.v[i];
      out.damping[i].topLeftCorner<3, 3>() += d;
      out.touchedMatrix = true;
    }
  }
  // Fitted from none (off) to a viscous medium; plausible from air to glycerol (1.4 Pa s).
  std::optional<Diagnosable> diagnosis(const SetupHint& setup) const override {
    Diagnosable d;
    d.fit = {{kParams[kViscosity].name, 0.0, std::max(setup.mediumViscosity, 0.01), 0.0, 2.0}};
    d.fromSetup = {{kParams[kViscosity].name, setup.mediumViscosity}};
    return d;
  }
};

}  // namespace

std::unique_ptr<Effect> makeDragEffect() { return std::make_unique<Drag>(); }

}  // namespace coilsim
