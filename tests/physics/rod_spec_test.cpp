// Tests of a rod's description before sampling (src/physics/rod_spec.cpp and
// makeRest in src/physics/rest_shape.cpp).
// References: solid circle A = pi r^2, I = pi r^4 / 4, J = 2 I, Cowper's
// shear factor 6 (1 + nu) / (7 + 6 nu) (Cowper 1966, J. Appl. Mech. 33:335);
// isotropic G = E / (2 (1 + nu)); a helix's loop diameter is the diameter of
// the cylinder its points lie on, its pitch the rise per turn.
#include <gtest/gtest.h>

#include <cmath>

#include "physics/rod_spec.h"

namespace coilsim::test {
namespace {

TEST(RodSpec, CircularWireGivesTheSolidCircleSection) {
  RodSpec rod;
  rod.wireRadius = 0.15e-3;
  rod.poissonRatio = 0.39;
  const double r = 0.15e-3, nu = 0.39;
  const Section s = sectionOf(rod);
  EXPECT_NEAR(s.area, M_PI * r * r, 1e-24);
  EXPECT_NEAR(s.iy, M_PI * std::pow(r, 4) / 4, 1e-30);
  EXPECT_NEAR(s.iz, s.iy, 0);
  EXPECT_NEAR(s.torsion, M_PI * std::pow(r, 4) / 2, 1e-30);
  EXPECT_NEAR(s.shearFactor, 6 * (1 + nu) / (7 + 6 * nu), 1e-15);
  EXPECT_EQ(s.radius, r);
}

TEST(RodSpec, ExplicitSectionIsKeptWhenThereIsNoWireRadius) {
  RodSpec rod;
  rod.explicitSection = {2e-7, 3e-14, 4e-14, 5e-14, 0.5, 0.3e-3};
  rod.poissonRatio = 0.39;  // does not enter explicit constants
  const Section s = sectionOf(rod);
  EXPECT_EQ(s.area, 2e-7);
  EXPECT_EQ(s.iy, 3e-14);
  EXPECT_EQ(s.iz, 4e-14);
  EXPECT_EQ(s.torsion, 5e-14);
  EXPECT_EQ(s.shearFactor, 0.5);
  EXPECT_EQ(s.radius, 0.3e-3);
}

TEST(RodSpec, MaterialAndMassPerLengthFromTheConstants) {
  RodSpec rod;
  rod.youngModulus = 7.5e9;
  rod.poissonRatio = 0.25;
  rod.density = 21450;
  rod.wireRadius = 0.1e-3;
  const Material m = materialOf(rod);
  EXPECT_EQ(m.youngModulus, 7.5e9);
  EXPECT_NEAR(m.shearModulus, 3e9, 1e-3);  // 7.5 / 2.5 GPa
  EXPECT_EQ(m.density, 21450);
  EXPECT_NEAR(massPerLength(rod), 21450 * M_PI * 1e-8, 1e-15);
}

TEST(RodSpec, HelixRestShapeHasItsLoopDiameterAndPitch) {
  RestShapeDef helix;
  helix.type = RestShapeDef::Type::Helix;
  helix.loopDiameter = 7e-3;
  helix.pitch = 2e-3;
  const double length = 0.06;
  const RestCurve c = makeRest(helix, length, 240);
  ASSERT_EQ(c.points.size(), 241u);
  // The axis of the canonical helix: the mean of one full turn's points
  // lies on it, and it runs along the net rise of whole turns.
  const double turn = std::hypot(M_PI * 7e-3, 2e-3);  // arc length of one loop
  const int perTurn = int(std::lround(240 * turn / length));
  Vec3 centre0 = Vec3::Zero(), centre1 = Vec3::Zero();
  for (int i = 0; i < perTurn; ++i) centre0 += c.points[i], centre1 += c.points[i + perTurn];
  centre0 /= perTurn, centre1 /= perTurn;
  const Vec3 axis = (centre1 - centre0).normalized();
  EXPECT_NEAR((centre1 - centre0).norm(), 2e-3, 0.02e-3);
  for (int i = 0; i < perTurn; ++i) {
    const Vec3 d = c.points[i] - centre0;
    EXPECT_NEAR((d - d.dot(axis) * axis).norm(), 3.5e-3, 0.02e-3) << "point " << i;
  }
}

TEST(RodSpec, StraightRestShapeIsAStraightLineOfTheLength) {
  const RestCurve c = makeRest(RestShapeDef{}, 0.05, 10);
  ASSERT_EQ(c.points.size(), 11u);
  EXPECT_NEAR((c.points.back() - c.points.front()).norm(), 0.05, 1e-15);
  for (const Vec3& p : c.points) EXPECT_NEAR(p.y() * p.y() + p.z() * p.z(), 0, 1e-30);
}

TEST(RodSpec, PolylineTooShortIsRefused) {
  RestShapeDef line;
  line.type = RestShapeDef::Type::Polyline;
  line.points = {Vec3::Zero()};
  EXPECT_THROW(makeRest(line, 0.05, 10), std::invalid_argument);
}

}  // namespace
}  // namespace coilsim::test
