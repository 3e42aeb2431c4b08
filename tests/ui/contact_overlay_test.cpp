// Contact markers: one point per contact, on the centre line where the
// contact is, with an arrow along the force, the largest 3 mm long; the
// panel's max wall force is the largest per-node wall force. Skipped in a
// build whose State has no contact forces.
#include "ui/contact_overlay.h"

#include <gtest/gtest.h>

#include "scenes.h"

namespace coilsim::ui {
namespace {

template <class Rod>
bool addContacts(Rod& r) {
  if constexpr (requires { r.contact.wall.emplace_back().normalForce; r.contact.wallForce; }) {
    auto& a = r.contact.wall.emplace_back();
    a.segment = 3, a.s = 0.25, a.normal = Vec3(0, 0, 1), a.normalForce = 2e-3;
    auto& b = r.contact.self.emplace_back();
    b.segment = 10, b.s = 0.5, b.normal = Vec3(0, 1, 0), b.normalForce = 1e-3;
    r.contact.wallForce.assign(r.x.size(), 0.0);
    r.contact.wallForce[3] = 1.5e-3, r.contact.wallForce[4] = 0.5e-3;
    return true;
  } else {
    return false;
  }
}

TEST(ContactOverlay, MarkersWhereTheContactsAreWithScaledArrows) {
  const Model model = testing::straightRodModel();  // nodes every 0.5 mm along x
  State state = makeState(model);
  if (!addContacts(state.rods[0])) GTEST_SKIP() << "this build's State has no contact forces";
  DrawData data;
  const ContactSummary sum = addContactMarkers(state, 3e-3, data);
  EXPECT_TRUE(sum.available);
  EXPECT_EQ(sum.contacts, 2);
  EXPECT_DOUBLE_EQ(sum.maxWallForce, 1.5e-3);
  ASSERT_EQ(data.points.size(), 2u);
  EXPECT_NEAR((data.points[0].position - Vec3(3.25 * 0.5e-3, 0, 0)).norm(), 0, 1e-15);
  EXPECT_NEAR((data.points[0].vector - Vec3(0, 0, 3e-3)).norm(), 0, 1e-15);  // the largest force
  EXPECT_NEAR((data.points[1].position - Vec3(10.5 * 0.5e-3, 0, 0)).norm(), 0, 1e-15);
  EXPECT_NEAR((data.points[1].vector - Vec3(0, 1.5e-3, 0)).norm(), 0, 1e-15);  // half the force, half as long
  EXPECT_NE(data.points[0].colour, data.points[1].colour);  // wall and self look different
}

TEST(ContactOverlay, NoContactsNoMarkers) {
  const Model model = testing::straightRodModel();
  const State state = makeState(model);
  DrawData data;
  const ContactSummary sum = addContactMarkers(state, 3e-3, data);
  EXPECT_EQ(sum.contacts, 0);
  EXPECT_EQ(sum.maxWallForce, 0.0);
  EXPECT_TRUE(data.points.empty());
}

}  // namespace
}  // namespace coilsim::ui
