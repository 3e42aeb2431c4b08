// Tests of the implicit time step (src/physics/dynamics.cpp, health.cpp).
// References:
//  - a rest shape is an equilibrium: without load the helix stays on the
//    analytic helix of coil-measurement/1 (curvature R / (R^2 + c^2),
//    torsion +-c / (R^2 + c^2), c = p / 2pi), read off the nodes by the exact
//    screw fit of tests/support/curve_geometry.h;
//  - energy balance: with Rayleigh damping and implicit Euler, the total
//    energy can only decrease; for a single mode of x'' + (a + b w^2) x' +
//    w^2 x = 0 the exact solution's energy, sampled at equal phases, decays
//    like exp(-(a + b w^2) t) (e.g. Clough & Penzien, Dynamics of Structures,
//    sec. 12-7); implicit Euler (linearised step as in integrator.h) maps
//    (x, v) by a matrix of determinant 1 / D, D = 1 + h a + h b w^2 + h^2 w^2,
//    so its energy decays exactly like D^(-t / h) (derived from the step's
//    equations in integrator.h, not from its output);
//  - blow-up handling as documented in integrator.h: refused step, state
//    restored, counted, one warning.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>

#include "support/cantilever_modes.h"
#include "support/curve_geometry.h"
#include "support/known_bugs.h"
#include "support/rod_models.h"
#include "support/tolerance.h"

namespace coilsim::test {
namespace {

// ---- Helix rest shape ------------------------------------------------------

constexpr double kHelixLength = 0.03, kLoopDiameter = 0.007, kPitch = 0.002;
constexpr int kHelixBeams = 120;

Model helixCoil(bool rightHanded, double alpha = 0) {
  ModelDef d = modelOf({clamped(rodWithRest(makeHelix(kHelixLength, kHelixBeams, kLoopDiameter, kPitch, rightHanded),
                                            kHelixLength, kHelixBeams, platinum(),
                                            circularSection(1.8e-4, kPlatinumPoisson)))});
  d.damping.massCoeff = alpha;
  return compileModel(d);
}

// Worst relative errors of curvature and torsion read off every four
// consecutive nodes, against the coil-measurement/1 formulas.
std::pair<double, double> helixErrors(const std::vector<Vec3>& x, bool rightHanded) {
  const double r = kLoopDiameter / 2, c = (rightHanded ? 1 : -1) * kPitch / (2 * M_PI), a2 = r * r + c * c;
  double ek = 0, et = 0;
  for (size_t i = 0; i + 3 < x.size(); ++i) {
    const HelixFit f = helixThrough(x[i], x[i + 1], x[i + 2], x[i + 3]);
    ek = std::max(ek, relativeError(f.curvature, r / a2));
    et = std::max(et, relativeError(f.torsion, c / a2));
  }
  return {ek, et};
}

TEST(DynamicsTest, HelixRestShapeIsKeptWithoutLoad) {
  for (const bool right : {true, false}) {
    const Model m = helixCoil(right);
    State s = makeState(m);
    ASSERT_TRUE(run(m, s, 300));
    const auto [ek, et] = helixErrors(s.rods[0].x, right);
    const std::string tag = right ? "right" : "left";
    // Second differences of 0.25 mm chords amplify coordinate round-off ~1e3 times.
    const Tolerance tol{1e-8, "exact screw fit; second differences amplify round-off ~1e3 times"};
    EXPECT_TRUE(small(tag + " helix after 300 steps: curvature (relative)", ek, tol));
    EXPECT_TRUE(small(tag + " helix after 300 steps: signed torsion (relative)", et, tol));
    double drift = 0;
    for (int i = 0; i <= kHelixBeams; ++i) drift = std::max(drift, (s.rods[0].x[i] - m.rods[0].restPoints[i]).norm());
    EXPECT_TRUE(small(tag + " helix drift from rest / D", drift / kLoopDiameter,
                      {1e-12, "forces of the rest shape are round-off; 300 steps keep it there"}));
  }
}

TEST(DynamicsTest, PerturbedHelixReturnsToItsRestShape) {
  const Model m = helixCoil(true, 40.0);
  State s = makeState(m);
  // Kick every node sideways at 5 mm/s and spin it at 5 rad/s.
  for (int i = 1; i <= kHelixBeams; ++i) {
    s.rods[0].v[i] = Vec3(0.005 * std::sin(0.3 * i), 0.005 * std::cos(0.7 * i), 0.005);
    s.rods[0].w[i] = Vec3(5 * std::cos(0.2 * i), 0, 5);
  }
  ASSERT_TRUE(run(m, s, 1500));
  const auto [ek, et] = helixErrors(s.rods[0].x, true);
  // Mass damping 40 1/s removes underdamped modes like exp(-20 t); the
  // softest (overdamped) coil modes decay at ~w^2 / a. After 1.5 s the shape
  // is back within 1e-6 (the kick displaced it by ~1e-4 D).
  const Tolerance tol{1e-6, "damped return: exp(-20 t) and slow overdamped modes over 1.5 s"};
  EXPECT_TRUE(small("perturbed helix back to rest: curvature (relative)", ek, tol));
  EXPECT_TRUE(small("perturbed helix back to rest: torsion (relative)", et, tol));
}

// ---- Energy ----------------------------------------------------------------

// Cantilever in its analytic first mode (tip amplitude 1e-4 L), no gravity.
// 40 beams: the model's first frequency is then within 3e-4 of the formula
// (modal_test.cpp), 6e-4 in omega^2, which the decay rates below depend on.
constexpr double kLength = 0.1, kRadius = 1e-4;
constexpr int kBeams = 40;

double firstModeOmega() {
  const Section s = circularSection(kRadius, kSteelPoisson);
  return cantileverOmega(kCantileverBetaL[0], kLength, steel().youngModulus * s.iy, steel().density * s.area);
}

State startInFirstMode(const Model& m) {
  State s = makeState(m);
  const ModeShape mode(kCantileverBetaL[0], kLength);
  const double scale = 1e-4 * kLength / mode.value(kLength);
  for (int i = 0; i <= kBeams; ++i) {
    const double x = kLength * i / kBeams;
    s.rods[0].x[i].z() = scale * mode.value(x);
    s.rods[0].q[i] = quatExp(Vec3(0, -scale * mode.slope(x), 0));
  }
  return s;
}

struct Decay {
  double rate = 0;             // measured energy decay rate, 1/s
  double worstIncrease = 0;    // largest step-to-step energy increase / initial energy
};

// Energy at upward zero crossings of the tip (equal phases), over ~3 periods.
Decay measureDecay(double alpha, double beta, double h) {
  ModelDef d = modelOf({clamped(straightRod(kLength, kBeams, steel(), circularSection(kRadius, kSteelPoisson)))});
  d.damping = {alpha, beta};
  d.timeStep = h;
  const Model m = compileModel(d);
  State s = startInFirstMode(m);
  const double e0 = computeEnergy(m, s).total();
  Decay out;
  std::vector<double> times, energies;
  double prevZ = s.rods[0].x[kBeams].z(), prevE = e0;
  const int steps = int(3.2 * 2 * M_PI / firstModeOmega() / h);
  for (int k = 0; k < steps; ++k) {
    EXPECT_TRUE(step(m, s).ok());
    const double z = s.rods[0].x[kBeams].z(), e = computeEnergy(m, s).total();
    out.worstIncrease = std::max(out.worstIncrease, (e - prevE) / e0);
    if (prevZ < 0 && z >= 0) {
      const double f = z / (z - prevZ);  // fraction of the step after the crossing
      times.push_back(s.time - f * h);
      energies.push_back(e - f * (e - prevE));
    }
    prevZ = z, prevE = e;
  }
  EXPECT_GE(times.size(), 3u);
  out.rate = -std::log(energies.back() / energies.front()) / (times.back() - times.front());
  return out;
}

// Exact energy decay rate of implicit Euler for one mode (see header).
double implicitEulerRate(double alpha, double beta, double omega, double h) {
  return std::log(1 + h * alpha + h * beta * omega * omega + h * h * omega * omega) / h;
}

// A step may gain energy only by round-off of the energy sums (~1e-13 of E).
const Tolerance kNoEnergyGain{1e-12, "round-off of the energy sums"};

TEST(DynamicsTest, MassProportionalDampingDecaysEnergyLikeExpMinusAlphaT) {
  const double alpha = 5.0, omega = firstModeOmega(), h = 2e-5;
  const Decay d = measureDecay(alpha, 0.0, h);
  // Implicit Euler adds h w^2 = 0.16 1/s (3 %) of numerical dissipation; the
  // bound on |rate - alpha| is that plus 1 % for mode leakage and sampling.
  EXPECT_TRUE(nearRel("energy decay rate vs alpha", d.rate, alpha,
                      {h * omega * omega / alpha + 0.01, "implicit Euler's own h w^2 plus 1 %"}));
  EXPECT_TRUE(nearRel("energy decay rate vs implicit Euler's exact rate", d.rate,
                      implicitEulerRate(alpha, 0, omega, h),
                      {5e-3, "model omega^2 within 6e-4 of the formula, mode leakage, crossing interpolation"}));
  EXPECT_TRUE(small("largest energy gain in one step / E0", std::max(0.0, d.worstIncrease), kNoEnergyGain));
}

TEST(DynamicsTest, StiffnessProportionalDampingDecaysEnergyLikeExpMinusBetaOmegaSquaredT) {
  const double omega = firstModeOmega(), beta = 5.0 / (omega * omega), h = 2e-5;  // b w^2 = 5 1/s
  const Decay d = measureDecay(0.0, beta, h);
  EXPECT_TRUE(nearRel("energy decay rate vs beta omega^2", d.rate, beta * omega * omega,
                      {h * omega * omega / (beta * omega * omega) + 0.01, "implicit Euler's own h w^2 plus 1 %"}));
  EXPECT_TRUE(nearRel("energy decay rate vs implicit Euler's exact rate (beta)", d.rate,
                      implicitEulerRate(0, beta, omega, h),
                      {5e-3, "model omega^2 within 6e-4 of the formula, mode leakage, crossing interpolation"}));
  EXPECT_TRUE(small("largest energy gain in one step / E0 (beta)", std::max(0.0, d.worstIncrease), kNoEnergyGain));
}

TEST(DynamicsTest, TotalEnergyNeverIncreasesInALargeMotion) {
  // A helix coil released under gravity with light Rayleigh damping: large
  // rotations, gravity doing work, the co-rotational forces fully nonlinear.
  ModelDef d = modelOf({clamped(rodWithRest(makeHelix(kHelixLength, 60, kLoopDiameter, kPitch, true), kHelixLength, 60,
                                            platinum(), circularSection(1.8e-4, kPlatinumPoisson)))},
                       {"gravity"}, Vec3(0, 0, -9.81));
  d.damping = {1.0, 1e-5};
  const Model m = compileModel(d);
  State s = makeState(m);
  const double e0 = computeEnergy(m, s).total();
  double prev = e0, worst = 0, scale = 0;
  for (int k = 0; k < 1000; ++k) {
    ASSERT_TRUE(step(m, s).ok());
    const Energy e = computeEnergy(m, s);
    scale = std::max(scale, std::abs(e.potential));
    worst = std::max(worst, e.total() - prev);
    prev = e.total();
  }
  EXPECT_LT(prev, e0);
  EXPECT_TRUE(small("largest energy gain in one step / |potential|", worst / scale, kNoEnergyGain));
}

// ---- Blow-up ---------------------------------------------------------------

bool sameBits(const State& a, const State& b) {
  auto eqVec = [](const auto& u, const auto& v) {
    return u.size() == v.size() && (u.empty() || std::memcmp(u.data(), v.data(), sizeof(u[0]) * u.size()) == 0);
  };
  if (std::memcmp(&a.time, &b.time, sizeof(double)) != 0) return false;
  for (size_t k = 0; k < a.rods.size(); ++k) {
    const RodState &ra = a.rods[k], &rb = b.rods[k];
    if (!eqVec(ra.x, rb.x) || !eqVec(ra.q, rb.q) || !eqVec(ra.v, rb.v) || !eqVec(ra.w, rb.w)) return false;
  }
  return true;
}

bool sameTargets(const State& a, const State& b) {
  for (size_t k = 0; k < a.rods.size(); ++k)
    for (size_t c = 0; c < a.rods[k].targets.size(); ++c) {
      const Pose &ta = a.rods[k].targets[c], &tb = b.rods[k].targets[c];
      if (std::memcmp(ta.position.data(), tb.position.data(), 3 * sizeof(double)) != 0 ||
          std::memcmp(ta.rotation.coeffs().data(), tb.rotation.coeffs().data(), 4 * sizeof(double)) != 0)
        return false;
    }
  return true;
}

Model movingCantilever() {
  RodDef r = straightRod(0.05, 10, steel(), circularSection(1e-4, kSteelPoisson));
  // The clamp moves and turns, so the refused step must also put targets back.
  r.constraints.push_back({0, kAllDofs, Vec3(0.013, -0.007, 0.003), Vec3(0.3, 0.1, -0.2)});
  r.loads.push_back({10, Vec3(0, 0, -1e-4), Vec3::Zero()});
  ModelDef d = modelOf({r});
  d.damping.massCoeff = 1;
  return compileModel(d);
}

TEST(DynamicsTest, BlowUpIsRefusedCountedWarnedOnceAndTheStateRestored) {
  Model m = movingCantilever();
  State s = makeState(m);
  ASSERT_TRUE(run(m, s, 5));
  const State before = s;
  struct Case {
    const char* what;
    Vec3 force;
  };
  // A non-finite load, and an absurd one (1e12 N on a 0.1 mm wire: speed
  // far beyond HealthLimits::maxSpeed).
  const Case cases[] = {{"NaN load", Vec3(std::numeric_limits<double>::quiet_NaN(), 0, 0)},
                        {"absurd load", Vec3(0, 0, -1e12)}};
  long refused = 0;
  for (const Case& c : cases) {
    Model bad = m;
    bad.rods[0].loads[0].force = c.force;
    for (int k = 0; k < 3; ++k) {
      const StepReport rep = step(bad, s);
      ASSERT_FALSE(rep.ok()) << c.what;
      EXPECT_EQ(rep.failure->kind, FailureKind::BlowUp) << c.what << ": " << rep.message();
      EXPECT_FALSE(rep.message().empty());
      ++refused;
      EXPECT_TRUE(sameBits(s, before)) << c.what << ": positions, rotations, velocities or time changed";
    }
  }
  EXPECT_EQ(s.blowups, refused);
  // Same time, same kind of failure: one warning per distinct message, not per step.
  EXPECT_LE(s.warnings.size(), 2u);
  EXPECT_GE(s.warnings.size(), 1u);
  // After the bad load is gone the run goes on.
  EXPECT_TRUE(step(m, s).ok());
}

// The strain check compares squared lengths (health.cpp); the limit is on
// the engineering strain |x_b - x_a| / L0 - 1, which is what is set here.
TEST(DynamicsTest, HealthRefusesABeamStretchedOrCrushedBeyondTheStrainLimit) {
  const Model m = movingCantilever();
  const double limit = m.health.maxAxialStrain;
  for (const double strain : {0.9 * limit, -0.9 * limit, 1.1 * limit, -1.1 * limit}) {
    State s = makeState(m);
    RodState& r = s.rods[0];
    const Vec3 chord = r.x[4] - r.x[3];
    const Vec3 shift = strain * chord;  // beam 3 gets strain, beam 4 keeps its length
    for (int i = 4; i < r.activeNodes; ++i) r.x[i] += shift;
    const std::optional<Failure> problem = checkHealth(m, s);
    if (std::abs(strain) < limit) {
      EXPECT_FALSE(problem) << strain << ": " << problem->message();
    } else {
      ASSERT_TRUE(problem) << strain;
      // Where and how much: the beam stretched above, by the strain set there.
      EXPECT_EQ(problem->kind, FailureKind::BlowUp);
      EXPECT_EQ(problem->rod, m.rods[0].name);
      EXPECT_EQ(problem->beam, 3);
      EXPECT_EQ(problem->quantity, "axial strain");
      EXPECT_NEAR(problem->value, strain, 1e-12);
      EXPECT_EQ(problem->limit, limit);
      EXPECT_NE(problem->message().find("beam 3: axial strain"), std::string::npos) << strain << ": " << problem->message();
    }
  }
}

TEST(DynamicsTest, RefusedStepLeavesNoTrace) {
  SKIP_IF_OPEN(kRefusedStepMovesTargets);
  Model m = movingCantilever();
  State s = makeState(m);
  ASSERT_TRUE(run(m, s, 7));
  const State before = s;
  Model bad = m;
  bad.rods[0].loads[0].force = Vec3(0, 0, std::numeric_limits<double>::infinity());
  EXPECT_FALSE(step(bad, s).ok());
  EXPECT_TRUE(sameTargets(s, before)) << "constraint targets were moved back by -dt instead of restored";
  // The run then continues bit for bit as if the refused step never happened.
  State reference = before;
  ASSERT_TRUE(step(m, reference).ok());
  ASSERT_TRUE(step(m, s).ok());
  EXPECT_TRUE(sameBits(s, reference)) << "the refused step left a trace in the state";
}

// A cantilever bent by a tip load, then clamp and load both released at
// once (as a detach under load does): the freed end, with almost no rotary
// inertia, turns by a large angle within a millisecond, more than one
// linearised step follows, so step() retries the interval in substeps.
// Reference: once released there is no external force (no gravity, no mass
// damping; stiffness damping is internal), so the centre of mass stays put.
TEST(DynamicsTest, ReleasedShockIsResolvedInSubstepsAndConservesMomentum) {
  constexpr double kLength = 0.01, kTipLoad = 0.035;
  constexpr int kBeams = 20;
  RodDef held = clamped(straightRod(kLength, kBeams, platinum(), circularSection(1.5e-4, kPlatinumPoisson)));
  held.loads.push_back({kBeams, Vec3(0, kTipLoad, 0), Vec3::Zero()});
  ModelDef heldDef = modelOf({held});
  const Model heldModel = compileModel(heldDef);
  State bent = makeState(heldModel);
  ASSERT_TRUE(solveStatic(heldModel, bent).converged());

  ModelDef freeDef = modelOf({straightRod(kLength, kBeams, platinum(), circularSection(1.5e-4, kPlatinumPoisson))});
  freeDef.damping = {0.0, 1e-5};
  const Model m = compileModel(freeDef);
  State s = makeState(m);
  RodState& r = s.rods[0];
  r.x = bent.rods[0].x, r.q = bent.rods[0].q;
  std::printf("[ measured ] tip deflection before release %.3g of the length\n", r.x[kBeams].y() / kLength);
  auto centre = [&] {
    Vec3 c = Vec3::Zero();
    double mass = 0;
    for (int i = 0; i <= kBeams; ++i) c += r.nodes[i].mass * r.x[i], mass += r.nodes[i].mass;
    return Vec3(c / mass);
  };
  const Vec3 c0 = centre();
  for (int k = 0; k < 200; ++k) ASSERT_TRUE(step(m, s).ok()) << "step " << k << ": " << s.warnings.back();
  std::printf("[ measured ] %ld of 200 steps needed substeps; centre of mass moved %.3g m\n", s.substepped,
              (centre() - c0).norm());
  EXPECT_EQ(s.blowups, 0);
  EXPECT_GT(s.substepped, 0) << "the shock should be too fast for single steps (else this test proves nothing)";
  EXPECT_LT((centre() - c0).norm(), 1e-4 * kLength);
}

// An element spun about its clamped end: a stiff string (EA 235 N) with a
// free end node, almost no bending stiffness (3 EI / L^3 of 2e-3 N/m against
// the node's m / h^2 of 3.4 N/m), started at 600 rad/s. Reference: the exact
// motion is a rigid rotation, which keeps the element's length. One
// linearised step moves the end node along the tangent, by 0.6 L, and leaves
// it sqrt(1 + 0.6^2) - 1 = 17 % stretched; step() must take such a step in
// substeps until no element ends stretched by more than the 5 % its
// linearised step is promised to follow (integrator.h); the end node still
// moves on (implicit Euler damps the spin, which is not what is tested).
TEST(DynamicsTest, ElementTurningFastIsSteppedInSubstepsAndKeepsItsLength) {
  constexpr double kLength = 0.01, kRadius = 1e-4, kOmega = 600, kPromisedStretch = 0.05;
  const double area = M_PI * kRadius * kRadius;
  const Section string = customSection(area, 1e-19, 1e-19, 2e-19, 0.9, kRadius);
  const Model m = compileModel(modelOf({clamped(straightRod(kLength, 1, platinum(), string))}));
  ASSERT_NEAR(m.timeStep, 1e-3, 1e-15);
  State s = makeState(m);
  RodState& r = s.rods[0];
  r.v[1] = Vec3(0, kOmega * kLength, 0);
  r.w[1] = Vec3(0, 0, kOmega);
  double worst = 0;
  const Vec3 start = r.x[1];
  for (int k = 0; k < 20; ++k) {
    ASSERT_TRUE(step(m, s).ok()) << "step " << k << ": " << s.warnings.back();
    worst = std::max(worst, std::abs((r.x[1] - r.x[0]).norm() / kLength - 1));
  }
  std::printf("[ measured ] largest stretch %.3g after a step (one linearised step: %.3g), %ld of 20 steps substepped, "
              "end node %.3g of the length from its start\n",
              worst, std::sqrt(1 + std::pow(kOmega * m.timeStep, 2)) - 1, s.substepped, (r.x[1] - start).norm() / kLength);
  EXPECT_EQ(s.blowups, 0);
  EXPECT_GT(s.substepped, 0) << "a single step should turn it too far (else this test proves nothing)";
  EXPECT_LT(worst, kPromisedStretch);
  EXPECT_GT((r.x[1] - start).norm(), 0.1 * kLength) << "the element stopped turning";
}

// ---- Several States per Model ----------------------------------------------

TEST(DynamicsTest, StatesSharingAModelAreIndependentAndDeterministic) {
  const Model m = helixCoil(true, 2.0);
  State a = makeState(m), b = makeState(m), c = makeState(m);
  a.rods[0].v[kHelixBeams] = Vec3(0, 0, 0.01);
  c.rods[0].v[kHelixBeams] = Vec3(0, 0, 0.01);
  for (int k = 0; k < 100; ++k) {  // interleaved: shared scratch would show
    ASSERT_TRUE(step(m, a).ok());
    ASSERT_TRUE(step(m, b).ok());
  }
  ASSERT_TRUE(run(m, c, 100));
  EXPECT_TRUE(sameBits(a, c)) << "the same start gives different bits when another State is stepped in between";
  double drift = 0;
  for (int i = 0; i <= kHelixBeams; ++i) drift = std::max(drift, (b.rods[0].x[i] - m.rods[0].restPoints[i]).norm());
  EXPECT_TRUE(small("untouched State stays at rest / D", drift / kLoopDiameter,
                    {1e-12, "rest shape forces are round-off"}));
}

}  // namespace
}  // namespace coilsim::test
