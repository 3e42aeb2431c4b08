// Probe, not a test (docs/contact.md, "Dense packing: penetration and
// convergence (issue 16)"): the packed sac of tests/support/dense_packing.h
// settled to rest, then 0.2 s from that one State with every contact
// penalty at 1, 2, 4 and 8 times its registered value; per factor the
// sustained wall load, the deepest coil-coil overlap and the wire's least
// clearance from the wall's faces (both measured independently of the
// contact code, every 10 steps), and the wall's total normal force against
// the coils' weight less upthrust. Then the wall's total, step by step, at
// rest. Build and run from the worktree, after building physics_tests:
//   c++ -std=c++20 -O2 -mavx2 -mfma -I tests -I build/layers/physics -isystem /usr/include/eigen3 \
//     docs/probes/dense_packing_probe.cpp build/src/physics/libcoilsim_physics.a -lfcl -o /tmp/dense_probe
//   /tmp/dense_probe [frictionless wall: 1 (default) or 0] [time step ms: 1] [settling s: 1]
// DENSE_PROBE_SKIP_TABLE=1 leaves out the table, DENSE_PROBE_FRICTIONLESS_PAIRS=1 takes the coil-coil friction off.
// DENSE_PROBE_ENERGY=s: instead of the table, after the settling, s seconds
// more with an energy account of every step (support/step_energy.h: the work
// of each force term, and what the normal laws put in beyond their work),
// one line per 10 ms and one per step whose kinetic energy doubled; so the
// eruption docs/contact.md describes (1 ms, 1x, settled 3.7 s) is
//   DENSE_PROBE_ENERGY=0.15 /tmp/dense_probe 1 1 3.7
#include <cstdio>
#include <cstdlib>

#include "physics/assembly.h"
#include "physics/contact/detect.h"
#include "physics/integrator.h"
#include "support/dense_packing.h"
#include "support/step_energy.h"

using namespace coilsim;
using namespace coilsim::test::dense;

// The total force of effect `only` on all coils as the step applies it: the
// forces at the State's positions (the end of its last step) with the
// contacts found at that step's start; elastic forces taken out.
Vec3 effectTotal(const Model& model, const State& state, const std::string& only) {
  Model with = model, none = model;
  for (EffectUse& e : with.effects) e.enabled = e.name() == only;
  for (EffectUse& e : none.effects) e.enabled = false;
  Vec3 f = Vec3::Zero();
  for (size_t r = 0; r < state.rods.size(); ++r) {
    State a = state, b = state;
    assembleRod(with, int(r), a.rods[r], a.time, 1.0, false);
    assembleRod(none, int(r), b.rods[r], b.time, 1.0, false);
    for (int i = 0; i < state.rods[r].activeNodes; ++i)
      f += (a.rods[r].work.force[size_t(i)] - b.rods[r].work.force[size_t(i)]).head<3>();
  }
  return f;
}

// Steps `state` on for `seconds`, printing the energy account (pJ) of each
// step: every 10 ms, and at every step whose kinetic energy doubled.
void energyAccount(const Model& model, State& state, double seconds) {
  const double h = model.timeStep, pJ = 1e12;
  std::printf("| t ms | kinetic | beams | mass damping | wall normal | self normal | self friction | rod normal | "
              "rod friction | gravity + buoyancy | pair normal: work + stored | wall normal: work + stored | "
              "account's error | fastest node mm/s |\n|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  const int steps = int(std::lround(seconds / h)), every = int(std::lround(0.01 / h));
  for (int k = 1; k <= steps; ++k) {
    const State before = state;
    const long substepped = state.substepped;
    step(model, state);
    const test::StepEnergy e = test::accountStep(model, before, state);
    const bool jump = e.kinetic1 > 2 * e.kinetic0 && e.kinetic1 * pJ > 1e-3;
    if (k % every && !jump) continue;
    std::printf("| %.0f%s | %.3g | %.3g | %.3g | %.3g | %.3g | %.3g | %.3g | %.3g | %.3g | %.3g | %.3g | %.2g | %.3g |\n",
                state.time * 1e3, state.substepped != substepped ? " (substeps: account n/a)" : "", e.kinetic1 * pJ,
                e.at("beams") * pJ, e.at("mass damping") * pJ, e.at("wall normal") * pJ, e.at("self normal") * pJ,
                e.at("self friction") * pJ, e.at("rod normal") * pJ, e.at("rod friction") * pJ,
                (e.at("gravity") + e.at("buoyancy")) * pJ, e.pairNormalInput() * pJ, e.wallNormalInput() * pJ,
                e.balance * pJ, fastestNode(state) * 1e3);
  }
}

int main(int argc, char** argv) {
  const bool frictionless = argc < 2 || std::atoi(argv[1]) != 0;
  const double h = argc < 3 ? 1e-3 : std::atof(argv[2]) * 1e-3;
  ModelDef def = packedSac(frictionless);
  if (std::getenv("DENSE_PROBE_FRICTIONLESS_PAIRS"))
    for (EffectUse& e : def.effects)
      if (e.name() == "self_contact" || e.name() == "rod_contact") {
        e.set("friction_static", 0);
        e.set("friction_dynamic", 0);
      }
  def.damping.massCoeff = 20;
  def.timeStep = h;
  Model model = compileModel(def);
  State settled = makeState(model);
  const double settleSeconds = argc < 4 ? 1.0 : std::atof(argv[3]);
  const int settle = int(std::lround(settleSeconds / h)), after = int(std::lround(0.2 / h)), every = int(std::lround(0.01 / h));
  const double weight = netWeight(def), r = kWireRadius;
  for (int k = 1; k <= settle; ++k) {
    step(model, settled);
    if (k % int(std::lround(0.5 / h)) == 0)
      std::printf("settling, t = %.1f s: wall's total normal force / (weight - upthrust) %.3f, sustained load %.4f mN, fastest node %.3g mm/s\n",
                  k * h, wallNormalTotal(settled).z() / weight, settled.stats.wallLoad.now * 1e3, fastestNode(settled) * 1e3);
  }
  if (const char* seconds = std::getenv("DENSE_PROBE_ENERGY")) {
    energyAccount(model, settled, std::atof(seconds));
    return 0;
  }
  const test::ConvexCavity sac(sacWall());
  std::printf("%s wall, h %.3g ms, %.1f mm in %zu coils; weight less upthrust %.4f mN; settled 1 s: %ld refused, %ld in substeps\n",
              frictionless ? "frictionless" : "registered (friction)", h * 1e3, coilLength(def) * 1e3, def.rods.size(),
              weight * 1e3, settled.blowups, settled.substepped);
  std::printf("| penalties | sustained wall load mN | deepest coil-coil overlap um (%% of d) | least wire clearance from the wall's faces um | wall's total normal force / (weight - upthrust) | fastest node mm/s | refused | in substeps |\n");
  std::printf("|---|---|---|---|---|---|---|---|\n");
  for (int factor : {1, 2, 4, 8}) {
    if (std::getenv("DENSE_PROBE_SKIP_TABLE")) break;
    scalePenalties(model, factor);
    State s = settled;
    Depths deepest;
    deepest.wall = -INFINITY;
    for (int k = 1; k <= after; ++k) {
      step(model, s);
      if (k % every == 0) {
        const Depths d = measure(s, sac);
        deepest.pair = std::max(deepest.pair, d.pair);
        deepest.wall = std::max(deepest.wall, d.wall);
      }
    }
    const Vec3 w = wallNormalTotal(s);
    std::printf("| %dx | %.4f | %.3f (%.2f %%) | %.2f | %.3f (horizontal %.3f) | %.3g | %ld | %ld |\n", factor,
                s.stats.wallLoad.now * 1e3, deepest.pair * 1e6, 100 * deepest.pair / (2 * r), -deepest.wall * 1e6,
                w.z() / weight, w.head<2>().norm() / weight, fastestNode(s) * 1e3, s.blowups - settled.blowups,
                s.substepped - settled.substepped);
  }
  // The pair contacts at rest: their normal forces at detection and their
  // friction springs' memories, summed over both sides of every pair (a
  // pair's two contacts act on two bodies: the sums are internal forces and
  // must vanish).
  {
    Vec3 normal = Vec3::Zero(), spring = Vec3::Zero();
    double springAbs = 0;
    int pairs = 0, unmatched = 0, sliding = 0;
    const double kt = 0.5 * EffectRegistry::global().use("rod_contact").value("stiffness_n_mm");
    for (size_t a = 0; a < settled.rods.size(); ++a)
      for (const auto* list : {&settled.rods[a].contact.self, &settled.rods[a].contact.rod})
        for (const ContactPoint& c : *list) {
          normal += c.normalForce * c.normal;
          spring -= kt * c.slip;
          springAbs += kt * c.slip.norm();
          sliding += c.sliding;
          ++pairs;
          const auto& other = list == &settled.rods[a].contact.self ? settled.rods[size_t(c.other)].contact.self
                                                                     : settled.rods[size_t(c.other)].contact.rod;
          bool found = false;
          for (const ContactPoint& d : other)
            found = found || (d.segment == c.otherSegment && d.otherSegment == c.segment && size_t(d.other) == a);
          unmatched += !found;
        }
    std::printf("pair contacts at rest: %d (%d without their partner, %d sliding); net normal force at detection "
                "(%.4f %.4f %.4f) mN; net friction spring force -kt slip (%.4f %.4f %.4f) mN (sum of magnitudes %.4f mN)\n",
                pairs, unmatched, sliding, normal.x() * 1e3, normal.y() * 1e3, normal.z() * 1e3, spring.x() * 1e3,
                spring.y() * 1e3, spring.z() * 1e3, springAbs * 1e3);
  }
  for (const char* e : {"wall_contact", "self_contact", "rod_contact", "gravity", "buoyancy", "drag"}) {
    const Vec3 f = effectTotal(model, settled, e);
    std::printf("applied by %s: (%.4f %.4f %.4f) mN\n", e, f.x() * 1e3, f.y() * 1e3, f.z() * 1e3);
  }
  // Step by step at rest, registered penalties: is the wall's total steady, or does it alternate?
  scalePenalties(model, 1);
  State s = settled;
  std::printf("step by step from the settled State (registered penalties):\n");
  for (int k = 1; k <= 12; ++k) {
    step(model, s);
    double kinetic = 0;
    for (const RodState& rod : s.rods)
      for (int i = 0; i < rod.activeNodes; ++i) kinetic += 0.5 * rod.nodes[size_t(i)].mass * rod.v[size_t(i)].squaredNorm();
    const Vec3 w = wallNormalTotal(s);
    std::printf("  %2d: wall total z %.4f mN (/ weight %.3f), kinetic energy %.3g pJ, fastest %.3g mm/s\n", k, w.z() * 1e3,
                w.z() / weight, kinetic * 1e12, fastestNode(s) * 1e3);
  }
}
