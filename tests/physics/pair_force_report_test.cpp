// The coil-coil forces reported per node (RodContacts::rodForce) against
// statics: a straight wire laid across two clamped wires 6 mm apart, under
// gravity, comes to rest on them, and then the external forces on it sum to
// zero: the reported contact forces add up to its weight (no upthrust, no
// drag, frictionless, so nothing else holds it), and their moments about
// its centre of mass balance (two supports: statically determinate, each
// carries W (3 mm -+ x_c) / 6 mm for a centre of mass at x_c; frictionless,
// the wire may slide along itself). References: the sum of m g over its
// nodes and the lever rule.
// Both solves report it: the lumped one at detection (k times the
// penetration at the step's start), the coupled one as its solve applied
// the force (physics/pair_contact_set.h, reportSolvedPairForces).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "physics/integrator.h"
#include "physics/rest_shape.h"
#include "support/rod_models.h"

namespace coilsim {
namespace {

constexpr double kWire = 0.127e-3, kSpan = 12e-3;

RodDef wire(const char* name, const Vec3& start, const Vec3& along, double length, int beams) {
  return test::platinumWire(name, start, along, length, beams, kWire);
}

struct Rest {
  double total = 0, left = 0, right = 0;  // reported coil-coil force on the laid wire, N
  double weight = 0;                      // sum of m g over its nodes, N
  double centre = 0;                      // its centre of mass along x, m
  double fastest = 0;                     // fastest node at the end, m/s
};

ModelDef acrossTwo(double z, bool coupled, bool gravity) {
  std::vector<RodDef> rods = {wire("support-left", Vec3(-3e-3, -5e-3, 0), Vec3::UnitY(), 10e-3, 20),
                              wire("support-right", Vec3(3e-3, -5e-3, 0), Vec3::UnitY(), 10e-3, 20),
                              wire("laid", Vec3(-0.5 * kSpan, 0, z), Vec3::UnitX(), kSpan, 48)};
  for (int k = 0; k < 2; ++k)
    for (int i = 0; i <= rods[size_t(k)].beams; ++i) rods[size_t(k)].constraints.push_back({i, kAllDofs});
  ModelDef def = gravity ? test::modelOf(rods, {"gravity", "rod_contact"}, Vec3(0, 0, -9.81))
                         : test::modelOf(rods, {"rod_contact"});
  def.coupledPairs = coupled;
  for (EffectUse& e : def.effects)
    if (e.name() == "rod_contact") e.set("friction_static", 0.0), e.set("friction_dynamic", 0.0);
  return def;
}

Rest laidAcross(bool coupled) {
  ModelDef def = acrossTwo(2 * kWire + 0.5e-6, coupled, true);  // laid 0.5 um above touching
  def.damping.massCoeff = 20;
  const Model model = compileModel(def);
  State s = makeState(model);
  for (int k = 0; k < 1500; ++k) {
    const StepReport r = step(model, s);
    EXPECT_TRUE(r.ok()) << "step " << k;
    if (!r.ok()) break;
  }
  Rest out;
  const RodState& laid = s.rods[2];
  for (int i = 0; i < laid.activeNodes; ++i) {
    const double f = i < int(laid.contact.rodForce.size()) ? laid.contact.rodForce[size_t(i)] : 0.0;
    out.total += f;
    (laid.x[size_t(i)].x() < 0 ? out.left : out.right) += f;
    out.weight += laid.nodes[size_t(i)].mass * 9.81;
    out.centre += laid.nodes[size_t(i)].mass * 9.81 * laid.x[size_t(i)].x();
    out.fastest = std::max(out.fastest, laid.v[size_t(i)].norm());
  }
  out.centre /= out.weight;
  return out;
}

TEST(PairForceReport, AWireRestingOnTwoWiresReportsItsWeight) {
  for (const bool coupled : {false, true}) {
    SCOPED_TRACE(coupled ? "coupled" : "lumped");
    const Rest r = laidAcross(coupled);
    std::printf("[ measured ] %s: reported %.5f uN (left %.5f, right %.5f) against the weight %.5f uN, "
                "centre of mass at x = %.4f mm, fastest node %.2e mm/s\n",
                coupled ? "coupled" : "lumped", r.total * 1e6, r.left * 1e6, r.right * 1e6, r.weight * 1e6,
                r.centre * 1e3, r.fastest * 1e3);
    ASSERT_LT(r.fastest, 1e-4);  // at rest (0.1 mm/s)
    EXPECT_NEAR(r.total, r.weight, 0.01 * r.weight);
    EXPECT_NEAR(r.left, r.weight * (3e-3 - r.centre) / 6e-3, 0.01 * r.weight);
    EXPECT_NEAR(r.right, r.weight * (3e-3 + r.centre) / 6e-3, 0.01 * r.weight);
  }
}

// The same wire dropped at 50 mm/s from 20 um above the supports, with no
// gravity and no damping: the supports are all that acts on it, so in
// every step the force reported on it equals its momentum change over the
// step, sum m dv / h (Newton's second law; the beams' forces are internal).
// The coupled solve stops a closing contact by its stiffness before it
// penetrates, so the penalty at detection reports nothing for the impact;
// the force the solve applied is what stopped the wire. The lumped figures
// are printed (detection's penalty, a step late).
struct Impact {
  double worst = 0;  // largest |reported - momentum change / h| over the steps, N
  double peak = 0;   // largest momentum change / h, N
};

Impact dropped(bool coupled) {
  const ModelDef def = acrossTwo(2 * kWire + 20e-6, coupled, false);
  const Model model = compileModel(def);
  State s = makeState(model);
  for (Vec3& v : s.rods[2].v) v = Vec3(0, 0, -0.05);
  Impact out;
  for (int k = 0; k < 60; ++k) {
    const RodState& laid = s.rods[2];
    std::vector<Vec3> before = laid.v;
    const StepReport r = step(model, s);
    EXPECT_TRUE(r.ok()) << "step " << k;
    if (!r.ok()) break;
    double change = 0, reported = 0;
    for (int i = 0; i < laid.activeNodes; ++i) {
      change += laid.nodes[size_t(i)].mass * (laid.v[size_t(i)] - before[size_t(i)]).z() / model.timeStep;
      if (size_t(i) < laid.contact.rodForce.size()) reported += laid.contact.rodForce[size_t(i)];
    }
    out.worst = std::max(out.worst, std::abs(reported - change));
    out.peak = std::max(out.peak, std::abs(change));
  }
  return out;
}

TEST(PairForceReport, TheForceThatStopsADroppedWireIsTheForceReported) {
  const Impact lumped = dropped(false), coupled = dropped(true);
  std::printf("[ measured ] largest momentum change / h %.3f mN; reported minus it, worst step: %.3f mN coupled, "
              "%.3f mN lumped (coupled: %.1e of the peak)\n",
              coupled.peak * 1e3, coupled.worst * 1e3, lumped.worst * 1e3, coupled.worst / coupled.peak);
  ASSERT_GT(coupled.peak, 1e-4);  // the wire was stopped (0.1 mN and more)
  EXPECT_LT(coupled.worst, 1e-3 * coupled.peak);
}

}  // namespace
}  // namespace coilsim
