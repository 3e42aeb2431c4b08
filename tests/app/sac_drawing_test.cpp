// The neck disc and the legend of sac pictures (app/sac_drawing.h), against
// the geometry of a sphere cut by a plane: the cut is the circle of radius
// sqrt(R^2 - h^2) at distance h from the centre, and the cap beyond it holds
// pi c^2 (3R - c) / 3 of volume (c = R - h). (A test of the graphics file
// set: tests/app/CMakeLists.txt compiles it only with the ui layer.)
#include "app/sac_drawing.h"

#include <gtest/gtest.h>

#include "ui/contact_overlay.h"

#include <cmath>
#include <memory>

namespace coilsim::app {
namespace {

constexpr double kPi = 3.14159265358979323846;

planning::Sac sphereSac(double radius, double neckBelowCentre, int subdivisions) {
  auto mesh = std::make_shared<TriangleMesh>(planning::makeIcosphere(Vec3::Zero(), radius, subdivisions));
  return planning::makeSac(mesh, planning::Plane{Vec3(0, 0, -neckBelowCentre), Vec3::UnitZ()});
}

TEST(SacDrawing, NeckDiscIsTheCircleWhereThePlaneCutsTheSphere) {
  const double R = 3.5e-3, h = 2.5e-3;
  const DrawMesh disc = neckDisc(sphereSac(R, h, 4));
  ASSERT_GE(disc.vertices.size(), 20u);
  ASSERT_EQ(disc.triangles.size(), disc.vertices.size() - 1);  // a fan around the centre
  const double r = std::sqrt(R * R - h * h);
  // The mesh's chords lie inside the sphere: the cut points within a chord's sag of the circle.
  const double sag = 0.02 * R;
  double area = 0;
  for (size_t i = 1; i < disc.vertices.size(); ++i) {
    const Vec3& p = disc.vertices[i];
    EXPECT_NEAR(p.z(), -h, 1e-12);
    EXPECT_NEAR(std::hypot(p.x(), p.y()), r, sag);
  }
  for (const Eigen::Vector3i& t : disc.triangles)
    area += 0.5 * (disc.vertices[size_t(t[1])] - disc.vertices[size_t(t[0])])
                      .cross(disc.vertices[size_t(t[2])] - disc.vertices[size_t(t[0])])
                      .norm();
  EXPECT_NEAR(area, kPi * r * r, 0.05 * kPi * r * r);
}

TEST(SacDrawing, APlaneThatMissesTheSurfaceDrawsNothing) {
  EXPECT_TRUE(neckDisc(sphereSac(3.5e-3, 5e-3, 2)).triangles.empty());
}

TEST(SacDrawing, ABareSphereHasNoParentVesselAndTheLegendSaysSo) {
  // Cap beyond the plane: c = 1 mm of R = 3.5 mm, pi (3R - c) c^2 / 3 = 9.9 mm^3 of 179.6: 6 %.
  const planning::Sac sac = sphereSac(3.5e-3, 2.5e-3, 3);
  EXPECT_FALSE(hasParentVessel(sac));
  bool said = false;
  for (const ui::LegendEntry& e : sacLegend(sac)) said |= e.text.find("no parent vessel") != std::string::npos;
  EXPECT_TRUE(said);
}

// The pictures draw contact markers (ui/contact_overlay.h): the legend
// names both kinds with the colours they are drawn in, and no two entries
// share a colour (the coil-coil markers were once the neck plane's blue).
TEST(SacDrawing, TheLegendNamesTheContactMarkersInTheirOwnColours) {
  const std::vector<ui::LegendEntry> legend = sacLegend(sphereSac(3.5e-3, 2.5e-3, 3));
  int wall = 0, coil = 0;
  for (const ui::LegendEntry& e : legend) {
    wall += e.colour == ui::kWallContactColour && e.text.find("wall contact") != std::string::npos;
    coil += e.colour == ui::kCoilContactColour && e.text.find("coil-coil contact") != std::string::npos;
  }
  EXPECT_EQ(wall, 1);
  EXPECT_EQ(coil, 1);
  for (size_t i = 0; i < legend.size(); ++i)
    for (size_t j = i + 1; j < legend.size(); ++j) {
      if (legend[i].colour.w() == 0 || legend[j].colour.w() == 0) continue;  // text lines
      const Eigen::Vector3f a = legend[i].colour.head<3>(), b = legend[j].colour.head<3>();
      EXPECT_GT((a - b).norm(), 0.25f) << legend[i].text << " and " << legend[j].text << " look alike";
    }
}

TEST(SacDrawing, MoreVolumeBeyondTheNeckThanHalfTheSacCountsAsAVessel) {
  // Cut 0.5 mm above the centre: 57 % of the sphere beyond the plane, 43 % in the sac.
  EXPECT_TRUE(hasParentVessel(sphereSac(3.5e-3, -0.5e-3, 3)));
}

}  // namespace
}  // namespace coilsim::app
