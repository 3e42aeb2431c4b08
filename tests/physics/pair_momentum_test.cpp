// Newton's third law for the coupled pair solve (Model::coupledPairs,
// physics/pair_coupling.h). Reference: conservation of linear momentum. A
// free coil with nothing outside it (no gravity, no drag, no wall, no
// Rayleigh damping) whose loops start pressed into one another (pitch 0.9
// wire diameters) has only internal forces: the beams' (translation
// invariant) and the self contacts', equal and opposite on the two sides of
// each pair. The coupled step's rows move only the two sides' relative
// motion, so sum m v must stay where it started (at zero) to rounding.
// Frictionless: friction stays lumped (each side held against the other's
// start), which is not a pair of equal and opposite forces.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "physics/integrator.h"
#include "physics/rest_shape.h"
#include "support/rod_models.h"

namespace coilsim {
namespace {

constexpr double kWire = 0.127e-3, kLength = 20e-3;
constexpr int kBeams = 40;

struct Drift {
  double momentum = 0;  // largest |sum m v| over the run, kg m/s
  double scale = 0;     // largest sum m |v| over the run, kg m/s (the motion the contacts made)
  int contacts = 0;     // self contacts at the first step
};

Drift pressedLoops(bool coupled, int newtonIterations) {
  RodDef rod = test::rodWithRest(makeHelix(kLength, kBeams, 2e-3, 0.9 * 2 * kWire, true), kLength, kBeams,
                                 test::platinum(), circularSection(kWire, test::kPlatinumPoisson));
  ModelDef def = test::modelOf({rod}, {"self_contact"});
  def.coupledPairs = coupled;
  def.newtonIterations = newtonIterations;
  for (EffectUse& e : def.effects) e.set("friction_static", 0.0), e.set("friction_dynamic", 0.0);
  const Model model = compileModel(def);
  State s = makeState(model);
  Drift d;
  for (int k = 0; k < 200; ++k) {
    const StepReport r = step(model, s);
    EXPECT_TRUE(r.ok()) << "step " << k;
    if (!r.ok()) break;
    if (k == 0) d.contacts = int(s.rods[0].contact.self.size());
    const RodState& rs = s.rods[0];
    Vec3 p = Vec3::Zero();
    double scale = 0;
    for (int i = 0; i < rs.activeNodes; ++i) {
      p += rs.nodes[size_t(i)].mass * rs.v[size_t(i)];
      scale += rs.nodes[size_t(i)].mass * rs.v[size_t(i)].norm();
    }
    d.momentum = std::max(d.momentum, p.norm());
    d.scale = std::max(d.scale, scale);
  }
  return d;
}

TEST(PairMomentum, TheCoupledStepKeepsAFreeCoilsMomentumThroughItsSelfContacts) {
  for (const int iterations : {1, 3}) {
    SCOPED_TRACE(iterations);
    const Drift coupled = pressedLoops(true, iterations), lumped = pressedLoops(false, iterations);
    std::printf("[ measured ] %d Newton iteration(s): |sum m v| / sum m |v| = %.2e coupled, %.2e lumped "
                "(%d self contacts at the start)\n",
                iterations, coupled.momentum / coupled.scale, lumped.momentum / lumped.scale, coupled.contacts);
    ASSERT_GT(coupled.contacts, 20);   // the loops do press on one another
    ASSERT_GT(coupled.scale, 1e-12);   // and they move
    EXPECT_LT(coupled.momentum, 1e-9 * coupled.scale);
  }
}

}  // namespace
}  // namespace coilsim
