// Polygonised implicit surfaces are closed, oriented and have the topology
// of the solid (Euler characteristic).
#include "geometry/marching_tets.h"

#include <gtest/gtest.h>

#include <stdexcept>

#include "geometry/mesh_report.h"
#include "geometry/volume.h"
#include "support/tolerance.h"

namespace coilsim::geometry {
namespace {

long euler(const MeshReport& r) { return long(r.vertices) - long(r.edges) + long(r.triangles); }

TEST(MarchingTets, TorusIsClosedWithGenusOne) {
  const double R = 3, a = 1;
  const auto torus = [&](const Vec3& p) { return std::hypot(std::hypot(p.x(), p.y()) - R, p.z()) - a; };
  const TriangleMesh m = polygonise(torus, Vec3(-5, -5, -2), Vec3(5, 5, 2), 0.1);
  const MeshReport r = analyseMesh(m);
  EXPECT_TRUE(r.usable()) << (describeProblems(r).empty() ? "" : describeProblems(r).front());
  EXPECT_EQ(r.components, 1u);
  EXPECT_EQ(euler(r), 0) << "a torus has Euler characteristic 0";
  // Pappus: 2 pi R * pi a^2.
  EXPECT_TRUE(test::nearRel("torus volume", r.volume, 2 * M_PI * R * M_PI * a * a, {0.01, "h/a = 0.1"}));
}

TEST(MarchingTets, TwoBallsAreTwoSphereLikeComponents) {
  const auto balls = [](const Vec3& p) {
    return std::min((p - Vec3(-2, 0, 0)).norm() - 1, (p - Vec3(2, 0.1, 0)).norm() - 1.3);
  };
  const MeshReport r = analyseMesh(polygonise(balls, Vec3(-4, -2, -2), Vec3(4, 2, 2), 0.15));
  EXPECT_TRUE(r.usable());
  EXPECT_EQ(r.components, 2u);
  EXPECT_EQ(euler(r), 4) << "two spheres: 2 + 2";
}

TEST(MarchingTets, SamplesExactlyOnTheSurfaceStayManifold) {
  // The cube [-1, 1]^3 as max-norm: its faces fall exactly on grid planes.
  const auto box = [](const Vec3& p) { return p.cwiseAbs().maxCoeff() - 1.0; };
  const double h = 0.25;
  const MeshReport r = analyseMesh(polygonise(box, Vec3::Constant(-2), Vec3::Constant(2), h));
  EXPECT_TRUE(r.usable());
  EXPECT_EQ(euler(r), 2);
  // Faces on grid planes are kept (but for the 1e-4 h nudge); edges may be
  // chamfered by one tetrahedron: at most h^2/2 per unit length of 12 edges.
  EXPECT_LE(r.volume, 8.0);
  EXPECT_GE(r.volume, 8.0 - 12 * 2 * h * h / 2);
}

TEST(MarchingTets, RefusesBadInput) {
  const auto ball = [](const Vec3& p) { return p.norm() - 1; };
  EXPECT_THROW(polygonise(ball, Vec3::Constant(-0.5), Vec3::Constant(0.5), 0.1), std::invalid_argument);
  EXPECT_THROW(polygonise(ball, Vec3::Constant(-2), Vec3::Constant(2), 0), std::invalid_argument);
  EXPECT_THROW(polygonise(ball, Vec3::Constant(-2), Vec3::Constant(2), 1e-4), std::invalid_argument);
  EXPECT_THROW(polygonise(ball, Vec3::Constant(2), Vec3::Constant(-2), 0.1), std::invalid_argument);
}

}  // namespace
}  // namespace coilsim::geometry
