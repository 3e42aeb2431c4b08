// catheter_compliance: the flexible free catheter segment at the tip, a
// straight polymer tube of length L_c with the coil inside, clamped where
// the guide holds it and carrying the coil's tip node instead of the rigid
// clamp. Linear (Euler-Bernoulli) cantilever of the composite bending
// stiffness EI_c (tube plus the coil inside, the product's composite model
// of physics/catheter.h in its small-deflection limit), loaded by the
// coil's end force and moment and by its own weight q per length (tube and
// coil inside). In the tip frame (x along the exit direction):
//   (v, theta_z): EI/L^3 [[12, -6L], [-6L, 4L^2]],  (w, theta_y): EI/L^3 [[12, 6L], [6L, 4L^2]],
// and the weight alone moves the end by w_q = q L^4 / (8 EI) with slope
// q L^3 / (6 EI) along the load (theta_y = -slope for a load along +z), so
// the coil feels f = -K (d - d_q). Torsion GJ / L with GJ = EI / (1 + nu)
// (a tube, and a wire, has J = 2 I and G = E / (2 (1 + nu))): a coil hanging
// to one side twists a polymer tube by degrees, which moves its far loops by
// millimetres. Axial stiffness 100 times the lateral scale (a tube of
// E A / L ~ 1e4 N/m under mN loads stretches by well under a micron).
// Why not the deployment's beam-chain catheter (DeploymentDef::catheter):
// the workbench fits this segment hundreds of times; the free tip of a
// bench catheter bends by well under a degree, where the closed form is
// the chain's limit at no cost.
#include <algorithm>

#include "physics/effects/builtin.h"
#include "physics/model.h"
#include "physics/state.h"

namespace coilsim {
namespace {

constexpr ParamSpec kParams[] = {
    {"segment_length_mm", "mm", "length of the free, flexible catheter segment beyond the guide", 10.0, 0.5, 200.0, 1e-3},
    {"bending_stiffness_n_mm2", "N mm2", "bending stiffness EI of that segment (with the coil inside)", 10.0, 1e-3, 1e6,
     1e-6},
    {"poisson_ratio", "1", "Poisson's ratio of the segment (polymer 0.35-0.45): its torsion GJ = EI / (1 + nu)", 0.4,
     0.0, 0.5, 1.0},
    // A 0.60/0.42 mm polymer tube of 1.2 g/cm3: 0.21 g/m.
    {"tube_mass_per_length_g_m", "g/m", "mass of the tube per length (the coil inside adds its own)", 0.21, 0.0, 10.0,
     1e-3},
};

constexpr size_t kLength = paramIndex(kParams, "segment_length_mm");
constexpr size_t kBending = paramIndex(kParams, "bending_stiffness_n_mm2");
constexpr size_t kTubeMass = paramIndex(kParams, "tube_mass_per_length_g_m");
constexpr size_t kPoisson = paramIndex(kParams, "poisson_ratio");

class CatheterCompliance final : public Effect {
 public:
  std::string_view name() const override { return "catheter_compliance"; }
  std::string_view description() const override {
    return "flexible free catheter segment at the tip with the coil inside (a weighted cantilever instead of the rigid "
           "clamp)";
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
    K(3, 3) = EI / ((1 + p[kPoisson]) * L);
    const Mat3 R = c.rod.restFrames[0].toRotationMatrix();
    Mat6 T = Mat6::Zero();
    T.topLeftCorner<3, 3>() = R;
    T.bottomRightCorner<3, 3>() = R;
    const Mat6 Kg = T * K * T.transpose();
    // The segment's weight per length: the tube's and the coil's inside it
    // (the coil's line density from the first node that stands for some
    // length: the tip node's share is zero when a node sits exactly at the
    // tip), scaled like every load in a static continuation.
    double coilLine = 0;
    for (int i = 0; i < std::min(2, c.state.activeNodes) && coilLine == 0; ++i)
      if (c.state.nodes[i].length > 0) coilLine = c.state.nodes[i].mass / c.state.nodes[i].length;
    const Vec3 qLocal = R.transpose() * (c.loadFactor * (coilLine + p[kTubeMass]) * c.model.gravity);
    Vec6 sag = Vec6::Zero();  // local end displacement and rotation under the weight alone
    const double wq = L * L * L * L / (8 * EI), tq = L * L * L / (6 * EI);
    sag(1) = qLocal.y() * wq, sag(5) = qLocal.y() * tq;
    sag(2) = qLocal.z() * wq, sag(4) = -qLocal.z() * tq;
    Vec6 d;
    d.head<3>() = c.state.x[0] - c.rod.restPoints[0];
    d.tail<3>() = quatLog((c.state.q[0] * c.rod.restFrames[0].conjugate()).normalized());
    out.force[0] -= Kg * d - T * K * sag;
    out.stiffness[0] += Kg;
    out.touchedMatrix = true;
  }
  // Off is a rigid segment (1e6 N mm2: the tip moves well below a micron);
  // both the length and the stiffness are fitted. Plausible: tubes of
  // 0.5-0.7 mm with a coil inside, 0.5-100 N mm2; free lengths 2-40 mm.
  std::optional<Diagnosable> diagnosis(const SetupHint&) const override {
    return Diagnosable{{{kParams[kBending].name, 1e6 * 1e-6, 10.0 * 1e-6, 0.5e-6, 100e-6},
                        {kParams[kLength].name, 5e-3, 10e-3, 2e-3, 40e-3}},
                       {},
                       {},
                       true};
  }
};

}  // namespace

std::unique_ptr<Effect> makeCatheterComplianceEffect() { return std::make_unique<CatheterCompliance>(); }

}  // namespace coilsim
