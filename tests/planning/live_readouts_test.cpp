// Live read-outs of a manual deployment: the protrusion and wall-force
// warnings appear exactly when the geometry and the contact forces say so.
#include "planning/live_readouts.h"

#include <gtest/gtest.h>

#include "physics/contact/wall_load.h"
#include "planning/practice.h"

namespace coilsim::planning {
namespace {

const std::string kCase = std::string(COILSIM_SOURCE_DIR) + "/scenes/cases/sphere-7mm-wide-neck.json";

const LiveLine* find(const std::vector<LiveLine>& lines, const std::string& label) {
  for (const LiveLine& l : lines)
    if (l.label == label) return &l;
  return nullptr;
}

TEST(LiveReadouts, WarnWhenTheCoilProtrudesAndWhenTheWallLoadPassesTheThreshold) {
  const PracticeCase pc = loadCase(kCase);  // 3.5 mm sphere, neck plane z = -2.5 mm, safety threshold 100 mN
  PracticeSession session(pc, "finishing-2x10");
  ASSERT_EQ(session.command({DeviceCommand::Kind::Push, 10e-3, 4e-3}), "");
  for (int s = 0; s < 500; ++s) ASSERT_TRUE(session.step());
  const Model& model = session.model();
  State state = session.state();
  const Deployment& dep = session.deployment();
  LiveReadouts live(pc, dep);
  live.interval = 0;  // recompute on every call

  // 4 mm out of the tip 0.5 mm inside the neck, pointing into the sac: in the sac, no warning.
  std::vector<LiveLine> lines = live.lines(model, state);
  ASSERT_NE(find(lines, "protrusion"), nullptr);
  EXPECT_FALSE(find(lines, "protrusion")->warning);
  EXPECT_GT(live.metrics().coilLengthInSac, 3.5e-3);
  ASSERT_NE(find(lines, "wall load"), nullptr) << "the sac is a wall in practice";
  EXPECT_FALSE(find(lines, "wall load")->warning);

  // Lay the coil's nodes on a 2 mm circle 0.6 mm below the neck plane (inside the sphere's cap,
  // which stands for the parent vessel): more than 0.5 mm of coil beyond the neck, a protrusion.
  RodState& chain = state.rods[size_t(dep.chainRod)];
  const int first = dep.tipNode + 1, n = chain.activeNodes - first;
  for (int i = 0; i < n; ++i) {
    const double a = 2 * M_PI * i / n;
    chain.x[size_t(first + i)] = Vec3(1e-3 * std::cos(a), 1e-3 * std::sin(a), -3.1e-3);
  }
  lines = live.lines(model, state);
  ASSERT_NE(find(lines, "PROTRUSION"), nullptr);
  EXPECT_TRUE(find(lines, "PROTRUSION")->warning);
  EXPECT_GT(live.metrics().protrudingLength, 0.5e-3);

  // A node pressed on the wall with 0.2 N for one step (a penalty spike): not a load yet.
  chain.contact.wallForce.assign(chain.x.size(), 0.0);
  state.stats.wallLoad = {};
  const int window = wallLoadSteps(model.timeStep);
  ASSERT_GT(window, 1);
  chain.contact.wallForce[size_t(first + 1)] = 0.2;
  recordWallLoad(model, state);
  lines = live.lines(model, state);
  EXPECT_EQ(find(lines, "WALL LOAD"), nullptr);
  // Held for the whole window (5 ms): above the case's 100 mN threshold.
  for (int s = 1; s < window; ++s) recordWallLoad(model, state);
  lines = live.lines(model, state);
  ASSERT_NE(find(lines, "WALL LOAD"), nullptr);
  EXPECT_TRUE(find(lines, "WALL LOAD")->warning);
  EXPECT_DOUBLE_EQ(live.wallLoadNow(), 0.2);
  // Back below it: the warning for now goes, the largest so far stays flagged.
  chain.contact.wallForce[size_t(first + 1)] = 0.01;
  for (int s = 0; s < window; ++s) recordWallLoad(model, state);
  lines = live.lines(model, state);
  EXPECT_FALSE(find(lines, "wall load")->warning);
  EXPECT_TRUE(find(lines, "largest wall load")->warning);
  EXPECT_DOUBLE_EQ(live.wallLoadMax(), 0.2);
}

}  // namespace
}  // namespace coilsim::planning
