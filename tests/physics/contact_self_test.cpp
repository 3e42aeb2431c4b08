// Self-contact (effects/self_contact.cpp) by topology: one rod lies on the
// floor along x (held), loops round and crosses over itself along y 0.3 mm
// above (gap between the wires); the crossing part is then pressed down
// 0.9 mm by its held ends, far more than the gap. The sign of the crossing,
// (d1 x d2) . (q - p) for the two segments at the crossing (computed here,
// not by the contact code), can only change if one wire passes through the
// other. With self-contact switched off the same press does pass through
// (the control that shows the check can fail).
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <set>
#include <vector>

#include "physics/contact/detect.h"
#include "physics/contact/geometry.h"
#include "physics/integrator.h"
#include "support/rod_models.h"

namespace coilsim {
namespace {

constexpr double kRadius = 0.15e-3, kLift = 0.6e-3, kPress = 0.9e-3, kSpeed = 0.005;

struct Press {
  int flips = 0;              // steps after which the crossing's sign had turned over
  double closest = INFINITY;  // least distance between the floor and the crossing part, m
  bool met = false;           // the wires came within 2 r + 20 um (so the test is not vacuous)
};

bool isFloor(const Vec3& rest) { return std::abs(rest.y()) < 1e-9 && std::abs(rest.z()) < 1e-9; }
bool isCrossing(const Vec3& rest) { return std::abs(rest.y() - kLift) < 1e-6 && std::abs(rest.x() - 4e-3) < 1e-6; }

Press pressCrossing(bool selfContact) {
  // Floor from (-4, 0, 0) to (4, 0, 0) mm, round to (0, -4, lift), across to (0, 4, lift).
  const std::vector<Vec3> points = {{-4e-3, 0, 0}, {4e-3, 0, 0}, {4e-3, -4e-3, 0.5 * kLift}, {0, -4e-3, kLift},
                                    {0, 4e-3, kLift}};
  double length = 0;
  for (size_t i = 1; i < points.size(); ++i) length += (points[i] - points[i - 1]).norm();
  const int beams = 96;
  RodDef rod = test::rodWithRest(makePolyline(points, length, beams, FrameRule::ParallelTransport, 0), length, beams,
                                 test::platinum(), circularSection(kRadius, test::kPlatinumPoisson));
  ModelDef def = test::modelOf({rod});
  def.damping.massCoeff = 20;
  def.effects.push_back(EffectRegistry::global().use("self_contact"));
  def.effects.back().enabled = selfContact;
  Model probe = compileModel(def);
  State rest = makeState(probe);
  // compileModel starts the rod at the origin along +x: the floor runs from
  // 0 to 8 mm on x, the lift is +y and the crossing part runs along z at
  // x = 4 mm. The floor held; the crossing part pressed down by its two
  // ends (the nodes beyond 2.5 mm of the crossing).
  const std::vector<Vec3>& x = rest.rods[0].x;
  for (int i = 0; i <= beams; ++i) {
    if (isFloor(x[i]) && x[i].x() < 7.9e-3) def.rods[0].constraints.push_back({i, kAllDofs});
    if (isCrossing(x[i]) && std::abs(x[i].z()) > 2.5e-3)
      def.rods[0].constraints.push_back({i, kTranslation, Vec3(0, -kSpeed, 0), Vec3::Zero()});
  }
  const Model model = compileModel(def);
  State state = makeState(model);

  Press out;
  const auto crossing = [&](const RodState& r, double& distance) {
    // The floor segment and the crossing segment nearest to each other.
    double best = INFINITY, sign = 0;
    for (int i = 0; i + 1 < r.activeNodes; ++i) {
      if (!isFloor(x[i]) || !isFloor(x[i + 1])) continue;
      for (int j = i + 2; j + 1 < r.activeNodes; ++j) {
        if (!isCrossing(x[j]) || !isCrossing(x[j + 1])) continue;
        const SegmentPair p = closestSegmentSegment(r.x[i], r.x[i + 1], r.x[j], r.x[j + 1]);
        if (p.distance < best) {
          best = p.distance;
          sign = (r.x[i + 1] - r.x[i]).cross(r.x[j + 1] - r.x[j]).dot(p.q - p.p);
        }
      }
    }
    distance = best;
    return sign;
  };
  double d0 = 0;
  const double sign0 = crossing(state.rods[0], d0);
  EXPECT_GT(d0, 2 * kRadius) << "the wires must start apart";
  const int steps = int(kPress / kSpeed / model.timeStep);
  for (int n = 0; n < steps; ++n) {
    if (!step(model, state).ok()) {
      ADD_FAILURE() << "step " << n << ": " << state.warnings.back();
      break;
    }
    double d = 0;
    if (crossing(state.rods[0], d) * sign0 < 0) ++out.flips;
    out.closest = std::min(out.closest, d);
    out.met = out.met || d < 2 * kRadius + 20e-6;
  }
  return out;
}

TEST(SelfContactTest, PressedCrossingNeverPassesThrough) {
  const Press p = pressCrossing(true);
  std::printf("[ measured ] crossing pressed %.1f mm past touch: sign turned over after %d steps; closest centre lines "
              "%.1f um (2 r = %.0f um)\n", (kPress - (kLift - 2 * kRadius)) * 1e3, p.flips, p.closest * 1e6,
              2 * kRadius * 1e6);
  EXPECT_TRUE(p.met) << "the wires never met: the test would prove nothing";
  EXPECT_EQ(p.flips, 0);
  EXPECT_GT(p.closest, kRadius);  // pressed in by less than one radius
}

// The end-of-step check (Effect::endStep) on a pair the step's contacts did
// not hold: a straight rod (1 mm beams) whose tail has been folded back
// within the step so that segment 8 lies across segment 2, their centre lines 0.1 mm apart (wires
// of radius 0.15 mm: 0.2 mm deep). Missed while the contact list is empty;
// not once the pair is in it (the penalty's business); not for a graze
// shallower than 5 % of 2 r.
TEST(SelfContactTest, EndOfStepCheckCatchesAPairCrossedWithinTheStep) {
  const int beams = 10;
  ModelDef def = test::modelOf({test::straightRod(10e-3, beams, test::platinum(),
                                                  circularSection(kRadius, test::kPlatinumPoisson))});
  def.effects.push_back(EffectRegistry::global().use("self_contact"));
  const Model model = compileModel(def);
  const EffectUse& use = model.effects.back();
  const auto cross = [&](double centreDistance) {
    State state = makeState(model);
    RodState& r = state.rods[0];
    r.work.x0.assign(r.x.begin(), r.x.end());  // the start of the step: straight, no pair near
    // Segment 8 across segment 2; its neighbours 7 and 9 rise 2 mm from it
    // (the hairpin's other segments stay more than 2 r from the rod).
    r.x[7] = Vec3(2.5e-3, -0.5e-3, centreDistance + 2e-3);
    r.x[8] = Vec3(2.5e-3, -0.5e-3, centreDistance);
    r.x[9] = Vec3(2.5e-3, 0.5e-3, centreDistance);
    r.x[10] = Vec3(2.5e-3, 0.5e-3, centreDistance + 2e-3);
    return state;
  };
  State deep = cross(0.1e-3);
  const std::optional<Failure> missed = use.effect->endStep(model, use.values, deep, model.timeStep);
  ASSERT_TRUE(missed);
  EXPECT_EQ(missed->kind, FailureKind::MissedContact);
  // Named as the crossing was built: segment 2 (beam 2 of the rod) lies under segment 8.
  EXPECT_EQ(missed->rod, model.rods[0].name);
  EXPECT_EQ(missed->beam, 2);
  EXPECT_NE(missed->message().find("beam 8"), std::string::npos) << missed->message();
  // The depth is the construction's: 2 r less the 0.1 mm between centre lines, beyond 5 % of 2 r.
  EXPECT_NEAR(missed->value, 2 * kRadius - 0.1e-3, 1e-9);
  EXPECT_NEAR(missed->limit, 0.05 * 2 * kRadius, 1e-15);
  use.effect->beginStep(model, use.values, deep, model.timeStep);  // now the pair is in the step's contacts
  EXPECT_EQ(use.effect->endStep(model, use.values, deep, model.timeStep), std::nullopt);
  State graze = cross(0.29e-3);  // 10 um deep: 3 % of 2 r
  EXPECT_EQ(use.effect->endStep(model, use.values, graze, model.timeStep), std::nullopt);
}

TEST(SelfContactTest, SwitchedOffTheCrossingPassesThrough) {
  const Press p = pressCrossing(false);
  EXPECT_GT(p.flips, 0);
}

// The pair search (detect_rods.cpp): slow segments through a grid, fast
// ones (sweeping more than a quarter of their size in the step) paired with
// every segment directly. Reference: every pair of non-adjacent segments by
// brute force, listed when it is within the margin or its start velocity
// closes it within the step. A tight helix (many near pairs), most nodes
// slow and a few at up to 1 m/s, must give exactly that set.
TEST(SelfContactTest, PairSearchWithFastSegmentsFindsWhatBruteForceFinds) {
  ModelDef def;
  RodDef r;
  r.length = 0.06;
  r.beams = 120;
  r.rest = makeHelix(r.length, r.beams, 2e-3, 0.25e-3, true);
  r.material = test::platinum();
  r.section = circularSection(0.12e-3, test::kPlatinumPoisson);
  def.rods.push_back(r);
  def.timeStep = 1e-3;
  const Model model = compileModel(def);
  std::mt19937 rng(3);
  std::normal_distribution<double> slow(0, 0.005);
  std::uniform_real_distribution<double> u(0, 1);
  const double h = 1e-3, margin = 0.05e-3;
  ContactLaw law;
  law.stiffness = 5e4;
  for (int trial = 0; trial < 5; ++trial) {
    State s = makeState(model);
    RodState& rod = s.rods[0];
    int fastNodes = 0;  // (counted for the printout)
    for (Vec3& v : rod.v) {
      v = Vec3(slow(rng), slow(rng), slow(rng));
      if (u(rng) < 0.03) v = Vec3(u(rng) - 0.5, u(rng) - 0.5, u(rng) - 0.5).normalized() * (0.2 + 0.8 * u(rng)), ++fastNodes;
    }
    rod.v[60 + 7 * trial] = Vec3(0.6, -0.3, 0.2), ++fastNodes;  // at least one in every trial
    detectRodContacts(model, s, h, true, margin, law, law);
    std::set<std::pair<int, int>> found, expected;
    for (const ContactPoint& c : rod.contact.self)
      if (c.segment < c.otherSegment) found.insert({c.segment, c.otherSegment});
    for (int i = 0; i + 1 < rod.activeNodes; ++i)
      for (int j = i + 2; j + 1 < rod.activeNodes; ++j) {
        const SegmentPair p = closestSegmentSegment(rod.x[i], rod.x[i + 1], rod.x[j], rod.x[j + 1]);
        const double gap = p.distance - (rod.nodes[i].radius + rod.nodes[j].radius);
        const Vec3 n = (p.p - p.q) / p.distance;
        const Vec3 va = (1 - p.s) * rod.v[i] + p.s * rod.v[i + 1], vb = (1 - p.t) * rod.v[j] + p.t * rod.v[j + 1];
        if (gap <= margin || -gap - h * n.dot(va - vb) > 0) expected.insert({i, j});
      }
    EXPECT_GT(expected.size(), 100u) << "trial " << trial;
    EXPECT_EQ(found, expected) << "trial " << trial << " (" << fastNodes << " fast nodes)";
  }
}

}  // namespace
}  // namespace coilsim
