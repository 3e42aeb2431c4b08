// Rod-pair detection with sleeping rods (detect_rods.cpp, physics/sleep.h).
// Reference: the geometry of two crossing wires (their centre lines
// 2 r + 10 um apart, within the contact margin): the pair is found while
// one of them is awake, and not between two sleeping ones; a sleeping rod's
// self contacts are kept as they were, not detected again.
#include <gtest/gtest.h>

#include "physics/contact/detect.h"
#include "support/rod_models.h"

namespace coilsim {
namespace {

constexpr double kRadius = 0.127e-3, kLength = 5e-3;

Model crossingWires() {
  const Section section = circularSection(kRadius, test::kPlatinumPoisson);
  RodDef a = test::straightRod(kLength, 10, test::platinum(), section);
  RodDef b = a;
  a.placement = {Vec3(-0.5 * kLength, 0, 0), Vec3::UnitX(), Vec3::UnitY()};
  b.placement = {Vec3(0, -0.5 * kLength, 2 * kRadius + 10e-6), Vec3::UnitY(), Vec3::UnitX()};
  return compileModel(test::modelOf({a, b}, {"rod_contact"}));
}

void detectPairs(const Model& model, State& s) {
  ContactLaw law;
  law.stiffness = 5e4;
  law.radiusScale = 1;
  detectRodContacts(model, s, 1e-3, false, 0.05e-3, law, law);
}

TEST(DetectRodsSleeping, PairsWithAnAwakeRodAreFoundAndPairsOfTwoSleepingRodsAreNot) {
  const Model model = crossingWires();
  State s = makeState(model);
  detectPairs(model, s);
  ASSERT_FALSE(s.rods[0].contact.rod.empty()) << "the wires cross within the margin: a pair must be found";
  const size_t both = s.rods[0].contact.rod.size();
  s.rods[0].asleep = true;
  detectPairs(model, s);
  EXPECT_EQ(s.rods[0].contact.rod.size(), both) << "a sleeping rod still meets an awake one";
  EXPECT_EQ(s.rods[1].contact.rod.size(), both);
  s.rods[1].asleep = true;
  detectPairs(model, s);
  EXPECT_TRUE(s.rods[0].contact.rod.empty());
  EXPECT_TRUE(s.rods[1].contact.rod.empty());
}

TEST(DetectRodsSleeping, ASleepingRodKeepsItsSelfContacts) {
  const Model model = crossingWires();
  State s = makeState(model);
  ContactPoint kept;
  kept.segment = 1, kept.other = 0, kept.otherSegment = 7, kept.gap = -1e-6;
  s.rods[0].contact.self = {kept};
  s.rods[0].contact.selfForce.assign(s.rods[0].x.size(), 0.25);
  s.rods[0].asleep = true;
  ContactLaw law;
  law.stiffness = 5e4;
  law.radiusScale = 1;
  detectRodContacts(model, s, 1e-3, true, 0.05e-3, law, law);
  ASSERT_EQ(s.rods[0].contact.self.size(), 1u);
  EXPECT_EQ(s.rods[0].contact.self[0].otherSegment, 7);
  EXPECT_EQ(s.rods[0].contact.selfForce[3], 0.25);
  s.rods[0].asleep = false;  // awake, a straight wire has no self contact
  detectRodContacts(model, s, 1e-3, true, 0.05e-3, law, law);
  EXPECT_TRUE(s.rods[0].contact.self.empty());
}

}  // namespace
}  // namespace coilsim
