#pragma once
// An energy account of one dynamic step, term by term, for finding which
// force puts energy into a system that should only lose it (issue 16: a
// settled packing that erupts by itself).
//
// With one Newton iteration (the scenes' default) the step solves exactly
//   M (v1 - v0) = h [ sum_T F_T - a M v1 ],
//   F_T = f_T(x0, v0) - D_T (v1 - v0) - h K_T v1      (beams: f - (b + h) K v1)
// where f_T, K_T, D_T are what term T assembles at the start of the step
// with the contacts of the step's detection (dynamics.cpp, stepRod). So the
// work each term does on the step's motion, h v1 . F_T, adds up (with the
// mass damping's -h a |v1|^2_M) to v1 . M (v1 - v0) = the kinetic energy's
// change plus |v1 - v0|^2_M / 2, the implicit step's own dissipation. The
// terms are computed here by assembling each effect alone (friction as the
// effect with its Coulomb coefficients minus the effect without them), not
// read from the step.
//
// The contacts' stored energies are computed from the contact lists'
// geometry (k pen^2 / 2 per pair at the closest points, both sides' current
// positions; the wall's half-segment springs per node; kt |slip|^2 / 2 for
// friction), so that a normal term's work plus its stored energy's change
// is what the term put in (> 0) or took out (< 0).
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "physics/assembly.h"
#include "physics/contact/detect.h"
#include "physics/integrator.h"

namespace coilsim::test {

struct StepEnergy {
  std::map<std::string, double> work;  // J, per term: h v1 . F_T
  // Per term, rod and node, the force F_T the step applied (friction: with
  // the normal part; only when asked for).
  std::map<std::string, std::vector<std::vector<Vec6>>> force;
  double kinetic0 = 0, kinetic1 = 0;   // J
  double implicitLoss = 0;             // J, |v1 - v0|^2_M / 2
  double elastic0 = 0, elastic1 = 0;   // J, the beams'
  double potential0 = 0, potential1 = 0;  // J, gravity and buoyancy
  double pairPenalty0 = 0, pairPenalty1 = 0;  // J, the step's pair contacts at x0 and x1
  double wallPenalty0 = 0, wallPenalty1 = 0;  // J, the step's wall contacts at x0 and x1
  // Sum of the terms' work less what M (v1 - v0) . v1 says it is: the
  // account's own error (0 up to round-off when the step was one
  // unsplit Newton iteration).
  double balance = 0;
  // What each normal law put in: its work plus its stored energy's change.
  double pairNormalInput() const {
    return at("self normal") + at("rod normal") + pairPenalty1 - pairPenalty0;
  }
  double wallNormalInput() const { return at("wall normal") + wallPenalty1 - wallPenalty0; }
  double at(const std::string& k) const {
    auto it = work.find(k);
    return it == work.end() ? 0.0 : it->second;
  }
};

namespace energy_detail {

inline double kineticOf(const RodState& r, const std::vector<Quat>& q, const std::vector<Vec3>& v,
                        const std::vector<Vec3>& w) {
  double e = 0;
  for (int i = 0; i < r.activeNodes; ++i) {
    const Mat3 I = nodeInertiaGlobal(r, q[size_t(i)], i);
    e += 0.5 * r.nodes[size_t(i)].mass * v[size_t(i)].squaredNorm() + 0.5 * w[size_t(i)].dot(I * w[size_t(i)]);
  }
  return e;
}

// Penalty energy of the pair contacts of `state`'s lists at `state`'s
// positions, each pair once (it is listed in both rods), with stiffness k.
inline double pairPenalty(const State& state, bool self, double k) {
  double e = 0;
  for (size_t a = 0; a < state.rods.size(); ++a) {
    const RodState& r = state.rods[a];
    for (const ContactPoint& c : self ? r.contact.self : r.contact.rod) {
      const RodState& o = state.rods[size_t(c.other)];
      const Vec3 p = (1 - c.s) * r.x[size_t(c.segment)] + c.s * r.x[size_t(c.segment) + 1];
      const Vec3 q = (1 - c.otherS) * o.x[size_t(c.otherSegment)] + c.otherS * o.x[size_t(c.otherSegment) + 1];
      const double pen = c.radius - c.normal.dot(p - q);
      if (pen > 0) e += 0.5 * 0.5 * k * pen * pen;  // half: both sides list it
    }
  }
  return e;
}

inline double wallPenalty(const State& state, double perLength) {
  double e = 0;
  for (size_t a = 0; a < state.rods.size(); ++a) {
    const RodState& r = state.rods[a];
    for (const ContactPoint& c : r.contact.wall) {
      const double half = 0.5 * perLength * (r.x[size_t(c.segment) + 1] - r.x[size_t(c.segment)]).norm();
      for (int end = 0; end < 2; ++end) {
        if (c.node >= 0 && c.node != end) continue;
        const double pen = c.radius - c.normal.dot(r.x[size_t(c.segment + end)] - c.anchor);
        if (pen > 0) e += 0.5 * half * pen * pen;
      }
    }
  }
  return e;
}

inline const EffectUse* find(const Model& m, std::string_view name) {
  for (const EffectUse& e : m.effects)
    if (e.name() == name && e.enabled) return &e;
  return nullptr;
}

}  // namespace energy_detail

// The account of the step that took `before` to `after` (after = a copy of
// before stepped once; not split into substeps: check state.substepped).
inline StepEnergy accountStep(const Model& model, const State& before, const State& after, bool perNode = false) {
  using namespace energy_detail;
  StepEnergy out;
  const double h = model.timeStep, a = model.damping.massCoeff, b = model.damping.stiffnessCoeff;
  // The start State with the step's contacts (detected at its positions).
  State start = before;
  for (size_t k = 0; k < start.rods.size(); ++k) {
    start.rods[k].contact = after.rods[k].contact;
    for (auto* list : {&start.rods[k].contact.wall, &start.rods[k].contact.self, &start.rods[k].contact.rod})
      for (ContactPoint& c : *list) c.pressed[0] = c.pressed[1] = false;
  }
  // The terms: each effect alone; contacts split into normal and friction.
  struct Term {
    std::string name;
    std::string effect;
    bool frictionless;
  };
  std::vector<Term> terms;
  for (const EffectUse& e : model.effects) {
    if (!e.enabled) continue;
    const std::string n(e.name());
    if (n == "wall_contact" || n == "self_contact" || n == "rod_contact") {
      const std::string base = n == "wall_contact" ? "wall" : n == "self_contact" ? "self" : "rod";
      terms.push_back({base + " normal", n, true});
      terms.push_back({base + " friction", n, false});
    } else {
      terms.push_back({n, n, false});
    }
  }
  const auto assembled = [&](const std::string& effect, bool frictionless, size_t k, RodState& r) {
    Model m = model;
    for (EffectUse& e : m.effects) {
      e.enabled = e.enabled && e.name() == effect;
      if (frictionless && e.name() == effect)
        for (const ParamSpec& p : e.effect->params()) {
          const std::string_view n = p.name;
          if (n == "friction_static" || n == "friction_dynamic" || n == "catheter_friction_static" ||
              n == "catheter_friction_dynamic")
            e.set(n, 0.0);
        }
    }
    r = start.rods[k];
    assembleRod(m, int(k), r, start.time + h, 1.0, effect.empty());
  };
  double lhs = 0;  // v1 . M (v1 - v0) summed
  for (size_t k = 0; k < model.rods.size(); ++k) {
    const RodState& r0 = before.rods[k];
    const RodState& r1 = after.rods[k];
    if (!r0.active || r0.asleep) continue;
    const int n = r0.activeNodes;
    const auto vel = [&](const RodState& r, int i) {
      Vec6 v;
      v << r.v[size_t(i)], r.w[size_t(i)];
      return v;
    };
    std::vector<Mat6> mass(size_t(n), Mat6::Zero());
    for (int i = 0; i < n; ++i) {
      mass[size_t(i)].topLeftCorner<3, 3>() = r0.nodes[size_t(i)].mass * Mat3::Identity();
      mass[size_t(i)].bottomRightCorner<3, 3>() = nodeInertiaGlobal(r0, r0.q[size_t(i)], i);
      const Vec6 v1 = vel(r1, i), dv = v1 - vel(r0, i);
      lhs += v1.dot(mass[size_t(i)] * dv);
      out.implicitLoss += 0.5 * dv.dot(mass[size_t(i)] * dv);
      out.work["mass damping"] -= h * a * v1.dot(mass[size_t(i)] * v1);
    }
    out.kinetic0 += kineticOf(r0, r0.q, r0.v, r0.w);
    out.kinetic1 += kineticOf(r1, r1.q, r1.v, r1.w);
    // Beams (and nodal loads): f - (b + h) K v1, K block tridiagonal.
    RodState r = r0;
    assembled("", false, k, r);
    for (int i = 0; i < n; ++i) {
      Vec6 Kv = r.work.stiffness.diag[size_t(i)] * vel(r1, i);
      if (i > 0) Kv += r.work.stiffness.lower[size_t(i) - 1] * vel(r1, i - 1);
      if (i + 1 < n) Kv += r.work.stiffness.lower[size_t(i)].transpose() * vel(r1, i + 1);
      const Vec6 f = r.work.force[size_t(i)] - (b + h) * Kv;
      out.work["beams"] += h * vel(r1, i).dot(f);
      if (perNode) {
        auto& rods = out.force["beams"];
        rods.resize(model.rods.size());
        rods[k].resize(size_t(n));
        rods[k][size_t(i)] = f;
      }
    }
    const std::vector<Vec6> beamForce(r.work.force.begin(), r.work.force.end());
    for (const Term& t : terms) {
      assembled(t.effect, t.frictionless, k, r);
      double w = 0;
      for (int i = 0; i < n; ++i) {
        const Vec6 v1 = vel(r1, i), dv = v1 - vel(r0, i);
        Vec6 f = r.work.force[size_t(i)] - beamForce[size_t(i)];
        if (r.work.effectsTouchedMatrix) f -= r.work.effectD[size_t(i)] * dv + h * r.work.effectK[size_t(i)] * v1;
        w += h * v1.dot(f);
        if (perNode) {
          auto& rods = out.force[t.name];
          rods.resize(model.rods.size());
          rods[k].resize(size_t(n));
          rods[k][size_t(i)] = f;
        }
      }
      out.work[t.name] += w;
    }
  }
  // Friction = (effect with friction) - (effect without).
  for (const char* base : {"wall", "self", "rod"}) {
    const std::string f = std::string(base) + " friction", nrm = std::string(base) + " normal";
    if (out.work.count(f)) out.work[f] -= out.work[nrm];
  }
  double sum = 0;
  for (const auto& [name, w] : out.work) sum += w;
  out.balance = sum - lhs;
  const Energy e0 = computeEnergy(model, before), e1 = computeEnergy(model, after);
  out.elastic0 = e0.elastic, out.elastic1 = e1.elastic;
  out.potential0 = e0.potential, out.potential1 = e1.potential;
  // Stored penalty energies of the step's contacts.
  if (const EffectUse* s = find(model, "self_contact")) {
    out.pairPenalty0 += pairPenalty(start, true, s->value("stiffness_n_mm"));
    out.pairPenalty1 += pairPenalty(after, true, s->value("stiffness_n_mm"));
  }
  if (const EffectUse* s = find(model, "rod_contact")) {
    out.pairPenalty0 += pairPenalty(start, false, s->value("stiffness_n_mm"));
    out.pairPenalty1 += pairPenalty(after, false, s->value("stiffness_n_mm"));
  }
  if (const EffectUse* s = find(model, "wall_contact")) {
    // Every rod of these scenes has one wire: the wall's stiffness per length of the first.
    const double k = wallStiffness(s->value("stiffness_n_mm2"), s->value("stiffness_per_rigidity_1_mm3"), model.rods[0]);
    out.wallPenalty0 = wallPenalty(start, k);
    out.wallPenalty1 = wallPenalty(after, k);
  }
  return out;
}

}  // namespace coilsim::test
