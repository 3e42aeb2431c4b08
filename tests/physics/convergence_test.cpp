// Mesh convergence of the beam chain (src/physics/beam.cpp, model.cpp lumping).
// References:
//  - cantilever under its own weight w: tip deflection w L^4 / 8EI plus the
//    shear term w L^2 / (2 kappa G A) (Timoshenko & Gere, Mechanics of
//    Materials, appendix G; Timoshenko, Strength of Materials I, sec. 39);
//  - expected order 2, with a known constant: the element is nodally exact
//    under its consistent load (forces w h / 2 and moments +-w h^2 / 12 per
//    element: Przemieniecki, Theory of Matrix Structural Analysis, sec. 5.6);
//    lumping the weight as forces only drops the moments, which cancel between
//    neighbours except for w h^2 / 12 at the free tip. That moment deflects
//    the tip by (w h^2 / 12) L^2 / 2EI, i.e. a relative error of exactly
//    1 / (3 n^2) of the bending deflection (too large, the dropped moment
//    lifts the tip);
//  - large deflection: the elastica solved by RK4 shooting (tests/support/
//    elastica.h); a co-rotational chain of exact linear elements is second
//    order in the element length there too (Crisfield, Non-linear Finite
//    Element Analysis of Solids and Structures 2, sec. 17.2);
//  - large 3D rotation of a curved rod (the 45-degree bend of bend45_test.cpp,
//    out-of-plane load: bending and torsion coupled): second order as well, read
//    off as the Cauchy order log2(|x_n - x_2n| / |x_2n - x_4n|), which needs no
//    exact solution.
#include <gtest/gtest.h>

#include <cmath>

#include "support/bend45.h"
#include "support/elastica.h"
#include "support/known_bugs.h"
#include "support/rod_models.h"
#include "support/tolerance.h"

namespace coilsim::test {
namespace {

const int kMeshes[] = {4, 8, 16, 32};

// Observed order between consecutive meshes (each twice as fine).
double order(double coarseError, double fineError) { return std::log2(std::abs(coarseError / fineError)); }

TEST(ConvergenceTest, SelfWeightSagConvergesAtSecondOrderWithTheLumpingConstant) {
  const double length = 0.1;
  const Section s = circularSection(1e-3, kSteelPoisson);
  // Gravity scaled down 1000 times: w L^3 / EI = 1.5e-6, so geometric
  // nonlinearity (relative ~ 1e-12) cannot blur the 1 / (3 n^2) error.
  const Vec3 g(0, 0, -9.81e-3);
  const double w = steel().density * s.area * -g.z(), ei = steel().youngModulus * s.iy;
  const double bending = w * std::pow(length, 4) / (8 * ei);
  const double shear = w * length * length / (2 * s.shearFactor * steel().shearModulus * s.area);
  std::vector<double> errors;
  for (const int n : kMeshes) {
    const Model m = compileModel(modelOf({clamped(straightRod(length, n, steel(), s))}, {"gravity"}, g));
    State st = makeState(m);
    const StaticReport rep = solveStatic(m, st, tightStatic(1));
    ASSERT_TRUE(rep.converged()) << rep.message();
    errors.push_back((-st.rods[0].x[n].z() - (bending + shear)) / bending);
  }
  for (size_t k = 0; k < errors.size(); ++k) {
    const int n = kMeshes[k];
    // The error is exactly 1 / (3 n^2) up to the 1e-12 nonlinearity, the
    // Newton stop (1e-13 L against a 1e-6 L error at n = 32) and round-off.
    EXPECT_TRUE(nearRel("self-weight tip error * n^2 vs 1/3, n=" + std::to_string(n), errors[k] * n * n, 1.0 / 3.0,
                        {1e-6, "exact nodal values plus the dropped tip moment; Newton stop 1e-7 of the error"}));
    if (k > 0) {
      EXPECT_TRUE(nearAbs("self-weight observed order n=" + std::to_string(kMeshes[k - 1]) + "->" + std::to_string(n),
                          order(errors[k - 1], errors[k]), 2.0, {1e-5, "error exactly 1 / (3 n^2): order 2"}));
    }
  }
}

TEST(ConvergenceTest, LargeDeflectionConvergesAtSecondOrder) {
  SKIP_IF_OPEN(kElementMomentImbalance);
  // Elastica at PL^2/EI = 2 (tip turns 45 degrees), unit rod as in elastica_test
  // (EA L^2 / EI = 1e6: axial strain 2e-6, below the n = 32 error of ~3e-5).
  const double alpha = 2.0;
  const ElasticaTip ref = solveElastica(alpha);
  std::vector<double> errU, errW, errTheta;
  for (const int n : {8, 16, 32}) {
    RodDef r = clamped(straightRod(1.0, n, {1.0, 1.0 / 2.6, 1.0}, customSection(1e6, 1.0, 1.0, 2.0, 0.0, 1e-3)));
    r.loads.push_back({n, Vec3(0, 0, -alpha), Vec3::Zero()});
    const Model m = compileModel(modelOf({r}));
    State st = makeState(m);
    const StaticReport rep = solveStatic(m, st, tightStatic(6));
    ASSERT_TRUE(rep.converged()) << rep.message();
    const Vec3 x = st.rods[0].x[n], t = tangentOf(st.rods[0].q[n]);
    errU.push_back(1.0 - x.x() - ref.horizontal);
    errW.push_back(-x.z() - ref.vertical);
    errTheta.push_back(std::atan2(-t.z(), t.x()) - ref.rotation);
  }
  // Three meshes from n = 8: allow 0.15 for the O(h^2) correction at n = 8.
  const Tolerance tol{0.15, "second order; n = 8 is just in the asymptotic range"};
  for (size_t k = 1; k < errU.size(); ++k) {
    const std::string tag = " observed order, elastica PL^2/EI=2, step " + std::to_string(k);
    EXPECT_TRUE(nearAbs("u/L" + tag, order(errU[k - 1], errU[k]), 2.0, tol));
    EXPECT_TRUE(nearAbs("w/L" + tag, order(errW[k - 1], errW[k]), 2.0, tol));
    EXPECT_TRUE(nearAbs("tip rotation" + tag, order(errTheta[k - 1], errTheta[k]), 2.0, tol));
  }
}

TEST(ConvergenceTest, CurvedRodUnderOutOfPlaneLoadConvergesAtSecondOrder) {
  SKIP_IF_OPEN(kElementRollFromNodeA);
  std::vector<Vec3> tips;
  for (const int n : {16, 32, 64}) {
    const Model m = compileModel(modelOf({bend45Rod(n, 600.0)}));
    State st = makeState(m);
    const StaticReport rep = solveStatic(m, st, tightStatic(20));
    ASSERT_TRUE(rep.converged()) << rep.message();
    tips.push_back(st.rods[0].x[n]);
  }
  // From n = 16 the next term is ~20 % of the leading one (x converges from
  // slightly outside the asymptotic range): allow 0.3 around 2.
  const Tolerance tol{0.3, "second order; n = 16 at the edge of the asymptotic range"};
  const char* axis[] = {"x", "y", "z"};
  for (int c = 0; c < 3; ++c) {
    const double p = order(tips[0][c] - tips[1][c], tips[1][c] - tips[2][c]);
    EXPECT_TRUE(nearAbs(std::string("45-degree bend P=600 tip ") + axis[c] + " Cauchy order n=16,32,64", p, 2.0, tol));
  }
}

}  // namespace
}  // namespace coilsim::test
