// Contact detection split over two threads (physics/contact/detect_parallel.h).
// Reference: the same run on one thread. Splitting must not change a bit:
// every step's wall, self and rod contact lists and every pose and velocity
// are compared for equality, not within a tolerance.
#include <gtest/gtest.h>

#include <memory>

#include "physics/contact/detect.h"
#include "physics/deployment.h"
#include "physics/run.h"
#include "support/coil_spec.h"
#include "support/meshes.h"
#include "support/refusal.h"
#include "support/rod_models.h"

namespace coilsim {
namespace {

// A coil pushed into a 7 mm spherical cavity from a catheter whose drawn
// tube is a rod of its own: wall contacts, self-contacts of the loops, and
// rod contacts between the coil and the catheter.
struct Cavity {
  Model model;
  State state;
};

// rigid: the wall holds each node by a constraint instead of the penalty.
std::unique_ptr<Cavity> cavity(double coilLength, int beams, bool rigid = false) {
  auto c = std::make_unique<Cavity>();
  ModelDef def;
  def.gravity = Vec3(0, 0, -9.81);
  def.damping.massCoeff = 20;
  def.timeStep = 1e-3;
  for (const char* name : {"gravity", "wall_contact", "self_contact", "rod_contact"})
    def.effects.push_back(EffectRegistry::global().use(name));
  for (EffectUse& e : def.effects)
    if (e.name() == "wall_contact") e.set("rigid", rigid ? 1.0 : 0.0);
  def.obstacles.push_back(test::obstacleOf(test::icosphere(3.5e-3, 4)));
  DeploymentDef d;
  d.coil = test::wireSpec(coilLength, test::helixRest(6e-3, 0.4e-3), 7.5e9, test::kPlatinumPoisson, 21450, 0.15e-3);
  d.coilBeams = beams;
  d.tip.position = Vec3(0, 0, -2.5e-3);
  d.tip.direction = Vec3(0, 0, 1);
  d.tip.normal = Vec3(1, 0, 0);
  d.catheterDrawLength = 2e-3;
  def.device = d;
  c->model = compileModel(def);
  c->state = makeState(c->model);
  resetDevice(c->model, c->state, 0.0, 0.0);
  return c;
}

void expectSameContacts(const std::vector<ContactPoint>& a, const std::vector<ContactPoint>& b, const char* kind, int step) {
  ASSERT_EQ(a.size(), b.size()) << kind << ", step " << step;
  for (size_t j = 0; j < a.size(); ++j) {
    ASSERT_EQ(a[j].segment, b[j].segment) << kind << ", step " << step;
    ASSERT_EQ(a[j].other, b[j].other) << kind << ", step " << step;
    ASSERT_EQ(a[j].otherSegment, b[j].otherSegment) << kind << ", step " << step;
    ASSERT_EQ(a[j].node, b[j].node) << kind << ", step " << step;
    ASSERT_EQ(a[j].s, b[j].s) << kind << ", step " << step;
    ASSERT_EQ(a[j].gap, b[j].gap) << kind << ", step " << step;
    ASSERT_EQ(a[j].normal, b[j].normal) << kind << ", step " << step;
    ASSERT_EQ(a[j].anchor, b[j].anchor) << kind << ", step " << step;
    ASSERT_EQ(a[j].normalForce, b[j].normalForce) << kind << ", step " << step;
    ASSERT_EQ(a[j].slip, b[j].slip) << kind << ", step " << step;
  }
}

// One push of a coil into the cavity, once with detection on one thread and
// once split over two (every detection, whatever its size): the same
// contacts in the same order and the same states, bit for bit. Under both
// wall laws, each of which takes the coil its own way. 40 mm: the loops
// meet under both (at 30 mm under the penalty only: 652 and 0
// self-contacts, the constraint's path keeps the first loops apart; at
// 40 mm 6272 and 1342).
class DetectParallelTest : public ::testing::TestWithParam<bool> {};

TEST_P(DetectParallelTest, TwoThreadsFindExactlyTheContactsOfOne) {
  const double length = 0.04, speed = 0.01;
  auto one = cavity(length, 80, GetParam());
  State two = one->state;
  two.contactScratch.threads.setCount(2);
  two.contactScratch.threads.minSegmentsToSplit = 0;
  ASSERT_EQ(test::refusal(command(one->model, one->state, {DeviceCommand::Kind::Push, speed, length})), "");
  ASSERT_EQ(test::refusal(command(one->model, two, {DeviceCommand::Kind::Push, speed, length})), "");
  long wall = 0, self = 0, rod = 0;
  const int steps = int(length / speed / one->model.timeStep) + 200;
  for (int i = 0; i < steps; ++i) {
    ASSERT_TRUE(advance(one->model, one->state).ok()) << "step " << i;
    ASSERT_TRUE(advance(one->model, two).ok()) << "step " << i;
    ASSERT_EQ(one->state.rods.size(), two.rods.size());
    for (size_t k = 0; k < two.rods.size(); ++k) {
      const RodState &a = one->state.rods[k], &b = two.rods[k];
      expectSameContacts(a.contact.wall, b.contact.wall, "wall", i);
      expectSameContacts(a.contact.self, b.contact.self, "self", i);
      expectSameContacts(a.contact.rod, b.contact.rod, "rod", i);
      ASSERT_EQ(a.x, b.x) << "step " << i << ", rod " << k;
      ASSERT_EQ(a.v, b.v) << "step " << i << ", rod " << k;
      ASSERT_EQ(a.w, b.w) << "step " << i << ", rod " << k;
      for (size_t n = 0; n < a.q.size(); ++n) ASSERT_EQ(a.q[n].coeffs(), b.q[n].coeffs()) << "step " << i;
      wall += long(a.contact.wall.size()), self += long(a.contact.self.size()), rod += long(a.contact.rod.size());
    }
  }
  EXPECT_EQ(one->state.substepped, two.substepped);
  // Not vacuous: every kind of contact was found, and the detections were split.
  EXPECT_GT(wall, 1000);
  EXPECT_GT(self, 300);
  EXPECT_GT(rod, 0);
  EXPECT_GT(two.contactScratch.threads.splits(), steps);
  EXPECT_EQ(one->state.contactScratch.threads.splits(), 0);
}

INSTANTIATE_TEST_SUITE_P(WallLaw, DetectParallelTest, ::testing::Values(false, true),
                         [](const ::testing::TestParamInfo<bool>& i) { return i.param ? "Constraint" : "Penalty"; });

// A copied State (a plan candidate, a snapshot) keeps the thread count but
// never shares the thread: both copies step on, alone and alike.
TEST(DetectParallelCopyTest, ACopiedStateStepsWithAThreadOfItsOwn) {
  auto c = cavity(0.01, 20);
  c->state.contactScratch.threads.setCount(2);
  c->state.contactScratch.threads.minSegmentsToSplit = 0;
  ASSERT_EQ(test::refusal(command(c->model, c->state, {DeviceCommand::Kind::Push, 0.01, 0.01})), "");
  for (int i = 0; i < 300; ++i) ASSERT_TRUE(advance(c->model, c->state).ok());
  State copy = c->state;
  EXPECT_EQ(copy.contactScratch.threads.count(), 2);
  for (int i = 0; i < 300; ++i) {
    ASSERT_TRUE(advance(c->model, c->state).ok());
    ASSERT_TRUE(advance(c->model, copy).ok());
    ASSERT_EQ(c->state.rods[0].x, copy.rods[0].x) << "step " << i;
  }
  EXPECT_GT(copy.contactScratch.threads.splits(), 0);
}

}  // namespace
}  // namespace coilsim
