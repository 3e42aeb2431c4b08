// The morphology of a sac against closed forms: a sphere cut by a plane
// (spherical cap: volume pi h^2 (3R - h) / 3 with h the cap height, neck a
// circle of radius sqrt(R^2 - s^2), s the centre's height above the plane).
#include "geometry/sac_morphology.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "support/meshes.h"

namespace coilsim::geometry {
namespace {

// An icosphere's vertices lie on the sphere; at 5 subdivisions its faces sag
// by < 0.05 % of R, so lengths agree to 0.3 % and the volume to 0.5 %.
constexpr double kLength = 3e-3, kVolume = 5e-3;

struct Cut {
  double s;      // centre height above the plane, in radii
  Vec3 normal;   // of the plane, toward the dome
};

class SphereCap : public testing::TestWithParam<Cut> {};

TEST_P(SphereCap, MatchesClosedForms) {
  const double R = 3.5;
  const Vec3 centre(1.0, -2.0, 0.5);
  const Vec3 n = GetParam().normal.normalized();
  const double s = GetParam().s * R;
  const TriangleMesh sphere = test::icosphere(R, 5, centre);
  const Plane plane{centre - s * n, n};
  const double vessel = 2.0;  // mm, a parent vessel's diameter
  const SacMorphology m = measureSac(sphere, plane, centre, vessel);

  const double h = R + s, neck = 2 * std::sqrt(R * R - s * s);
  const double across = s >= 0 ? 2 * R : neck;  // widest parallel to the plane
  EXPECT_NEAR(m.volume, M_PI * h * h * (3 * R - h) / 3, kVolume * m.volume);
  EXPECT_NEAR(m.neckWidth, neck, kLength * neck);
  EXPECT_NEAR(m.neckArea, M_PI * (R * R - s * s), 2 * kLength * m.neckArea);
  EXPECT_NEAR(m.domeHeight, h, kLength * h);
  EXPECT_NEAR(m.maxHeight, s >= 0 ? h : neck / 2, kLength * R);  // farthest from the neck's centre: top, or rim
  EXPECT_NEAR(m.width, across, kLength * across);
  EXPECT_NEAR(m.depth, across, kLength * across);
  EXPECT_NEAR(m.maxDiameter, across, kLength * across);
  EXPECT_NEAR(m.meanDiameter, (h + 2 * across) / 3, kLength * R);
  EXPECT_NEAR(m.aspectRatio, h / neck, 2 * kLength * h / neck);
  EXPECT_NEAR(m.domeToNeck, across / neck, 2 * kLength * across / neck);
  EXPECT_NEAR(m.sizeRatio, m.maxHeight / vessel, 1e-12);
  EXPECT_LT((m.neckCentre - plane.point).norm(), kLength * R);
}

INSTANTIATE_TEST_SUITE_P(Cuts, SphereCap,
                         testing::Values(Cut{0.6, Vec3::UnitZ()}, Cut{0.3, Vec3(1, 2, -0.5)}, Cut{0.0, Vec3(0, -1, 1)},
                                         Cut{-0.4, Vec3(-0.3, 0.2, 1)}));

// Two spheres above one plane: only the piece holding the given point counts.
TEST(SacMorphology, MeasuresOnlyThePieceHoldingThePoint) {
  TriangleMesh two = test::icosphere(3, 4, Vec3(0, 0, 2));
  const TriangleMesh other = test::icosphere(2, 4, Vec3(10, 0, 1));
  const int base = int(two.vertices.size());
  for (const Vec3& v : other.vertices) two.vertices.push_back(v);
  for (const auto& t : other.triangles) two.triangles.push_back(t + Eigen::Vector3i::Constant(base));
  const Plane plane{Vec3::Zero(), Vec3::UnitZ()};
  const SacMorphology a = measureSac(two, plane, Vec3(0, 0, 2), 0);
  const SacMorphology b = measureSac(two, plane, Vec3(10, 0, 1), 0);
  const auto cap = [](double R, double s) { return M_PI * (R + s) * (R + s) * (2 * R - s) / 3; };
  EXPECT_NEAR(a.volume, cap(3, 2), 0.01 * a.volume);
  EXPECT_NEAR(b.volume, cap(2, 1), 0.01 * b.volume);
  EXPECT_EQ(a.sizeRatio, 0);
}

TEST(SacMorphology, NothingAboveThePlaneMeasuresZero) {
  const SacMorphology m = measureSac(test::icosphere(1, 2), Plane{Vec3(0, 0, 2), Vec3::UnitZ()}, Vec3::Zero(), 1);
  EXPECT_EQ(m.volume, 0);
  EXPECT_EQ(m.triangles, 0u);
}

// The piece measured is the one highlighted: on a sphere cut by a plane, the
// triangles flagged are exactly those with a vertex above the plane (one
// piece), all within the sphere's radius of its centre.
TEST(SacPiece, IsTheTrianglesReachingAboveThePlane) {
  const double R = 3.5;
  const Vec3 centre(1.0, -2.0, 0.5);
  const TriangleMesh sphere = test::icosphere(R, 4, centre);
  const Plane plane{centre - 1.0 * Vec3::UnitZ(), Vec3::UnitZ()};
  const std::vector<char> piece = sacPiece(sphere, plane, centre);
  ASSERT_EQ(piece.size(), sphere.triangles.size());
  size_t flagged = 0;
  for (size_t t = 0; t < piece.size(); ++t) {
    bool above = false;
    for (int k = 0; k < 3; ++k) above |= plane.side(sphere.vertices[sphere.triangles[t][k]]) > 0;
    EXPECT_EQ(bool(piece[t]), above) << t;
    flagged += piece[t];
  }
  EXPECT_EQ(flagged, measureSac(sphere, plane, centre, 0).triangles);
  // Above the top: nothing.
  const std::vector<char> none = sacPiece(sphere, {centre + 2 * R * Vec3::UnitZ(), Vec3::UnitZ()}, centre);
  EXPECT_EQ(std::count(none.begin(), none.end(), char(1)), 0);
}

}  // namespace
}  // namespace coilsim::geometry
