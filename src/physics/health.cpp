#include <cmath>

#include "physics/beam.h"
#include "physics/integrator.h"

namespace coilsim {

// A step result is unhealthy if anything is non-finite, moves faster than a
// coil can, or a beam is stretched or crushed beyond any elastic meaning.
std::optional<Failure> checkHealth(const Model& model, const State& state) {
  const HealthLimits& lim = model.health;
  // Built only on failure: the rod, the node or beam, the quantity.
  const auto blowUp = [](const RodModel& rm, int node, int beam, const char* quantity, double value, double limit,
                         std::string text) {
    Failure f = badRod(rm.name, std::move(text));
    f.kind = FailureKind::BlowUp;
    f.node = node, f.beam = beam;
    f.quantity = quantity, f.value = value, f.limit = limit;
    return f;
  };
  for (size_t k = 0; k < model.rods.size(); ++k) {
    const RodModel& rm = model.rods[k];
    const RodState& r = state.rods[k];
    if (!r.active) continue;
    for (int i = 0; i < r.activeNodes; ++i) {
      // A NaN or infinity anywhere makes the sum non-finite: one test per node.
      const double sum = r.x[i].sum() + r.q[i].coeffs().sum() + r.v[i].sum() + r.w[i].sum();
      if (!std::isfinite(sum))
        return blowUp(rm, i, -1, "position, rotation or velocity", sum, INFINITY,
                      "non-finite position, rotation or velocity");
      if (r.v[i].squaredNorm() > lim.maxSpeed * lim.maxSpeed)
        return blowUp(rm, i, -1, "speed", r.v[i].norm(), lim.maxSpeed,
                      "speed " + std::to_string(r.v[i].norm()) + " m/s exceeds " + std::to_string(lim.maxSpeed) +
                          " m/s (numerical blow-up)");
      if (r.w[i].squaredNorm() > lim.maxAngularSpeed * lim.maxAngularSpeed)
        return blowUp(rm, i, -1, "angular speed", r.w[i].norm(), lim.maxAngularSpeed,
                      "angular speed exceeds " + std::to_string(lim.maxAngularSpeed) + " rad/s");
    }
    // |strain| > s  <=>  |chord|^2 outside [(1 - s)^2, (1 + s)^2] L^2: no
    // square root or division per beam unless the check fails.
    const double hi = (1 + lim.maxAxialStrain) * (1 + lim.maxAxialStrain);
    const double lo = lim.maxAxialStrain < 1 ? (1 - lim.maxAxialStrain) * (1 - lim.maxAxialStrain) : 0.0;
    for (int e = 0; e + 1 < r.activeNodes; ++e) {
      const double L2 = r.beams[e].length * r.beams[e].length;
      const double d2 = (r.x[e + 1] - r.x[e]).squaredNorm();
      if (d2 <= hi * L2 && d2 >= lo * L2) continue;
      const double strain = std::sqrt(d2) / r.beams[e].length - 1.0;
      if (std::abs(strain) > lim.maxAxialStrain)
        return blowUp(rm, -1, e, "axial strain", strain, lim.maxAxialStrain,
                      "axial strain " + std::to_string(strain) + " beyond " + std::to_string(lim.maxAxialStrain));
    }
  }
  return std::nullopt;
}

Energy computeEnergy(const Model& model, const State& state) {
  Energy en;
  BeamEval ev;
  for (size_t k = 0; k < model.rods.size(); ++k) {
    const RodModel& rm = model.rods[k];
    const RodState& r = state.rods[k];
    if (!r.active) continue;
    for (int i = 0; i < r.activeNodes; ++i) {
      const Mat3 R = r.q[i].toRotationMatrix();
      const Vec3 wBody = R.transpose() * r.w[i];
      en.kinetic += 0.5 * r.nodes[i].mass * r.v[i].squaredNorm() + 0.5 * wBody.dot(r.nodes[i].inertia.cwiseProduct(wBody));
    }
    for (int e = 0; e + 1 < r.activeNodes; ++e) {
      evalBeam(r.beams[e], r.x[e], r.q[e], r.x[e + 1], r.q[e + 1], false, ev);
      en.elastic += ev.energy;
    }
    const EffectContext ctx{model, rm, r, state.time, 1.0, model.timeStep};
    for (const EffectUse& u : model.effects)
      if (u.enabled) en.potential += u.effect->energy(ctx, u.values);
    for (const NodalLoad& l : rm.loads)
      if (l.node < r.activeNodes) en.potential -= l.force.dot(r.x[l.node]);  // moments: no potential kept
  }
  return en;
}

}  // namespace coilsim
