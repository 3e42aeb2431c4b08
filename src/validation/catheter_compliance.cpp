// catheter_compliance: the tip node on a cantilever spring (see effects.h).
#include <mutex>

#include "physics/model.h"
#include "physics/state.h"
#include "validation/effects.h"

namespace coilsim::validation {
namespace {

constexpr ParamSpec kParams[] = {
    {"segment_length_mm", "mm", "length of the free, flexible catheter segment beyond the guide", 10.0, 0.5, 200.0, 1e-3},
    {"bending_stiffness_n_mm2", "N mm2", "bending stiffness EI of that segment (with the coil inside)", 10.0, 1e-3, 1e6,
     1e-6},
};

class CatheterCompliance final : public Effect {
 public:
  std::string_view name() const override { return "catheter_compliance"; }
  std::string_view description() const override {
    return "flexible free catheter segment at the tip (cantilever spring instead of the rigid clamp)";
  }
  std::span<const ParamSpec> params() const override { return kParams; }
  void apply(const EffectContext& c, std::span<const double> p, RodForces& out) const override {
    if (c.rod.role != RodRole::Coil || c.state.activeNodes < 1 || c.rod.constraints.empty()) return;
    if (c.rod.constraints[0].node != 0 || c.rod.constraints[0].mask != kFreeDofs) return;  // still clamped
    const double L = p[0], EI = p[1];
    const double k = EI / (L * L * L);
    Mat6 K = Mat6::Zero();  // local: (dx, dy, dz, rx, ry, rz)
    K(1, 1) = K(2, 2) = 12 * k;
    K(5, 5) = K(4, 4) = 4 * k * L * L;
    K(1, 5) = K(5, 1) = -6 * k * L;
    K(2, 4) = K(4, 2) = 6 * k * L;
    K(0, 0) = 100 * 12 * k;
    K(3, 3) = 100 * 4 * k * L * L;
    const Mat3 R = c.rod.restFrames[0].toRotationMatrix();
    Mat6 T = Mat6::Zero();
    T.topLeftCorner<3, 3>() = R;
    T.bottomRightCorner<3, 3>() = R;
    const Mat6 Kg = T * K * T.transpose();
    Vec6 d;
    d.head<3>() = c.state.x[0] - c.rod.restPoints[0];
    d.tail<3>() = quatLog((c.state.q[0] * c.rod.restFrames[0].conjugate()).normalized());
    out.force[0] -= Kg * d;
    out.stiffness[0] += Kg;
    out.touchedMatrix = true;
  }
};

}  // namespace

std::unique_ptr<Effect> makeCatheterComplianceEffect() { return std::make_unique<CatheterCompliance>(); }

void ensureValidationEffects() {
  static std::once_flag once;
  std::call_once(once, [] {
    if (!EffectRegistry::global().find("catheter_compliance"))
      EffectRegistry::global().add(makeCatheterComplianceEffect());
    // A physics built-in (src/physics/effects/gravity_tilt.cpp); added here
    // too in case builtin.cpp does not list it.
    if (!EffectRegistry::global().find("gravity_tilt")) EffectRegistry::global().add(makeGravityTiltEffect());
  });
}

bool releasesClamp(const EffectUse& use) { return use.effect && use.name() == "catheter_compliance"; }

}  // namespace coilsim::validation
