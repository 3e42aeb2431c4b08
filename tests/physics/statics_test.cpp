// Tests of the static solver (src/physics/statics.cpp).
// References:
//  - a tip moment M = 2 pi EI / L bends an inextensible rod into a closed
//    circle (Euler-Bernoulli: constant curvature M / EI = 2 pi / L): the tip
//    returns to the base with the base's frame, and the point at mid-length
//    sits at the diameter L / pi (e.g. Crisfield, Non-linear Finite Element
//    Analysis of Solids and Structures 2, sec. 17.9, the "roll-up" test);
//  - static equilibrium is the rest point of damped dynamics: a long,
//    critically damped run of the time stepper (a different code path,
//    src/physics/dynamics.cpp) must settle on the Newton solution.
#include <gtest/gtest.h>

#include <cmath>

#include "support/rod_models.h"
#include "support/tolerance.h"

namespace coilsim::test {
namespace {

TEST(StaticsTest, TipMomentTwoPiEIOverLRollsTheRodIntoACircle) {
  const double length = 0.1;
  const int beams = 64;
  const Section s = circularSection(1e-3, kSteelPoisson);
  const double ei = steel().youngModulus * s.iy;
  RodDef r = clamped(straightRod(length, beams, steel(), s));
  r.loads.push_back({beams, Vec3::Zero(), Vec3(0, 2 * M_PI * ei / length, 0)});
  const Model m = compileModel(modelOf({r}));
  State st = makeState(m);
  const StaticReport rep = solveStatic(m, st, tightStatic(32));
  ASSERT_TRUE(rep.converged()) << rep.message();
  const RodState& rs = st.rods[0];
  // Closure and frame are exact by the symmetry of the discrete ring (every
  // element carries the same moment); only the Newton stop (1e-13 L, 1e-12
  // rad per update) and round-off over 64 elements remain.
  const Tolerance closure{1e-10, "symmetric ring: Newton stop and round-off over 64 elements"};
  EXPECT_TRUE(small("tip distance to the base / L", (rs.x[beams] - rs.x[0]).norm() / length, closure));
  EXPECT_TRUE(small("tip frame vs base frame (rad)", rs.q[beams].angularDistance(rs.q[0]), closure));
  // The nodes form a regular 64-gon; its diameter differs from L / pi by a
  // relative O(theta_e^2), theta_e = 2 pi / n = 0.098, with a constant
  // between 1/24 and 1/6 depending on the chord length the element keeps.
  const double thetaE = 2 * M_PI / beams;
  EXPECT_TRUE(nearRel("mid-length point distance vs L/pi", (rs.x[beams / 2] - rs.x[0]).norm(), length / M_PI,
                      {thetaE * thetaE / 4, "regular n-gon vs circle: O(theta_e^2), constant <= 1/6"}));
  // The circle stays in the x-z plane and bends towards -z.
  double offPlane = 0;
  for (const Vec3& x : rs.x) offPlane = std::max(offPlane, std::abs(x.y()));
  EXPECT_TRUE(small("largest out-of-plane coordinate / L", offPlane / length, closure));
  EXPECT_LT(rs.x[beams / 2].z(), -0.9 * length / M_PI);
}

TEST(StaticsTest, DampedDynamicsSettlesOnTheStaticSolution) {
  // A steel wire sagging under gravity (w L^3 / EI = 1.2: a 15 % sag, well
  // into the geometrically nonlinear range).
  const double length = 0.2;
  const int beams = 20;
  ModelDef d = modelOf({clamped(straightRod(length, beams, steel(), circularSection(1e-4, kSteelPoisson)))},
                       {"gravity"}, Vec3(0, 0, -9.81));
  // Mass-proportional damping a makes every underdamped mode decay like
  // exp(-a t / 2); a = 30 1/s (first mode 22 rad/s, damping ratio 0.7) and
  // 3 s give exp(-45): the transient is gone to round-off.
  d.damping.massCoeff = 30;
  d.timeStep = 2e-3;
  const Model m = compileModel(d);
  State stat = makeState(m), dyn = makeState(m);
  const StaticReport rep = solveStatic(m, stat, tightStatic(4));
  ASSERT_TRUE(rep.converged()) << rep.message();
  ASSERT_TRUE(run(m, dyn, 1500));
  double worst = 0;
  for (int i = 0; i <= beams; ++i) worst = std::max(worst, (dyn.rods[0].x[i] - stat.rods[0].x[i]).norm());
  const double sag = -stat.rods[0].x[beams].z();
  EXPECT_GT(sag, 0.1 * length);
  EXPECT_TRUE(small("settled dynamics vs static shape / sag", worst / sag,
                    {1e-9, "exp(-45) transient; both fixed points of the same forces, to round-off"}));
}

TEST(StaticsTest, RefusesARodWithoutConstraintAndKeepsTheState) {
  const Model m = compileModel(modelOf({straightRod(0.1, 4, steel(), circularSection(1e-3, kSteelPoisson))},
                                       {"gravity"}, Vec3(0, 0, -9.81)));
  State s = makeState(m);
  const std::vector<Vec3> before = s.rods[0].x;
  const StaticReport rep = solveStatic(m, s);
  EXPECT_FALSE(rep.converged());
  EXPECT_NE(rep.message().find("constraint"), std::string::npos) << rep.message();
  EXPECT_EQ(s.rods[0].x, before);
}

TEST(StaticsTest, ARefusedSolveLeavesEveryRodAsItWas) {
  // A clamped wire that gravity would bend, moving, beside a free one: the
  // free rod makes the model unsolvable, so nothing may change, not even the
  // clamped rod listed first (its poses and its velocities).
  const Section s = circularSection(1e-3, kSteelPoisson);
  RodDef held = clamped(straightRod(0.1, 4, steel(), s));
  RodDef loose = straightRod(0.1, 4, steel(), s);
  loose.name = "loose";
  const Model m = compileModel(modelOf({held, loose}, {"gravity"}, Vec3(0, 0, -9.81)));
  State st = makeState(m);
  for (Vec3& v : st.rods[0].v) v = Vec3(0, 0, -0.01);
  const State before = st;
  const StaticReport rep = solveStatic(m, st);
  EXPECT_FALSE(rep.converged());
  EXPECT_NE(rep.message().find("'loose'"), std::string::npos) << rep.message();
  for (size_t k = 0; k < st.rods.size(); ++k) {
    EXPECT_EQ(st.rods[k].x, before.rods[k].x) << "rod " << k;
    EXPECT_EQ(st.rods[k].v, before.rods[k].v) << "rod " << k;
    for (size_t i = 0; i < st.rods[k].q.size(); ++i)
      EXPECT_EQ(st.rods[k].q[i].coeffs(), before.rods[k].q[i].coeffs()) << "rod " << k << " node " << i;
  }
}

TEST(StaticsTest, ANewtonFailureKeepsTheLastConvergedIncrementAndSaysWhich) {
  // The sagging wire of the test above (w L^3 / EI = 1.2) allowed one Newton
  // iteration and no bisection: the first increment (the full load) cannot
  // converge from the straight rod, so the last converged increment is load
  // factor 0, the unloaded clamped rod at rest, at rest.
  const double length = 0.2;
  const int beams = 20;
  const Model m = compileModel(modelOf({clamped(straightRod(length, beams, steel(), circularSection(1e-4, kSteelPoisson)))},
                                       {"gravity"}, Vec3(0, 0, -9.81)));
  State st = makeState(m);
  const std::vector<Vec3> rest = st.rods[0].x;
  for (Vec3& v : st.rods[0].v) v = Vec3(0, 0, -0.01);
  StaticOptions o;
  o.loadSteps = 1;
  o.maxIterations = 1;
  o.maxBisections = 0;
  const StaticReport rep = solveStatic(m, st, o);
  EXPECT_FALSE(rep.converged());
  EXPECT_EQ(rep.loadFactor, 0.0);
  EXPECT_NE(rep.message().find("left at load factor 0"), std::string::npos) << rep.message();
  EXPECT_EQ(st.rods[0].x, rest);
  for (const Vec3& v : st.rods[0].v) EXPECT_EQ(v, Vec3::Zero());
}

TEST(StaticsTest, AConvergedSolveReportsTheFullLoad) {
  const Model m = compileModel(modelOf({clamped(straightRod(0.2, 20, steel(), circularSection(1e-4, kSteelPoisson)))},
                                       {"gravity"}, Vec3(0, 0, -9.81)));
  State st = makeState(m);
  const StaticReport rep = solveStatic(m, st, tightStatic(4));
  ASSERT_TRUE(rep.converged()) << rep.message();
  EXPECT_EQ(rep.loadFactor, 1.0);
}

}  // namespace
}  // namespace coilsim::test
