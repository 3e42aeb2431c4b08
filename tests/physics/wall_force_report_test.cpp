// The wall forces reported per node (RodContacts::wallForce) by a step that
// solves its pair contacts coupled, against Newton's laws: three free wires
// stacked on a floor (two along y on the floor, one laid across them).
// Nothing but the floor and gravity acts on the stack from outside (no
// upthrust, no drag, frictionless), and the wires' forces on one another
// are internal, so
// - dropped with no gravity and no damping, in every step the floor's
//   reported force equals the stack's momentum change over the step,
//   sum m dv / h;
// - at rest under gravity the floor carries the stack's weight, sum m g.
// The coupled step holds a node that closes on the wall by its stiffness
// before it penetrates (physics/pair_contact_set.h), so detection's penalty
// at the step's start misses what stopped it: the force its solve applied
// is reported (reportSolvedWallForces). The lumped solve's figures
// (detection's penalty) are printed beside.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "physics/contact/detect.h"
#include "physics/integrator.h"
#include "physics/rest_shape.h"
#include "support/meshes.h"
#include "support/rod_models.h"

namespace coilsim {
namespace {

constexpr double kWire = 0.127e-3;  // wire radius, m

RodDef wire(const char* name, const Vec3& start, const Vec3& along, double length, int beams) {
  return test::platinumWire(name, start, along, length, beams, kWire);
}

// The stack with the lower wires `above` their touching height over the
// floor z = 0, the laid one touching them to within 0.5 um.
ModelDef stack(double above, bool coupled, bool gravity) {
  const double lower = (1 + kWallSkin) * kWire + above, laid = lower + 2 * kWire + 0.5e-6;
  std::vector<RodDef> rods = {wire("lower-left", Vec3(-3e-3, -5e-3, lower), Vec3::UnitY(), 10e-3, 20),
                              wire("lower-right", Vec3(3e-3, -5e-3, lower), Vec3::UnitY(), 10e-3, 20),
                              wire("laid", Vec3(-6e-3, 0, laid), Vec3::UnitX(), 12e-3, 48)};
  ModelDef def = gravity ? test::modelOf(rods, {"gravity", "rod_contact", "wall_contact"}, Vec3(0, 0, -9.81))
                         : test::modelOf(rods, {"rod_contact", "wall_contact"});
  def.coupledPairs = coupled;
  for (EffectUse& e : def.effects)
    if (e.name() == "rod_contact" || e.name() == "wall_contact")
      e.set("friction_static", 0.0), e.set("friction_dynamic", 0.0);
  def.obstacles.push_back(test::obstacleOf(test::plane(Vec3::Zero(), -Vec3::UnitZ(), 8e-3, 8), 0.0));
  return def;
}

// The floor's reported force on the stack, N (along +z: the floor's normal).
double floorForce(const State& s) {
  double f = 0;
  for (const RodState& r : s.rods)
    for (int i = 0; i < r.activeNodes && size_t(i) < r.contact.wallForce.size(); ++i) f += r.contact.wallForce[size_t(i)];
  return f;
}

struct Impact {
  double worst = 0;  // largest |reported - momentum change / h| over the steps, N
  double peak = 0;   // largest momentum change / h, N
  int steps = 0;
};

Impact dropped(bool coupled) {
  const Model model = compileModel(stack(20e-6, coupled, false));
  State s = makeState(model);
  for (RodState& r : s.rods)
    for (Vec3& v : r.v) v = Vec3(0, 0, -0.05);  // 50 mm/s, 20 um above the floor
  Impact out;
  for (int k = 0; k < 60; ++k) {
    std::vector<std::vector<Vec3>> before;
    for (const RodState& r : s.rods) before.push_back(r.v);
    const StepReport r = step(model, s);
    EXPECT_TRUE(r.ok()) << "step " << k;
    if (!r.ok()) break;
    double change = 0;
    for (size_t j = 0; j < s.rods.size(); ++j)
      for (int i = 0; i < s.rods[j].activeNodes; ++i)
        change += s.rods[j].nodes[size_t(i)].mass * (s.rods[j].v[size_t(i)] - before[j][size_t(i)]).z() / model.timeStep;
    out.worst = std::max(out.worst, std::abs(floorForce(s) - change));
    out.peak = std::max(out.peak, std::abs(change));
    ++out.steps;
  }
  return out;
}

TEST(WallForceReport, TheFloorsForceIsTheMomentumChangeOfADroppedStack) {
  const Impact lumped = dropped(false), coupled = dropped(true);
  std::printf("[ measured ] largest momentum change / h %.3f mN; reported minus it, worst step: %.3e mN coupled "
              "(%.1e of the peak), %.3f mN lumped\n",
              coupled.peak * 1e3, coupled.worst * 1e3, coupled.worst / coupled.peak, lumped.worst * 1e3);
  ASSERT_EQ(coupled.steps, 60);
  ASSERT_GT(coupled.peak, 1e-4);  // the stack was stopped (0.1 mN and more)
  EXPECT_LT(coupled.worst, 1e-3 * coupled.peak);
}

TEST(WallForceReport, AStackAtRestOnTheFloorReportsItsWeight) {
  for (const bool coupled : {false, true}) {
    SCOPED_TRACE(coupled ? "coupled" : "lumped");
    ModelDef def = stack(0.5e-6, coupled, true);
    def.damping.massCoeff = 20;
    const Model model = compileModel(def);
    State s = makeState(model);
    ASSERT_TRUE(test::run(model, s, 1500)) << "a step was refused";
    double weight = 0, fastest = 0;
    for (const RodState& r : s.rods)
      for (int i = 0; i < r.activeNodes; ++i) {
        weight += r.nodes[size_t(i)].mass * 9.81;
        fastest = std::max(fastest, r.v[size_t(i)].norm());
      }
    std::printf("[ measured ] %s: the floor reports %.5f uN against the weight %.5f uN, fastest node %.2e mm/s\n",
                coupled ? "coupled" : "lumped", floorForce(s) * 1e6, weight * 1e6, fastest * 1e3);
    ASSERT_LT(fastest, 1e-4);  // at rest (0.1 mm/s)
    EXPECT_NEAR(floorForce(s), weight, 0.01 * weight);
  }
}

}  // namespace
}  // namespace coilsim
