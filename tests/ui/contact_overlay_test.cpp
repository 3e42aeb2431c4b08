// Contact markers: one point per contact, on the rod's surface where it
// touches (the centre line minus the rod's radius along the contact normal),
// with an arrow along the force, the largest 3 mm long; the panel's max wall
// force is the largest per-node wall force. Drawn, the markers leave the
// rod's own per-node colour visible across most of its width at every
// contact. Skipped in a build whose State has no contact forces.
#include "ui/contact_overlay.h"

#include <gtest/gtest.h>

#include <cstdlib>

#include "golden.h"
#include "render/backend.h"
#include "render/renderer.h"
#include "scenes.h"

namespace coilsim::ui {
namespace {

// A wall contact at segment 3 and a self contact at segment 10, with the wall's node forces.
void addContacts(RodState& r) {
  auto& a = r.contact.wall.emplace_back();
  a.segment = 3, a.s = 0.25, a.normal = Vec3(0, 0, 1), a.normalForce = 2e-3;
  auto& b = r.contact.self.emplace_back();
  b.segment = 10, b.s = 0.5, b.normal = Vec3(0, 1, 0), b.normalForce = 1e-3;
  r.contact.wallForce.assign(r.x.size(), 0.0);
  r.contact.wallForce[3] = 1.5e-3, r.contact.wallForce[4] = 0.5e-3;
}

TEST(ContactOverlay, MarkersWhereTheContactsAreWithScaledArrows) {
  const Model model = testing::straightRodModel();  // nodes every 0.5 mm along x, radius 0.25 mm
  State state = makeState(model);
  addContacts(state.rods[0]);
  DrawData data;
  const ContactSummary sum = addContactMarkers(model, state, 3e-3, data);
  EXPECT_TRUE(sum.available);
  EXPECT_EQ(sum.contacts, 2);
  EXPECT_DOUBLE_EQ(sum.maxWallForce, 1.5e-3);
  ASSERT_EQ(data.points.size(), 2u);
  // On the surface, on the side the force comes from: the wall below (+z force), the other segment at -y.
  EXPECT_NEAR((data.points[0].position - Vec3(3.25 * 0.5e-3, 0, -0.25e-3)).norm(), 0, 1e-15);
  EXPECT_NEAR((data.points[0].vector - Vec3(0, 0, 3e-3)).norm(), 0, 1e-15);  // the largest force
  EXPECT_NEAR((data.points[1].position - Vec3(10.5 * 0.5e-3, -0.25e-3, 0)).norm(), 0, 1e-15);
  EXPECT_NEAR((data.points[1].vector - Vec3(0, 1.5e-3, 0)).norm(), 0, 1e-15);  // half the force, half as long
  EXPECT_NE(data.points[0].colour, data.points[1].colour);  // wall and self look different
  EXPECT_DOUBLE_EQ(contactMarkerRadius(model), 0.6 * 0.25e-3);
}

// The rod coloured per node (blue to red), contacts at five segments with
// the wall above or below, seen from the side (AP: the normals in the
// picture's plane) with the window's marker size, against the same rod
// drawn without markers: in every column of the picture, at most half of
// the rod's pixels change. Markers at the centre line, 1.6 times as wide as
// the rod (as they were drawn before), changed all of them at each contact.
TEST(ContactOverlay, MarkersLeaveTheRodsColourVisible) {
  const Model model = testing::straightRodModel();
  State state = makeState(model);
  addContacts(state.rods[0]);
  RodState& r = state.rods[0];
  r.contact.wall.clear();
  r.contact.self.clear();
  for (int seg : {2, 6, 9, 13, 17}) {
    auto& c = r.contact.wall.emplace_back();
    c.segment = seg, c.s = 0.5, c.normal = Vec3(0, 0, seg % 2 ? -1.0 : 1.0), c.normalForce = 1e-3 * (1 + seg % 3);
  }
  const DrawData bare = testing::rodDrawData(model, state);
  DrawData marked = bare;
  addContactMarkers(model, state, 3e-3, marked);
  ASSERT_EQ(marked.points.size(), 5u);

  constexpr int w = 480, h = 320;
  std::string error;
  render::BackendOptions bo;
  bo.width = w, bo.height = h;
  const auto backend = render::createBackend("osmesa", bo, error);
  ASSERT_NE(backend, nullptr) << error;
  render::Renderer renderer;
  ASSERT_TRUE(renderer.init(error)) << error;
  render::RenderSettings settings;
  settings.pointRadius = contactMarkerRadius(model);
  render::Camera camera = render::apView(render::Camera{});
  render::fitCamera(camera, render::boundsOf(bare), render::ViewMode::Shaded, w, h);
  auto draw = [&](const DrawData& d, const DrawData& points) {
    DrawData all = d;
    all.points = points.points;
    EXPECT_TRUE(renderer.render(all, camera, settings, w, h, error)) << error;
    render::Image image;
    EXPECT_TRUE(renderer.readFrame(image));
    return image;
  };
  const render::Image empty = draw(DrawData{}, DrawData{}), without = draw(bare, DrawData{}),
                      with = draw(bare, marked);
  auto differ = [](const std::uint8_t* a, const std::uint8_t* b) {
    return std::abs(a[0] - b[0]) > 30 || std::abs(a[1] - b[1]) > 30 || std::abs(a[2] - b[2]) > 30;
  };
  int columns = 0, worst = 0;
  double worstShare = 0;
  for (int x = 0; x < w; ++x) {
    int rod = 0, changed = 0;
    for (int y = 0; y < h; ++y) {
      if (!differ(without.at(x, y), empty.at(x, y))) continue;  // background
      ++rod;
      changed += differ(with.at(x, y), without.at(x, y));
    }
    if (rod < 10) continue;  // the rod's rounded ends
    ++columns;
    const double share = double(changed) / rod;
    if (share > worstShare) worstShare = share, worst = x;
  }
  EXPECT_GT(columns, 300);  // the rod spans the picture
  EXPECT_LE(worstShare, 0.5) << "column " << worst << ": " << 100 * worstShare << " % of the rod's pixels hidden";
  EXPECT_TRUE(testing::matchesGolden(with, "contact_markers_on_rod"));
}

TEST(ContactOverlay, NoContactsNoMarkers) {
  const Model model = testing::straightRodModel();
  const State state = makeState(model);
  DrawData data;
  const ContactSummary sum = addContactMarkers(model, state, 3e-3, data);
  EXPECT_EQ(sum.contacts, 0);
  EXPECT_EQ(sum.maxWallForce, 0.0);
  EXPECT_TRUE(data.points.empty());
}

}  // namespace
}  // namespace coilsim::ui
