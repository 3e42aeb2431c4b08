// Dense contact that stays right (issue 16), on a packed sac
// (support/dense_packing.h: four coils, 194 mm, laid as nested spherical
// spirals in the bottom of a 7 mm sac, nearly every segment within reach of
// another or of the wall), with wall, self and coil-coil contact:
// - the contacts keep the wires apart and inside the wall while the packing
//   settles under gravity and a fifth coil is pushed into it. References
//   computed here, not by the contact code: every pair of segments'
//   centre-line distance in closed form, every node's clearance from the
//   icosphere's face planes (exact for a point inside a convex polyhedron;
//   a segment is nearest a plane at an end), at every 10th step. With the
//   contacts off the same checks fail (the control).
// - at rest, with the pair contacts solved coupled, the reported wall load
//   (State::stats.wallLoad, the sustained figure) converges as the wall and
//   coil-coil penalties stiffen from one settled State, and the wall's
//   reported force is the packing's momentum balance. Under the lumped
//   pair law (the default) the packing is not at rest: it creeps and
//   erupts by itself (at 4 times its penalties; built without fused
//   multiply-adds, as the sanitizer build is, at 1 and 2 times), so a
//   convergence seen from it depends on the build's rounding, not on the
//   law, and is not asserted (docs/contact.md, Known problems, "A dense
//   packing at rest presses the wall with more than its weight").
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "physics/contact/detect.h"
#include "physics/integrator.h"
#include "support/dense_packing.h"

namespace coilsim {
namespace {

using namespace test::dense;

constexpr int kEvery = 10;  // steps between the independent checks

struct DynamicRun {
  Depths deepest;   // over every checked step
  Depths settled;   // at the end of the settling, before the push
  long refused = 0, substepped = 0;
  double pushForce = 0;  // largest coil-coil force on a node of the pushed coil, N
  double tipOffLine = 0;  // how far the pushed coil's tip was turned off its line by the packing, m
};

// The packing settles under gravity for `settle` steps (from the laid
// state: the gaps close and the shells land on each other and the wall),
// then a fifth coil, aimed from the sac's centre at the innermost shell
// (37 deg off the bottom pole) with its tip 0.2 mm short of touching it, is
// pushed 1.5 mm at 20 mm/s into the packing and held for `hold` steps.
DynamicRun settleAndPush(bool contacts, int settle, int hold) {
  ModelDef def = packedSac(false);
  const double a = 37 * M_PI / 180, speed = 0.02, travel = 1.5e-3;
  const Vec3 along(std::sin(a), 0, -std::cos(a));
  const double shell = kSacRadius - 1.1 * kWireRadius - (kShells - 1) * (2 * kWireRadius + kGap);
  def.rods.push_back(pushedCoil((shell - 2 * kWireRadius - 0.2e-3) * along, along, 5e-3));
  // The control: no contacts, and no gravity either, under which the
  // shells would fall together and none through another; the pushed coil
  // then passes through the shells and, at the end of its push, the wall.
  if (!contacts)
    for (EffectUse& e : def.effects)
      if (e.name() != "drag") e.enabled = false;
  Model model = compileModel(def);
  State s = makeState(model);
  const test::ConvexCavity sac(sacWall());
  const long pushing = std::lround(travel / speed / model.timeStep);
  DynamicRun out;
  const auto check = [&](const Depths& d) {
    out.deepest.pair = std::max(out.deepest.pair, d.pair);
    out.deepest.wall = std::max(out.deepest.wall, d.wall);
  };
  check(measure(s, sac));
  for (long k = 1; k <= settle + pushing + hold; ++k) {
    if (k == settle + 1) model.rods.back().constraints[0].velocity = speed * along;
    if (k == settle + pushing + 1) model.rods.back().constraints[0].velocity = Vec3::Zero();
    if (!step(model, s).ok()) ++out.refused;
    if (k % kEvery == 0) check(measure(s, sac));
    if (k == settle) out.settled = measure(s, sac);
    const RodState& pushed = s.rods.back();
    for (double f : pushed.contact.rodForce) out.pushForce = std::max(out.pushForce, f);
    const Vec3 tip = pushed.x[size_t(pushed.activeNodes - 1)], base = pushed.x.front();
    out.tipOffLine = std::max(out.tipOffLine, (tip - base - (tip - base).dot(along) * along).norm());
  }
  out.substepped = s.substepped;
  return out;
}

TEST(DensePacking, SettlingAndAPushedCoilKeepTheWiresApartAndInsideTheWall) {
  const DynamicRun run = settleAndPush(true, 300, 125);
  const double d = 2 * kWireRadius;
  std::printf("[ measured ] settled: %d of %d segments touching; deepest coil-coil overlap %.2f um (%.2f %% of d), "
              "wire past the wall's faces %.2f um (skin %.2f um); %ld steps in substeps, %ld refused\n",
              run.settled.touching, run.settled.segments, run.deepest.pair * 1e6, 100 * run.deepest.pair / d,
              run.deepest.wall * 1e6, kWallSkin * kWireRadius * 1e6, run.substepped, run.refused);
  std::printf("[ measured ] pushed coil: largest coil-coil force on a node %.3f mN, tip turned %.3f mm off its line\n",
              run.pushForce * 1e3, run.tipOffLine * 1e3);
  // The push reached the packing.
  EXPECT_GT(run.pushForce, 0.0);
  // The scene is dense: at least 90 % of the segments (the pushed coil's
  // ten, still apart, included) within 10 % of r of a wire or the wall.
  EXPECT_GE(run.settled.touching, 0.9 * run.settled.segments);
  EXPECT_EQ(run.refused, 0);
  EXPECT_LE(run.deepest.pair, 0.1 * d) << "coil-coil interpenetration beyond 10 % of the wire diameter";
  // The skin (kWallSkin r outside the wire) may be pressed in, the wire itself may not pass the wall.
  EXPECT_LE(run.deepest.wall, 0.0) << "the wire passed the wall's faces";
}

TEST(DensePacking, WithoutContactsTheSameChecksFail) {
  const DynamicRun run = settleAndPush(false, 0, 0);
  EXPECT_GT(run.deepest.pair, 0.1 * 2 * kWireRadius);
  EXPECT_GT(run.deepest.wall, 0.0);
}

// The same scene with its pair contacts solved coupled (Model::coupledPairs,
// physics/pair_coupling.h) and the contact set decided within the step
// (physics/pair_contact_set.h), settled from the laid state; the wall's
// force reported as the solve applied it. Where the lumped solve's packing
// erupts by itself (4 times its penalties; built without fused
// multiply-adds, 1 and 2 times: docs/contact.md), here each doubling up
// to 8 times changes the sustained wall load by less than the 10 %
// with the packing at rest, no step is refused, and the wires stay apart
// and inside the wall (the independent checks of the first test, every 10
// steps). At 8 times it chattered on the wall while the solve could pull
// a pair's sides together (docs/contact.md, "Pairs let go"). Not Richardson
// in 1 / k, as for a penalty in series with the wires: under the coupled
// solve the load moves by 0.2-3 % per doubling, not monotonically, within
// the spread between settled packings (docs/contact.md, Known problems).
TEST(DensePacking, CoupledPairContactsKeepTheWallLoadConvergedUpToEightTimesThePenalties) {
  ModelDef def = packedSac(true);
  def.damping.massCoeff = 20;
  for (EffectUse& e : def.effects)
    if (e.name() == "wall_contact") e.set("rigid", 0.0);  // the coupled solve takes penalty walls
  def.coupledPairs = true;
  Model model = compileModel(def);
  const double weight = netWeight(def);
  const test::ConvexCavity sac(sacWall());
  State settled = makeState(model);
  Depths deepest;
  deepest.wall = -INFINITY;
  const auto check = [&](const State& s) {
    const Depths d = measure(s, sac);
    deepest.pair = std::max(deepest.pair, d.pair);
    deepest.wall = std::max(deepest.wall, d.wall);
  };
  for (int k = 1; k <= 900; ++k) {
    ASSERT_TRUE(step(model, settled).ok()) << "settling, step " << k;
    if (k % kEvery == 0) check(settled);
  }
  constexpr int kFactors = 4;
  double loads[kFactors];
  for (int i = 0; i < kFactors; ++i) {
    const double factor = double(1 << i);
    scalePenalties(model, factor);
    State s = settled;
    for (int k = 1; k <= 400; ++k) {  // 0.2 s leaves the packing moving at 2 and 4 times
      ASSERT_TRUE(step(model, s).ok()) << "x" << factor << " step " << k;
      if (k % kEvery == 0) check(s);
    }
    loads[i] = s.stats.wallLoad.now;
    std::printf("[ measured ] coupled, penalties x%g: sustained wall load %.5f mN, fastest node %.3g mm/s, wall's "
                "total normal force / (weight less upthrust) %.3f, %ld steps in substeps since the laid state\n",
                factor, loads[i] * 1e3, fastestNode(s) * 1e3, wallNormalTotal(s).z() / weight, s.substepped);
    EXPECT_LT(fastestNode(s), 1e-3) << "x" << factor << ": not at rest, the load would be a transient's";
  }
  for (int i = 1; i < kFactors; ++i)
    EXPECT_LT(std::abs(loads[i] - loads[i - 1]), 0.1 * loads[i]) << "x" << (1 << (i - 1)) << " to x" << (1 << i);
  std::printf("[ measured ] coupled: deepest coil-coil overlap %.3f um (%.2f %% of d), wire past the wall's faces %.2f um\n",
              deepest.pair * 1e6, 100 * deepest.pair / (2 * kWireRadius), deepest.wall * 1e6);
  EXPECT_LE(deepest.pair, 0.1 * 2 * kWireRadius) << "coil-coil interpenetration beyond 10 % of the wire diameter";
  EXPECT_LE(deepest.wall, 0.0) << "the wire passed the wall's faces";
}

// The wall's reported force on the same packing against Newton's second
// law: the wall, gravity and upthrust are the only external forces of
// weight (drag and mass damping act on the packing's slow creep, 1e-4 of
// it), and with frictionless coil-coil contacts the pairs' forces are
// equal and opposite (their friction is still lumped, each side's own,
// which is not: with it the wall carries 0.93 of the weight,
// docs/contact.md). So at every step the wall's reported total normal
// force less the weight less upthrust is the packing's momentum change
// over the step, sum m dv / h. The coupled step reports the force its
// solve applied (physics/pair_contact_set.h), and a wall node the solve
// held but found pulling is let go and the step taken again: reported
// clamped at 0 instead, 90 such nodes made the wall seem to carry 1.75
// times the weight.
TEST(DensePacking, TheCoupledWallForceIsTheMomentumBalanceOfAFrictionlessPacking) {
  ModelDef def = packedSac(true);
  def.damping.massCoeff = 20;
  def.coupledPairs = true;
  for (EffectUse& e : def.effects) {
    if (e.name() == "wall_contact") e.set("rigid", 0.0);
    if (e.name() == "self_contact" || e.name() == "rod_contact")
      e.set("friction_static", 0.0), e.set("friction_dynamic", 0.0);
  }
  const Model model = compileModel(def);
  const double weight = netWeight(def);
  State s = makeState(model);
  double worst = 0;
  int checked = 0;
  for (int k = 1; k <= 600; ++k) {
    std::vector<std::vector<Vec3>> before;
    for (const RodState& r : s.rods) before.push_back(r.v);
    ASSERT_TRUE(step(model, s).ok()) << "step " << k;
    if (k <= 100) continue;  // the laid packing's first drop onto the wall
    double change = 0;
    for (size_t j = 0; j < s.rods.size(); ++j)
      for (int i = 0; i < s.rods[j].activeNodes; ++i)
        change += s.rods[j].nodes[size_t(i)].mass * (s.rods[j].v[size_t(i)] - before[j][size_t(i)]).z() / model.timeStep;
    worst = std::max(worst, std::abs(wallNormalTotal(s).z() - weight - change));
    ++checked;
  }
  std::printf("[ measured ] frictionless pairs, coupled: |wall's total normal force - weight less upthrust - momentum "
              "change / h| at most %.4f mN over %d steps (%.2f %% of the weight less upthrust, %.4f mN)\n",
              worst * 1e3, checked, 100 * worst / weight, weight * 1e3);
  EXPECT_LT(worst, 0.02 * weight);
}

}  // namespace
}  // namespace coilsim
