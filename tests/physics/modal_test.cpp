// Natural frequencies of a cantilever: the assembled stiffness and lumped mass
// (src/physics/assembly.cpp, model.cpp) and the time stepper (dynamics.cpp).
// References:
//  - clamped-free Euler-Bernoulli beam: cos(bL) cosh(bL) = -1, beta_1 L =
//    1.87510, beta_2 L = 4.69409, omega = (beta L)^2 sqrt(EI / (rho A L^4))
//    (Blevins, Formulas for Natural Frequency and Mode Shape, table 8-1; the
//    roots are re-derived here by bisection); a slender rod (L / r = 1000)
//    keeps shear and rotary inertia corrections below (beta r)^2 ~ 2e-5;
//  - implicit Euler on x'' = -omega^2 x turns the phase by atan(omega h) per
//    step (its amplification matrix has eigenvalues 1 / (1 -+ i omega h)), so
//    a free vibration has the period 2 pi h / atan(omega h) (Hairer & Wanner,
//    Solving ODEs II, sec. IV.2, applied to the linear test equation).
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

#include "support/cantilever_modes.h"
#include "support/rod_models.h"
#include "support/tolerance.h"

namespace coilsim::test {
namespace {

// Steel wire, L = 100 mm, r = 0.1 mm.
constexpr double kLength = 0.1, kRadius = 1e-4;

Model cantilever(int beams) {
  return compileModel(modelOf({clamped(straightRod(kLength, beams, steel(), circularSection(kRadius, kSteelPoisson)))}));
}

double analyticOmega(int mode) {
  const Section s = circularSection(kRadius, kSteelPoisson);
  return cantileverOmega(kCantileverBetaL[mode - 1], kLength, steel().youngModulus * s.iy, steel().density * s.area);
}

// Sorted angular frequencies of the generalised eigenproblem K phi = w^2 M phi
// with the clamped node's six DOFs removed.
Eigen::VectorXd modelFrequencies(int beams) {
  const Model m = cantilever(beams);
  State s = makeState(m);
  assembleAt(m, s);
  const RodModel& rm = m.rods[0];
  const Eigen::MatrixXd kFull = toDense(s.rods[0].work.stiffness);
  const int dofs = 6 * beams;  // nodes 1 .. beams
  const Eigen::MatrixXd k = kFull.bottomRightCorner(dofs, dofs);
  Eigen::MatrixXd mass = Eigen::MatrixXd::Zero(dofs, dofs);
  for (int i = 1; i <= beams; ++i) {
    mass.block<3, 3>(6 * (i - 1), 6 * (i - 1)) = rm.nodeMass[i] * Mat3::Identity();
    mass.block<3, 3>(6 * (i - 1) + 3, 6 * (i - 1) + 3) = globalInertia(rm, s.rods[0].q[i], i);
  }
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> es(k, mass, Eigen::EigenvaluesOnly);
  Eigen::VectorXd w = es.eigenvalues().cwiseMax(0.0).cwiseSqrt();
  std::sort(w.data(), w.data() + w.size());
  return w;
}

TEST(ModalReference, FrequencyEquationRootsMatchPublishedBetaL) {
  for (int k = 1; k <= 2; ++k)
    EXPECT_TRUE(nearAbs("root " + std::to_string(k) + " of cos x cosh x = -1", cantileverRoot(k),
                        kCantileverBetaL[k - 1], {5e-9, "Blevins quotes 9 significant digits"}));
}

// Lumped mass converges at second order in the element length (the exact
// element stiffness leaves the lumping as the only error), so the observed
// order between meshes n, 2n is 2 and Richardson extrapolation (4 w_2n -
// w_n) / 3 removes the leading error. What remains: an O((beta h)^4)
// remainder, and the physics the Euler-Bernoulli formula leaves out: shear and
// rotary inertia lower omega_k by ~(beta_k r_g)^2 (1 + E / kappa G) / 2
// (Timoshenko beam, e.g. Rao sec. 11.6), r_g = r / 2 the radius of gyration:
// 2e-6 for mode 1, 1.1e-5 for mode 2.
double richardson(double coarse, double fine) { return (4 * fine - coarse) / 3; }
Tolerance extrapolated(int mode, int coarseBeams) {
  const Section s = circularSection(kRadius, kSteelPoisson);
  const double beta = kCantileverBetaL[mode - 1] / kLength, rg = kRadius / 2;
  const double physics = 0.5 * beta * beta * rg * rg * (1 + steel().youngModulus / (s.shearFactor * steel().shearModulus));
  const double bh = kCantileverBetaL[mode - 1] / coarseBeams;
  return {2 * physics + std::pow(bh, 4) / 100,
          "shear and rotary inertia (estimate x2) plus an O((beta h)^4) remainder, (beta h)^4 / 100"};
}
const Tolerance kSecondOrder{0.05, "lumped mass: second order; next term O(h^2) relative, 2 % at n = 10"};

// Relative round-off of eigenvalue lambda when the spectrum reaches lambda_max
// (the rotational DOFs of tiny rotary inertia): eps lambda_max / lambda.
Tolerance eigenRoundoff(const Eigen::VectorXd& w, int k) {
  const double ratio = (w.maxCoeff() / w[k]) * (w.maxCoeff() / w[k]);
  return roundoff(ratio, 10, "generalised eigensolver: eps lambda_max / lambda");
}

TEST(ModalTest, FirstTwoFrequenciesConvergeToTheCantileverFormula) {
  const int meshes[] = {10, 20, 40};
  std::vector<Eigen::VectorXd> w;
  for (const int beams : meshes) {
    w.push_back(modelFrequencies(beams));
    const std::string tag = " n=" + std::to_string(beams);
    // Circular section: each bending mode appears twice (y and z bending).
    EXPECT_TRUE(nearRel("mode 1 y/z pair" + tag, w.back()[1], w.back()[0], eigenRoundoff(w.back(), 0)));
    EXPECT_TRUE(nearRel("mode 2 y/z pair" + tag, w.back()[3], w.back()[2], eigenRoundoff(w.back(), 2)));
  }
  for (const int mode : {1, 2}) {
    const int idx = 2 * (mode - 1);
    const double exact = analyticOmega(mode);
    for (int k = 1; k < 3; ++k) {
      const std::string tag = "omega_" + std::to_string(mode) + " n=" + std::to_string(meshes[k - 1]) + "->" +
                              std::to_string(meshes[k]);
      const double order = std::log2((w[k - 1][idx] - exact) / (w[k][idx] - exact));
      EXPECT_TRUE(nearAbs(tag + " observed order", order, 2.0, kSecondOrder));
      EXPECT_TRUE(nearRel(tag + " Richardson vs (beta L)^2 sqrt(EI/rho A L^4)", richardson(w[k - 1][idx], w[k][idx]),
                          exact, extrapolated(mode, meshes[k - 1])));
    }
  }
}

// First-mode angular frequency of the model read off a free vibration: the
// period between upward zero crossings of the tip, corrected for implicit
// Euler's own phase error (omega = tan(2 pi h / T) / h inverts T = 2 pi h /
// atan(omega h)).
double timeSteppedOmega(int beams) {
  ModelDef d = modelOf({clamped(straightRod(kLength, beams, steel(), circularSection(kRadius, kSteelPoisson)))});
  const double h = 2 * M_PI / analyticOmega(1) / 400;  // 400 steps per period
  d.timeStep = h;
  const Model m = compileModel(d);
  State s = makeState(m);
  // Start at rest in the analytic first mode, tip amplitude 1e-4 L (linear).
  const ModeShape mode(kCantileverBetaL[0], kLength);
  const double scale = 1e-4 * kLength / mode.value(kLength);
  for (int i = 0; i <= beams; ++i) {
    const double x = kLength * i / beams;
    s.rods[0].x[i].z() = scale * mode.value(x);
    s.rods[0].q[i] = quatExp(Vec3(0, -scale * mode.slope(x), 0));  // tangent (1, 0, w')
  }
  std::vector<double> ups;
  double prev = s.rods[0].x[beams].z();
  for (int k = 0; k < 400 * 4 + 10; ++k) {
    EXPECT_TRUE(step(m, s).ok());
    const double z = s.rods[0].x[beams].z();
    if (prev < 0 && z >= 0) ups.push_back(s.time - h * z / (z - prev));  // linear interpolation
    prev = z;
  }
  EXPECT_GE(ups.size(), 3u);
  const double period = (ups.back() - ups.front()) / double(ups.size() - 1);
  return std::tan(2 * M_PI * h / period) / h;
}

TEST(ModalTest, FreeVibrationHasTheFirstModeFrequency) {
  const double coarse = timeSteppedOmega(20), fine = timeSteppedOmega(40);
  const double exact = analyticOmega(1);
  EXPECT_TRUE(nearAbs("time-stepped omega_1 observed order n=20->40", std::log2((coarse - exact) / (fine - exact)), 2.0,
                      kSecondOrder));
  // Besides the eigenvalue bound: crossings interpolated linearly at 400
  // steps per period (~1e-6) and leakage of higher discrete modes, which the
  // analytic start shape excites at O(h^2) amplitude and implicit Euler damps.
  const Tolerance tol{extrapolated(1, 20).bound + 1e-5, "eigenvalue bound plus crossing interpolation and leakage"};
  EXPECT_TRUE(nearRel("time-stepped omega_1, Richardson n=20,40, vs formula", richardson(coarse, fine), exact, tol));
}

}  // namespace
}  // namespace coilsim::test
