// Large deflection of an end-loaded cantilever (static solver, src/physics/statics.cpp,
// on the co-rotational beam, src/physics/beam.cpp) against the elastica.
// References:
//  - the elastica ODE theta'' = -(P L^2/EI) cos(theta) solved independently
//    in tests/support/elastica.h (shooting + RK4);
//  - Mattiasson, K. (1981), "Numerical results from large deflection beam and
//    frame problems analysed by means of elliptic integrals", Int. J. Numer.
//    Meth. Eng. 17:145-153, table 1 (tip values u/L, w/L for PL^2/EI = 1, 2,
//    5, 10; the values below were checked against two independent
//    transcriptions of that table);
//  - the first integral of the elastica, (theta')^2 / 2 = alpha (sin theta_L -
//    sin theta), which at the root gives sin(theta_L) = alpha (x_tip / L)^2 / 2
//    (Bisshopp & Drucker 1945, Q. Appl. Math. 3:272, eq. 4).
#include <gtest/gtest.h>

#include <cmath>

#include "support/elastica.h"
#include "support/known_bugs.h"
#include "support/rod_models.h"
#include "support/tolerance.h"

namespace coilsim::test {
namespace {

struct MattiassonRow {
  double alpha, horizontal, vertical;  // PL^2/EI, u/L, w/L
};
constexpr MattiassonRow kMattiasson[] = {
    {1.0, 0.05643, 0.30172},
    {2.0, 0.16064, 0.49346},
    {5.0, 0.38763, 0.71379},
    {10.0, 0.55500, 0.81061},
};
// The table gives five decimals: half a unit in the last place.
const Tolerance kTableRounding{5e-6 + 1e-9, "Mattiasson's table is rounded to 5 decimals"};

TEST(ElasticaReference, ShootingSolutionReproducesMattiassonTable) {
  for (const MattiassonRow& row : kMattiasson) {
    const ElasticaTip tip = solveElastica(row.alpha);
    const std::string tag = "RK4 elastica PL^2/EI=" + std::to_string(int(row.alpha));
    EXPECT_TRUE(nearAbs(tag + " u/L vs Mattiasson", tip.horizontal, row.horizontal, kTableRounding));
    EXPECT_TRUE(nearAbs(tag + " w/L vs Mattiasson", tip.vertical, row.vertical, kTableRounding));
    // First integral: an identity of the exact solution, so it checks the
    // RK4 march and the shooting, not the table. RK4 with 2000 steps has a
    // truncation error ~1e-13; the bisection stops at 1e-15 alpha.
    const double x = 1.0 - tip.horizontal;
    EXPECT_TRUE(nearAbs(tag + " first integral", std::sin(tip.rotation), row.alpha * x * x / 2,
                        {1e-10, "RK4 truncation (h = 5e-4, error ~ h^4) and bisection"}));
    EXPECT_TRUE(nearAbs(tag + " root curvature = alpha x_tip", tip.rootCurvature, row.alpha * x,
                        {1e-10, "moment balance at the root, same numerical error"}));
  }
}

// Unit elastica rod: L = 1, EI = 1, Euler-Bernoulli (the elastica has no
// shear), EA L^2 / EI = 1e6 (a round wire with L / r = 500): the axial strain
// P / EA <= 1e-5 stays well below the tolerances (the elastica is inextensible).
RodDef elasticaRod(int beams) {
  const Material m{1.0, 1.0 / 2.6, 1.0};
  const Section s = customSection(1e6, 1.0, 1.0, 2.0, 0.0, 1e-3);
  return clamped(straightRod(1.0, beams, m, s));
}

struct FeTip {
  double horizontal, vertical, rotation;
};

FeTip solveFe(double alpha, int beams) {
  RodDef r = elasticaRod(beams);
  r.loads.push_back({beams, Vec3(0, 0, -alpha), Vec3::Zero()});  // P = alpha EI / L^2
  const Model m = compileModel(modelOf({r}));
  State s = makeState(m);
  const StaticReport rep = solveStatic(m, s, tightStatic(int(2 * alpha) + 2));
  EXPECT_TRUE(rep.converged()) << "alpha " << alpha << ": " << rep.message();
  const Vec3 x = s.rods[0].x[beams], t = tangentOf(s.rods[0].q[beams]);
  return {1.0 - x.x(), -x.z(), std::atan2(-t.z(), t.x())};
}

// 32 beams. A co-rotational chain of exact linear elements is second order
// in the rotation per element theta_e (its chord differs from the arc by
// theta_e^2 / 24 of its length); the largest is theta_e = kappa_max L / n =
// alpha x_tip / n (0.03 rad for alpha = 1, 0.14 for alpha = 10). The bound
// theta_e^2 / 12 allows an error constant twice that of the chord defect.
constexpr int kBeams = 32;
Tolerance discretisation(double alpha, double xTip) {
  const double thetaE = alpha * xTip / kBeams;
  return {thetaE * thetaE / 12, "second order in the rotation per element: theta_e^2 / 12"};
}

TEST(ElasticaTest, EndLoadedCantileverMatchesShootingSolution) {
  SKIP_IF_OPEN(kElementMomentImbalance);
  SKIP_IF_OPEN(kStaticTangentLacksGeometricStiffness);
  for (const double alpha : {1.0, 2.0, 5.0, 10.0}) {
    const ElasticaTip ref = solveElastica(alpha);
    const FeTip fe = solveFe(alpha, kBeams);
    const Tolerance tol = discretisation(alpha, 1.0 - ref.horizontal);
    const std::string tag = "PL^2/EI=" + std::to_string(int(alpha)) + " n=32";
    EXPECT_TRUE(nearAbs(tag + " u/L vs RK4", fe.horizontal, ref.horizontal, tol));
    EXPECT_TRUE(nearAbs(tag + " w/L vs RK4", fe.vertical, ref.vertical, tol));
    EXPECT_TRUE(nearAbs(tag + " tip rotation vs RK4 (rad)", fe.rotation, ref.rotation, tol));
  }
}

TEST(ElasticaTest, EndLoadedCantileverMatchesMattiassonTable) {
  SKIP_IF_OPEN(kElementMomentImbalance);
  SKIP_IF_OPEN(kStaticTangentLacksGeometricStiffness);
  for (const MattiassonRow& row : kMattiasson) {
    const FeTip fe = solveFe(row.alpha, kBeams);
    const Tolerance tol{discretisation(row.alpha, 1.0 - row.horizontal).bound + kTableRounding.bound,
                        "theta_e^2 / 12 discretisation plus table rounding"};
    const std::string tag = "PL^2/EI=" + std::to_string(int(row.alpha)) + " n=32";
    EXPECT_TRUE(nearAbs(tag + " u/L vs Mattiasson", fe.horizontal, row.horizontal, tol));
    EXPECT_TRUE(nearAbs(tag + " w/L vs Mattiasson", fe.vertical, row.vertical, tol));
  }
}

}  // namespace
}  // namespace coilsim::test
