// catheter_compliance: the flexible free catheter segment at the tip, a
// cantilever of length L_c and bending stiffness EI_c carrying the coil's
// tip node instead of the rigid clamp. Its end stiffness (Euler-Bernoulli
// cantilever, end load and moment) in the tip frame (x along the exit
// direction):
//   (v, theta_z): EI/L^3 [[12, -6L], [-6L, 4L^2]],  (w, theta_y): EI/L^3 [[12, 6L], [6L, 4L^2]],
// with axial and torsional stiffness 100 times the lateral scale (the
// catheter neither stretches nor twists appreciably).
#include "physics/effects/builtin.h"
#include "physics/model.h"
#include "physics/state.h"

namespace coilsim {
namespace {

constexpr ParamSpec kParams[] = {
    {"segment_length_mm", "mm", "length of the free, flexible catheter segment beyond the guide", 10.0, 0.5, 200.0, 1e-3},
    {"bending_stiffness_n_mm2", "N mm2", "bending stiffness EI of that segment (with the coil inside)", 10.0, 1e-3, 1e6,
     1e-6},
};

constexpr size_t kLength = paramIndex(kParams, "segment_length_mm");
constexpr size_t kBending = paramIndex(kParams, "bending_stiffness_n_mm2");

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
    const double L = p[kLength], EI = p[kBending];
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
  // Off is the stiffest segment the bounds allow (rigid to well below a
  // micron); plausible: polymer tubes of 0.5-0.7 mm with a coil inside.
  std::optional<Diagnosable> diagnosis(const SetupHint&) const override {
    return Diagnosable{{{kParams[kBending].name, 1e6 * 1e-6, 10.0 * 1e-6, 0.5e-6, 100e-6}}, {}, true};
  }
};

}  // namespace

std::unique_ptr<Effect> makeCatheterComplianceEffect() { return std::make_unique<CatheterCompliance>(); }

}  // namespace coilsim
