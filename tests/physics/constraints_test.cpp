// Tests of constraints (Constraint in src/physics/model.h; how dynamics.cpp
// and statics.cpp hold DOFs).
// References:
//  - beams under a central load P (Euler-Bernoulli; Timoshenko & Gere,
//    Mechanics of Materials, appendix G; Roark's Formulas for Stress and
//    Strain, table 8.1): pinned-pinned mid deflection P L^3 / 48EI, end slope
//    P L^2 / 16EI; clamped-clamped P L^3 / 192EI, end slope 0;
//    clamped-pinned (propped) 7 P L^3 / 768EI;
//  - a rod pinned at one end swings as a compound pendulum, omega^2 =
//    m g d / I_pin; for n equal beams lumped at the nodes, d = L / 2 exactly
//    and I_pin = rho A L^3 (1/3 + 1/(6 n^2)) (sum of i^2 over the nodes), so
//    omega^2 = (3 g / 2 L) / (1 + 1 / (2 n^2));
//  - a prescribed rigid motion of the clamp moves a stress-free rod rigidly:
//    positions x0' + R (x - x0), frames R q, zero strain energy.
#include <gtest/gtest.h>

#include <cmath>

#include "support/rod_models.h"
#include "support/tolerance.h"

namespace coilsim::test {
namespace {

constexpr double kLength = 0.1, kRadius = 1e-3;
constexpr int kBeams = 20, kMid = kBeams / 2;
constexpr unsigned kTwist = 1u << 3;  // rotation about global x: the rod's axis

// Euler-Bernoulli section (shear off) so the textbook formulas hold exactly;
// the element is then nodally exact for point loads.
Section ebSection() {
  Section s = circularSection(kRadius, kSteelPoisson);
  s.shearFactor = 0;
  return s;
}

// P L^2 / EI = 1e-4: geometric nonlinearity (and the membrane tension of
// axially held ends, ~(deflection / r)^2 = 4e-8) stay below 1e-6.
const Tolerance kSmall{1e-6, "nodally exact elements; nonlinearity < 1e-7"};

struct Supported {
  double mid, slope0;  // mid-span deflection (down), rotation of node 0 (rad)
};

Supported centralLoad(unsigned mask0, unsigned maskN) {
  RodDef r = straightRod(kLength, kBeams, steel(), ebSection());
  r.constraints.push_back({0, mask0});
  r.constraints.push_back({kBeams, maskN});
  const double ei = steel().youngModulus * ebSection().iy;
  r.loads.push_back({kMid, Vec3(0, 0, -1e-4 * ei / (kLength * kLength)), Vec3::Zero()});
  const Model m = compileModel(modelOf({r}));
  State s = makeState(m);
  const StaticReport rep = solveStatic(m, s, tightStatic(1));
  EXPECT_TRUE(rep.converged()) << rep.message();
  return {-s.rods[0].x[kMid].z(), s.rods[0].q[0].angularDistance(Quat::Identity())};
}

TEST(ConstraintsTest, PinnedAndClampedEndsGiveTheTextbookDeflections) {
  const double ei = steel().youngModulus * ebSection().iy;
  const double p = 1e-4 * ei / (kLength * kLength), pl3 = p * std::pow(kLength, 3) / ei;
  // Pinned: translations held, rotation free (plus the twist of one end, which
  // the rod would otherwise be free to spin about).
  const Supported pinned = centralLoad(kTranslation | kTwist, kTranslation);
  EXPECT_TRUE(nearRel("pinned-pinned mid deflection vs PL^3/48EI", pinned.mid, pl3 / 48, kSmall));
  EXPECT_TRUE(nearRel("pinned end rotation vs PL^2/16EI", pinned.slope0, p * kLength * kLength / (16 * ei), kSmall));
  const Supported clampedBoth = centralLoad(kAllDofs, kAllDofs);
  EXPECT_TRUE(nearRel("clamped-clamped mid deflection vs PL^3/192EI", clampedBoth.mid, pl3 / 192, kSmall));
  EXPECT_TRUE(small("clamped end rotation (rad)", clampedBoth.slope0, {0.0, "the clamp sets the frame exactly"}));
  const Supported propped = centralLoad(kAllDofs, kTranslation);
  EXPECT_TRUE(nearRel("clamped-pinned mid deflection vs 7PL^3/768EI", propped.mid, 7 * pl3 / 768, kSmall));
}

TEST(ConstraintsTest, RodPinnedAtOneEndSwingsAsACompoundPendulum) {
  // Hanging along -z from a pin at the origin, turned 0.01 rad about y.
  const double g = 9.81, theta0 = 0.01;
  RodDef r = straightRod(kLength, kBeams, steel(), circularSection(kRadius, kSteelPoisson));
  r.placement.direction = Vec3(0, 0, -1);
  r.placement.normal = Vec3(1, 0, 0);
  r.constraints.push_back({0, kTranslation});
  ModelDef d = modelOf({r}, {"gravity"}, Vec3(0, 0, -g));
  const double omegaRigid = std::sqrt(1.5 * g / kLength / (1 + 1.0 / (2.0 * kBeams * kBeams)));
  d.timeStep = 2 * M_PI / omegaRigid / 400;
  const Model m = compileModel(d);
  State s = makeState(m);
  const Quat tilt(Eigen::AngleAxisd(theta0, Vec3::UnitY()));
  for (int i = 0; i <= kBeams; ++i) {
    s.rods[0].x[i] = tilt * s.rods[0].x[i];
    s.rods[0].q[i] = (tilt * s.rods[0].q[i]).normalized();
  }
  std::vector<double> ups;
  double prev = s.rods[0].x[kBeams].x();
  for (int k = 0; k < 400 * 3 + 10; ++k) {
    ASSERT_TRUE(step(m, s).ok());
    const double x = s.rods[0].x[kBeams].x();
    if (prev < 0 && x >= 0) ups.push_back(s.time - m.timeStep * x / (x - prev));
    prev = x;
  }
  ASSERT_GE(ups.size(), 2u);
  const double period = (ups.back() - ups.front()) / double(ups.size() - 1);
  const double omega = std::tan(2 * M_PI * m.timeStep / period) / m.timeStep;  // undo implicit Euler's phase error
  // Elastic compliance lowers omega by ~(omega / omega_bending)^2 = 2e-4;
  // amplitude theta0^2 / 16 = 6e-6; crossings interpolated at 400 per period.
  EXPECT_TRUE(nearRel("pendulum omega vs sqrt(3g/2L / (1 + 1/2n^2))", omega, omegaRigid,
                      {1e-3, "bending compliance (omega_p / omega_1)^2 = 2e-4, amplitude, interpolation"}));
  EXPECT_TRUE(small("pin position drift", s.rods[0].x[0].norm(), {0.0, "held exactly"}));
}

// Clamp moving with constant velocity and angular velocity.
Model movingClamp(const Vec3& velocity, const Vec3& angular) {
  RodDef r = straightRod(kLength, kBeams, steel(), circularSection(kRadius, kSteelPoisson));
  r.constraints.push_back({0, kAllDofs, velocity, angular});
  return compileModel(modelOf({r}));
}

// Strain energy of a strain of 1e-9 along the whole rod: the scale below
// which "no strain" is round-off (coordinates of 0.1 m carry 1e-17 m).
double strainScale(const Model& m) {
  const RodModel& rm = m.rods[0];
  return 0.5 * rm.material.youngModulus * rm.section.area * kLength * 1e-18;
}

TEST(ConstraintsTest, PrescribedClampVelocityTranslatesTheRodRigidly) {
  const Vec3 v(0.02, -0.01, 0.005);
  const Model m = movingClamp(v, Vec3::Zero());
  State s = makeState(m);
  for (auto& vi : s.rods[0].v) vi = v;  // already moving with the clamp
  ASSERT_TRUE(run(m, s, 200));
  double worst = 0;
  for (int i = 0; i <= kBeams; ++i)
    worst = std::max(worst, (s.rods[0].x[i] - (m.rods[0].restPoints[i] + v * s.time)).norm());
  EXPECT_TRUE(small("translated rod vs x + v t / L", worst / kLength, roundoff(1.0, 400, "200 steps of x += h v")));
  EXPECT_TRUE(small("strain energy of the translated rod / (EA L 1e-18 / 2)", elasticEnergy(m, s) / strainScale(m),
                    {1.0, "below a strain of 1e-9"}));
}

TEST(ConstraintsTest, PrescribedClampSpinTwistsTheRodRigidlyAboutItsAxis) {
  const Vec3 spin(3.0, 0, 0);  // rad/s about the rod's axis
  const Model m = movingClamp(Vec3::Zero(), spin);
  State s = makeState(m);
  for (auto& wi : s.rods[0].w) wi = spin;
  ASSERT_TRUE(run(m, s, 200));
  const Quat expected = quatExp(spin * s.time);
  double worstFrame = 0, worstPos = 0;
  for (int i = 0; i <= kBeams; ++i) {
    worstFrame = std::max(worstFrame, s.rods[0].q[i].angularDistance(expected * m.rods[0].restFrames[i]));
    worstPos = std::max(worstPos, (s.rods[0].x[i] - m.rods[0].restPoints[i]).norm());
  }
  EXPECT_TRUE(small("spun frames vs exp(w t) q (rad)", worstFrame, roundoff(1.0, 1e3, "200 composed rotations")));
  EXPECT_TRUE(small("spun rod position drift / L", worstPos / kLength, roundoff(1.0, 1e3, "200 steps")));
  EXPECT_TRUE(small("strain energy of the spun rod / (EA L 1e-18 / 2)", elasticEnergy(m, s) / strainScale(m),
                    {1.0, "below a strain of 1e-9"}));
}

TEST(ConstraintsTest, StaticSolveFollowsARigidlyMovedClamp) {
  // Move the clamp by (5, 2, -3) mm and turn it 0.3 rad about z, then solve.
  const Vec3 v(0.005, 0.002, -0.003), w(0, 0, 0.3);
  const Model m = movingClamp(v, w);
  State s = makeState(m);
  advanceTargets(m, s, 1.0);
  const StaticReport rep = solveStatic(m, s, tightStatic(1));
  ASSERT_TRUE(rep.converged()) << rep.message();
  const Quat r = quatExp(w);
  double worstPos = 0, worstFrame = 0;
  for (int i = 0; i <= kBeams; ++i) {
    const Vec3 expected = v + r * m.rods[0].restPoints[i];
    worstPos = std::max(worstPos, (s.rods[0].x[i] - expected).norm());
    worstFrame = std::max(worstFrame, s.rods[0].q[i].angularDistance(r * m.rods[0].restFrames[i]));
  }
  const Tolerance newton{1e-10, "Newton stop 1e-13 L per update, round-off"};
  EXPECT_TRUE(small("rigidly moved rod positions / L", worstPos / kLength, newton));
  EXPECT_TRUE(small("rigidly moved rod frames (rad)", worstFrame, newton));
}

}  // namespace
}  // namespace coilsim::test
