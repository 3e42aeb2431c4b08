// A bench that is not level: the true gravity is the nominal one turned by a
// small tilt, g' = exp(a e1 + b e2) g, with e1, e2 orthogonal to g (e1 the
// global x axis made orthogonal to g, or y if x is parallel to it; e2 = g^ x e1).
// Added on top of `gravity`, it applies the difference m (g' - g) per node.
#include <cmath>

#include "physics/effects/builtin.h"
#include "physics/model.h"
#include "physics/state.h"

namespace coilsim {
namespace {

constexpr double kRadPerDeg = M_PI / 180.0;  // ParamSpec's toSI: the degree edge unit

constexpr ParamSpec kParams[] = {
    {"tilt_a_deg", "deg", "bench tilt about e1 (the x axis made orthogonal to gravity)", 0.0, -30.0, 30.0, kRadPerDeg},
    {"tilt_b_deg", "deg", "bench tilt about e2 = gravity direction x e1", 0.0, -30.0, 30.0, kRadPerDeg},
};

constexpr size_t kTiltA = paramIndex(kParams, "tilt_a_deg");
constexpr size_t kTiltB = paramIndex(kParams, "tilt_b_deg");

// The tilted gravity minus the nominal one.
Vec3 gravityChange(const Vec3& g, double a, double b) {
  const double gn = g.norm();
  if (!(gn > 0)) return Vec3::Zero();
  const Vec3 u = g / gn;
  Vec3 e1 = Vec3::UnitX() - u.x() * u;
  if (e1.norm() < 1e-6) e1 = Vec3::UnitY() - u.y() * u;
  e1.normalize();
  const Vec3 e2 = u.cross(e1);
  return quatExp(a * e1 + b * e2) * g - g;
}

class GravityTilt final : public Effect {
 public:
  std::string_view name() const override { return "gravity_tilt"; }
  std::string_view description() const override { return "bench not level: gravity turned by two small tilt angles"; }
  std::span<const ParamSpec> params() const override { return kParams; }
  void apply(const EffectContext& c, std::span<const double> p, RodForces& out) const override {
    const Vec3 dg = gravityChange(c.model.gravity, p[kTiltA], p[kTiltB]);
    for (int i = 0; i < c.state.activeNodes; ++i) out.force[i].head<3>() += c.loadFactor * c.state.nodes[i].mass * dg;
  }
  double energy(const EffectContext& c, std::span<const double> p) const override {
    const Vec3 dg = gravityChange(c.model.gravity, p[kTiltA], p[kTiltB]);
    double e = 0;
    for (int i = 0; i < c.state.activeNodes; ++i) e -= c.state.nodes[i].mass * dg.dot(c.state.x[i]);
    return e;
  }
  // Level is off; a bench set up by eye is level within a few degrees.
  std::optional<Diagnosable> diagnosis(const SetupHint&) const override {
    const double typical = 1.0 * kRadPerDeg, band = 5.0 * kRadPerDeg;
    Diagnosable d;
    d.fit = {{kParams[kTiltA].name, 0.0, typical, -band, band}, {kParams[kTiltB].name, 0.0, typical, -band, band}};
    return d;
  }
};

}  // namespace

std::unique_ptr<Effect> makeGravityTiltEffect() { return std::make_unique<GravityTilt>(); }

}  // namespace coilsim
