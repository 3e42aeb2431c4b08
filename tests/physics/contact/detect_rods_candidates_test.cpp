// The pair search's candidates kept from step to step (a Verlet list,
// detect_rods.cpp, ContactScratch::keepPairCandidates) must find exactly
// the contacts of a fresh grid search every step, the reference. Two States
// of one Model, one keeping its candidates and one searching afresh, step
// the packed sac (support/dense_packing.h: four coils settling under
// gravity onto each other and the wall, 389 segments, most of them within
// reach of another) while a fifth coil is pushed in: every step's self and
// coil-coil contacts, and the poses, equal bit for bit. The candidates must
// have been both kept and rebuilt along the way (else the test would prove
// nothing about when they stop holding).
#include <gtest/gtest.h>

#include "physics/contact/detect.h"
#include "physics/integrator.h"
#include "support/dense_packing.h"
#include "support/rod_models.h"

namespace coilsim {
namespace {

using namespace test::dense;

void expectSameContacts(const std::vector<ContactPoint>& a, const std::vector<ContactPoint>& b, int step) {
  ASSERT_EQ(a.size(), b.size()) << "step " << step;
  for (size_t j = 0; j < a.size(); ++j) {
    ASSERT_EQ(a[j].segment, b[j].segment) << "step " << step;
    ASSERT_EQ(a[j].other, b[j].other) << "step " << step;
    ASSERT_EQ(a[j].otherSegment, b[j].otherSegment) << "step " << step;
    ASSERT_EQ(a[j].gap, b[j].gap) << "step " << step;
    ASSERT_EQ(a[j].normal, b[j].normal) << "step " << step;
    ASSERT_EQ(a[j].closing[0], b[j].closing[0]) << "step " << step;
  }
}

TEST(DetectRodsCandidates, KeptCandidatesFindExactlyTheFreshSearchsContacts) {
  ModelDef def = packedSac(false);
  // A fifth coil, straight, held at its proximal end and pushed 1.5 mm at
  // 20 mm/s from the sac's centre into the innermost shell (aimed as in
  // DensePacking: 37 deg off the bottom pole, its tip 0.2 mm short of
  // touching): a rod moving through the others, whose candidates must go.
  const double a = 37 * M_PI / 180;
  const Vec3 down(std::sin(a), 0, -std::cos(a));
  const double shell = kSacRadius - 1.1 * kWireRadius - (kShells - 1) * (2 * kWireRadius + kGap);
  def.rods.push_back(pushedCoil((shell - 2 * kWireRadius - 0.2e-3) * down, down, 5e-3));
  Model model = compileModel(def);
  State kept = makeState(model), fresh = kept;
  fresh.contactScratch.keepPairCandidates = false;
  long contacts = 0;
  for (int i = 0; i < 250; ++i) {
    if (i == 50) model.rods.back().constraints[0].velocity = 0.02 * down;
    if (i == 125) model.rods.back().constraints[0].velocity = Vec3::Zero();
    ASSERT_TRUE(step(model, kept).ok()) << "step " << i;
    ASSERT_TRUE(step(model, fresh).ok()) << "step " << i;
    for (size_t k = 0; k < kept.rods.size(); ++k) {
      expectSameContacts(kept.rods[k].contact.self, fresh.rods[k].contact.self, i);
      expectSameContacts(kept.rods[k].contact.rod, fresh.rods[k].contact.rod, i);
      contacts += long(kept.rods[k].contact.self.size() + kept.rods[k].contact.rod.size());
      ASSERT_EQ(kept.rods[k].x, fresh.rods[k].x) << "step " << i << ", rod " << k;
    }
  }
  const PairCandidates &self = kept.contactScratch.selfCandidates, &rod = kept.contactScratch.rodCandidates;
  std::printf("[ measured ] self: built %ld, kept %ld times; between rods: built %ld, kept %ld times; %ld contacts\n",
              self.builds, self.reuses, rod.builds, rod.reuses, contacts);
  EXPECT_GT(contacts, 100000) << "the coils hardly touched: the test would prove nothing";
  EXPECT_GT(self.reuses, self.builds) << "the candidates were hardly kept";
  EXPECT_GT(rod.reuses, rod.builds);
  EXPECT_GE(self.builds, 3) << "the candidates never stopped holding as the coils moved";
  EXPECT_GE(rod.builds, 3);
  EXPECT_EQ(fresh.contactScratch.selfCandidates.builds + fresh.contactScratch.rodCandidates.builds, 0);
}

// Two straight wires crossing 10 um apart (within the contact margin), one
// moved along the other by 20 um a detection, 2 mm in all: the crossing
// walks from segment to segment, so a list that was kept beyond what it
// covers misses the new pair. Reference: the fresh search, and the
// geometry (the wires cross once, mid-segment on one of them: one pair, or
// two where the crossing passes a node of the other).
TEST(DetectRodsCandidates, AWireSlidingAlongAnotherIsFoundAtEveryCrossing) {
  const double r = 0.127e-3, length = 5e-3;
  const Section section = circularSection(r, test::kPlatinumPoisson);
  RodDef a = test::straightRod(length, 10, test::platinum(), section);
  RodDef b = a;
  a.placement = {Vec3(-0.5 * length, 0, 0), Vec3::UnitX(), Vec3::UnitY()};
  b.placement = {Vec3(-1.4e-3, 0.25e-3 - 0.5 * length, 2 * r + 10e-6), Vec3::UnitY(), Vec3::UnitX()};
  const Model model = compileModel(test::modelOf({a, b}, {"rod_contact"}));
  State kept = makeState(model), fresh = kept;
  fresh.contactScratch.keepPairCandidates = false;
  ContactLaw law;
  law.stiffness = 5e4;
  law.radiusScale = 1;
  int crossings = 0, last = -1;
  for (int i = 0; i <= 100; ++i) {
    for (State* s : {&kept, &fresh}) {
      for (Vec3& x : s->rods[1].x) x.x() = -1.4e-3 + 20e-6 * i;
      detectRodContacts(model, *s, 1e-3, false, 0.05e-3, law, law);
    }
    expectSameContacts(kept.rods[0].contact.rod, fresh.rods[0].contact.rod, i);
    ASSERT_GE(kept.rods[0].contact.rod.size(), 1u) << "detection " << i << ": the wires cross within the margin";
    ASSERT_LE(kept.rods[0].contact.rod.size(), 2u) << "detection " << i;
    crossings += kept.rods[0].contact.rod.front().segment != last;
    last = kept.rods[0].contact.rod.front().segment;
  }
  const PairCandidates& c = kept.contactScratch.rodCandidates;
  std::printf("[ measured ] the crossing met %d segments; candidates built %ld, kept %ld times\n", crossings, c.builds,
              c.reuses);
  EXPECT_GE(crossings, 4) << "the crossing did not walk along the wire";
  EXPECT_GT(c.reuses, 0);
  EXPECT_GT(c.builds, 1);
}

}  // namespace
}  // namespace coilsim
