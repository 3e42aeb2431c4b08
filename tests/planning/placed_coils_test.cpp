// Placed coils: their rods go after the definition's, their state comes back
// whole (whatever a RodState carries) but at rest, and a coil placed joins
// them with its pose as it was left.
#include "planning/placed_coils.h"

#include <gtest/gtest.h>

#include <stdexcept>

#include "physics/rest_shape.h"

namespace coilsim::planning {
namespace {

RodDef rod(const std::string& name) {
  RodDef r;
  r.name = name;
  r.length = 0.01;
  r.beams = 10;
  r.rest = makeHelix(r.length, r.beams, 0.003, 0.0003, true);
  r.material = {1e9, 4e8, 20000};
  r.section = circularSection(1e-4, 0.3);
  return r;
}

// A state of `def`'s rod 0 moved off its rest and moving, with contact memory.
RodState movedPose(const ModelDef& def) {
  const Model m = compileModel(def);
  State s = makeState(m);
  RodState r = s.rods[0];
  for (Vec3& x : r.x) x += Vec3(1e-3, 2e-3, 3e-3);
  for (Vec3& v : r.v) v = Vec3(0.1, 0, 0);
  for (Vec3& w : r.w) w = Vec3(0, 0, 5);
  r.contact.wallPenetration = 7e-6;
  r.contact.wallHint.assign(3, 42);
  return r;
}

TEST(PlacedCoils, RodsFollowTheDefinitionsAndComeBackWholeAtRest) {
  ModelDef base;
  base.rods.push_back(rod("first"));
  const RodState pose = movedPose(base);
  const std::vector<PlacedCoil> placed{{rod("a (placed)"), pose}, {rod("b (placed)"), pose}};

  ModelDef def;
  def.rods.push_back(rod("running"));
  const size_t first = addPlacedRods(def, placed);
  ASSERT_EQ(first, 1u);
  ASSERT_EQ(def.rods.size(), 3u);
  EXPECT_EQ(def.rods[2].name, "b (placed)");

  const Model m = compileModel(def);
  State s = makeState(m);
  restorePlacedRods(s, first, placed);
  for (size_t i = 0; i < placed.size(); ++i) {
    const RodState& r = s.rods[first + i];
    EXPECT_EQ(r.x, pose.x);
    EXPECT_EQ(r.activeNodes, pose.activeNodes);
    EXPECT_EQ(r.contact.wallPenetration, pose.contact.wallPenetration);  // copied whole
    EXPECT_EQ(r.contact.wallHint, pose.contact.wallHint);
    for (const Vec3& v : r.v) EXPECT_EQ(v, Vec3::Zero());
    for (const Vec3& w : r.w) EXPECT_EQ(w, Vec3::Zero());
  }
  // The running rod is untouched.
  EXPECT_EQ(s.rods[0].x, makeState(m).rods[0].x);
  // Too few rods for the placed coils: said, not written past the end.
  State small = makeState(compileModel(base));
  EXPECT_THROW(restorePlacedRods(small, 1, placed), std::invalid_argument);
}

TEST(PlacedCoils, KeepingUpdatesThePosesAndAddsTheCoilLeft) {
  ModelDef def;
  def.rods.push_back(rod("running"));
  def.rods.push_back(rod("a (placed)"));
  const Model m = compileModel(def);
  State s = makeState(m);
  std::vector<PlacedCoil> placed{{def.rods[1], s.rods[1]}};
  s.rods[1].x[3] += Vec3(0, 0, 1e-3);  // the placed coil moved while the running one went in
  s.rods[0].x[2] += Vec3(1e-3, 0, 0);
  keepPlacedCoils(def, s, 1, 0, "finishing", placed);
  ASSERT_EQ(placed.size(), 2u);
  EXPECT_EQ(placed[0].pose.x, s.rods[1].x);
  EXPECT_EQ(placed[1].pose.x, s.rods[0].x);
  EXPECT_EQ(placed[1].def.name, "finishing (placed)");
  EXPECT_EQ(placed[1].def.beams, def.rods[0].beams);
}

}  // namespace
}  // namespace coilsim::planning
