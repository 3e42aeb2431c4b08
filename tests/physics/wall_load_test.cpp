// The wall load (physics/contact/wall_load.h): the sustained figure filters
// penalty spikes by its stated window, and a cantilever pressed on a wall
// reads the force of beam theory, converging as the penalty stiffness grows.
#include "physics/contact/wall_load.h"

#include <gtest/gtest.h>

#include <cmath>

#include "physics/contact/detect.h"
#include "physics/integrator.h"
#include "support/meshes.h"
#include "support/rod_models.h"

namespace coilsim {
namespace {

TEST(WallLoad, ASpikeEveryOtherStepIsNotALoadAndTheWindowIsStatedInSeconds) {
  // 1 N every other step over a steady 2 mN (a light node chattering): the
  // sustained load is the 2 mN, the peak the spike.
  WallLoad w;
  for (int s = 0; s <= 20; ++s) addWallLoad(w, s % 2 ? 1.0 : 2e-3, 1e-3, 1e-3 * s);
  EXPECT_DOUBLE_EQ(w.now, 2e-3);
  EXPECT_DOUBLE_EQ(w.max, 2e-3);
  EXPECT_DOUBLE_EQ(w.peak, 1.0);
  // A load counts once it has lasted the window, 5 ms, whatever the step.
  for (const double h : {1e-3, 2.5e-4}) {
    WallLoad v;
    const int steps = int(std::lround(kWallLoadWindow / h));
    EXPECT_EQ(wallLoadSteps(h), steps);
    for (int s = 0; s < steps - 1; ++s) addWallLoad(v, 0.05, h, h * s);
    EXPECT_EQ(v.now, 0.0) << "h = " << h;
    addWallLoad(v, 0.05, h, h * steps);
    EXPECT_EQ(v.now, 0.05) << "h = " << h;
  }
  // Nothing until a whole window was stepped; a State that starts again has none.
  EXPECT_EQ(State{}.stats.wallLoad.max, 0.0);
}

// A platinum cantilever (L = 10 mm, r = 0.15 mm, 20 beams, clamped at x = 0)
// is moved rigidly onto a flat frictionless wall tilted by alpha, so that
// only its tip node touches, until the wall's contact surface (the skin,
// kWallSkin r outside the wire) overlaps the tip by d along the wall normal;
// then it settles.
struct PressedCantilever {
  double load = 0;      // N, the sustained wall load after settling
  double fastest = 0;   // m/s, fastest node at the end
  double kBeam = 0;     // N/m, beam theory's tip stiffness along the wall normal
  double kNode = 0;     // N/m, the penalty on the tip node (k per length times half a segment)
};

constexpr double kLength = 0.01, kRadius = 0.15e-3, kOverlap = 0.1e-3, kTilt = 0.3;  // tan(alpha)
constexpr int kBeams = 20;

PressedCantilever pressCantilever(double stiffness_n_mm2) {
  RodDef rod = test::clamped(
      test::straightRod(kLength, kBeams, test::platinum(), circularSection(kRadius, test::kPlatinumPoisson)));
  ModelDef def = test::modelOf({rod});
  def.damping.massCoeff = 100;
  EffectUse wall = EffectRegistry::global().use("wall_contact");
  wall.set("stiffness_n_mm2", stiffness_n_mm2 * 1e6);
  wall.set("stiffness_per_rigidity_1_mm3", 0);  // the penalty exactly as given
  wall.set("friction_static", 0);
  wall.set("friction_dynamic", 0);
  def.effects.push_back(wall);
  // The wall rises along +x with slope kTilt; the rod lives above it.
  const double alpha = std::atan(kTilt);
  const Vec3 up(-std::sin(alpha), 0, std::cos(alpha));  // the wall's normal into the free side
  const Vec3 tip(kLength, 0, 0);
  const double gap = 0.1e-3;  // clear before the clamp moves
  const Vec3 foot = tip - ((1 + kWallSkin) * kRadius + gap) * up;
  def.obstacles.push_back(test::obstacleOf(test::plane(foot, -up, 2e-3, 8), 0.0));
  Model model = compileModel(def);
  State state = makeState(model);
  // The clamp moves along -up by gap + overlap at 10 mm/s, then holds.
  const double speed = 0.01, travel = gap + kOverlap;
  const long moving = std::lround(travel / speed / model.timeStep);
  model.rods[0].constraints[0].velocity = -speed * up;
  PressedCantilever out;
  for (long s = 0; s < 400; ++s) {
    if (s == moving) model.rods[0].constraints[0].velocity = Vec3::Zero();
    EXPECT_TRUE(step(model, state).ok()) << "step " << s;
  }
  for (const Vec3& v : state.rods[0].v) out.fastest = std::max(out.fastest, v.norm());
  out.load = state.stats.wallLoad.now;
  const double ei = test::platinum().youngModulus * M_PI * std::pow(kRadius, 4) / 4;
  // Tip force F along the normal: its transverse part F cos(alpha) bends the
  // cantilever by F cos L^3 / 3EI, which moves the tip along the normal by
  // that times cos (the axial part shortens it by 1e-7 of that).
  out.kBeam = 3 * ei / (std::pow(kLength, 3) * std::pow(std::cos(alpha), 2));
  out.kNode = stiffness_n_mm2 * 1e6 * (kLength / kBeams) / 2;
  return out;
}

// Beam and penalty in series: the tip takes the overlap d as F / kBeam + F / kNode.
double seriesForce(const PressedCantilever& p) { return kOverlap / (1 / p.kBeam + 1 / p.kNode); }

TEST(WallLoad, ACantileverPressedOnAWallReadsBeamTheorysForceAndConvergesAsThePenaltyStiffens) {
  // A Richardson-style sequence: penalties from about the beam's own tip
  // stiffness (9.8 N/m) up, each twice the last, and the default wall. The
  // load follows beam and penalty in series (so the penalty's law is the
  // one stated), and tends to beam theory's.
  const double ks[] = {0.04, 0.08, 0.16, 0.32};  // N/mm2 (tip node 10-80 N/m)
  double loads[4];
  for (int i = 0; i < 4; ++i) {
    const PressedCantilever p = pressCantilever(ks[i]);
    loads[i] = p.load;
    std::printf("[ measured ] k %.2f N/mm2: wall load %.4f mN, beam and penalty in series %.4f mN, fastest node %.2g m/s\n",
                ks[i], p.load * 1e3, seriesForce(p) * 1e3, p.fastest);
    EXPECT_LT(p.fastest, 1e-5) << "not settled";
    EXPECT_NEAR(p.load, seriesForce(p), 0.02 * seriesForce(p)) << "k = " << ks[i];
  }
  // Monotone convergence: each doubling changes the load less than the last.
  for (int i = 0; i + 2 < 4; ++i) EXPECT_LT(loads[i + 2] - loads[i + 1], loads[i + 1] - loads[i]) << "k " << ks[i];
  // Richardson extrapolation: in series, 1 / F is linear in 1 / k, so
  // 2 / F(2k) - 1 / F(k) is 1 / F at an infinitely stiff wall: beam theory's
  // F = 3 EI d / (L^3 cos^2 alpha).
  const PressedCantilever stiff = pressCantilever(ks[3]);
  const double limit = kOverlap * stiff.kBeam;
  const double extrapolated = 1 / (2 / loads[3] - 1 / loads[2]);
  EXPECT_NEAR(extrapolated, limit, 0.02 * limit);
  // At the registered wall (200 N/mm2) the load is beam theory's, and doubling the wall changes it by far less than 10 %.
  const double f200 = pressCantilever(200).load, f400 = pressCantilever(400).load;
  std::printf("[ measured ] default wall: %.4f mN, twice as stiff %.4f mN, beam theory %.4f mN\n", f200 * 1e3,
              f400 * 1e3, limit * 1e3);
  EXPECT_NEAR(f200, limit, 0.02 * limit);
  EXPECT_LT(std::abs(f400 - f200), 0.1 * f400);
}

}  // namespace
}  // namespace coilsim
