// Topology checks and safe repairs on hand-built good and broken cubes.
#include "geometry/mesh_report.h"

#include <gtest/gtest.h>

#include "geometry/shapes.h"
#include "support/tolerance.h"

namespace coilsim::geometry {
namespace {

using test::unitCube;

TEST(MeshReport, CubeIsClosedOrientedOutwardWithUnitVolume) {
  const MeshReport r = analyseMesh(unitCube());
  EXPECT_EQ(r.vertices, 8u);
  EXPECT_EQ(r.triangles, 12u);
  EXPECT_EQ(r.edges, 18u);  // Euler: V - E + F = 2 for a sphere-like surface
  EXPECT_EQ(r.boundaryEdges, 0u);
  EXPECT_EQ(r.nonManifoldEdges, 0u);
  EXPECT_EQ(r.misorientedEdges, 0u);
  EXPECT_EQ(r.components, 1u);
  EXPECT_TRUE(r.closed());
  EXPECT_TRUE(r.oriented());
  EXPECT_TRUE(r.outward());
  EXPECT_TRUE(r.usable());
  EXPECT_TRUE(test::nearAbs("cube volume", r.volume, 1.0, test::roundoff(1, 100, "12 triple products")));
  EXPECT_EQ(r.lower, Vec3::Zero());
  EXPECT_EQ(r.upper, Vec3::Ones());
  EXPECT_TRUE(describeProblems(r).empty());
}

TEST(MeshReport, MissingFaceLeavesFourBoundaryEdges) {
  TriangleMesh m = unitCube();
  m.triangles.resize(10);  // drop the last face (two triangles)
  const MeshReport r = analyseMesh(m);
  EXPECT_EQ(r.boundaryEdges, 4u);
  EXPECT_FALSE(r.closed());
  EXPECT_FALSE(r.usable());
  const RepairResult fix = repairMesh(m);
  EXPECT_FALSE(fix.usable);
  EXPECT_NE(fix.reason.find("holes"), std::string::npos) << fix.reason;
}

TEST(MeshReport, FlippedTriangleIsClosedButNotOrientedAndIsRepaired) {
  TriangleMesh m = unitCube();
  std::swap(m.triangles[3][1], m.triangles[3][2]);
  const MeshReport r = analyseMesh(m);
  EXPECT_TRUE(r.closed());
  EXPECT_EQ(r.misorientedEdges, 3u);  // all three edges of the flipped triangle
  EXPECT_FALSE(r.oriented());
  const RepairResult fix = repairMesh(m);
  ASSERT_TRUE(fix.usable) << fix.reason;
  EXPECT_TRUE(fix.report.oriented());
  EXPECT_TRUE(test::nearAbs("repaired volume", fix.report.volume, 1.0, test::roundoff(1, 100, "triple products")));
  ASSERT_EQ(fix.actions.size(), 1u);
}

TEST(MeshReport, InsideOutCubeIsFlipped) {
  TriangleMesh m = unitCube();
  for (auto& t : m.triangles) std::swap(t[1], t[2]);
  const MeshReport r = analyseMesh(m);
  EXPECT_TRUE(r.closed());
  EXPECT_TRUE(r.oriented());
  EXPECT_FALSE(r.outward());
  EXPECT_LT(r.volume, 0);
  EXPECT_FALSE(describeProblems(r).empty());
  const RepairResult fix = repairMesh(m);
  ASSERT_TRUE(fix.usable) << fix.reason;
  EXPECT_GT(fix.report.volume, 0.999);
}

TEST(MeshReport, FinOnAnEdgeIsNonManifoldAndRefused) {
  TriangleMesh m = unitCube();
  // A third triangle on the cube's edge 0-1, sticking out below.
  m.vertices.push_back(Vec3(0.5, -1, -1));
  m.triangles.emplace_back(0, 1, 8);
  const MeshReport r = analyseMesh(m);
  EXPECT_EQ(r.nonManifoldEdges, 1u);
  EXPECT_FALSE(r.closed());
  EXPECT_FALSE(r.oriented());
  const RepairResult fix = repairMesh(m);
  EXPECT_FALSE(fix.usable);
  EXPECT_NE(fix.reason.find("non-manifold"), std::string::npos) << fix.reason;
}

TEST(MeshReport, UnindexedTrianglesAreWeldedIntoAClosedCube) {
  // As an STL stores it: three own vertices per triangle.
  const TriangleMesh cube = unitCube();
  TriangleMesh soup;
  for (const auto& t : cube.triangles) {
    const int base = int(soup.vertices.size());
    for (int k = 0; k < 3; ++k) soup.vertices.push_back(cube.vertices[t[k]]);
    soup.triangles.emplace_back(base, base + 1, base + 2);
  }
  const MeshReport r = analyseMesh(soup);
  EXPECT_EQ(r.boundaryEdges, 36u);
  EXPECT_EQ(r.components, 12u);
  const RepairResult fix = repairMesh(soup);
  ASSERT_TRUE(fix.usable) << fix.reason;
  EXPECT_EQ(fix.report.vertices, 8u);
  EXPECT_EQ(fix.report.components, 1u);
}

TEST(MeshReport, NearlyCoincidentVerticesWeldOnlyWithinTolerance) {
  TriangleMesh m = unitCube();
  // Split vertex 7 into a copy 1e-7 away used by two of its triangles.
  m.vertices.push_back(m.vertices[7] + Vec3(1e-7, 0, 0));
  int replaced = 0;
  for (auto& t : m.triangles)
    for (int k = 0; k < 3 && replaced < 2; ++k)
      if (t[k] == 7) t[k] = 8, ++replaced, k = 3;
  EXPECT_FALSE(analyseMesh(m).closed());
  EXPECT_FALSE(repairMesh(m, 0).usable);
  const RepairResult fix = repairMesh(m, 1e-6);
  EXPECT_TRUE(fix.usable) << fix.reason;
}

TEST(MeshReport, DegenerateTrianglesAreDroppedAndTwoCubesAreTwoComponents) {
  TriangleMesh m = unitCube();
  const TriangleMesh second = unitCube(1.0, Vec3(3, 0, 0));
  for (const auto& t : second.triangles) m.triangles.emplace_back(t + Eigen::Vector3i::Constant(8));
  m.vertices.insert(m.vertices.end(), second.vertices.begin(), second.vertices.end());
  m.triangles.emplace_back(0, 0, 1);  // repeated vertex
  m.triangles.emplace_back(0, 1, 99);  // index out of range
  const MeshReport r = analyseMesh(m);
  EXPECT_EQ(r.degenerateTriangles, 2u);
  EXPECT_FALSE(r.usable());
  const RepairResult fix = repairMesh(m);
  ASSERT_TRUE(fix.usable) << fix.reason;
  EXPECT_EQ(fix.report.components, 2u);
  EXPECT_TRUE(test::nearAbs("two cubes", fix.report.volume, 2.0, test::roundoff(4, 200, "triple products")));
}

TEST(MeshReport, EmptyMeshIsNotUsable) {
  const MeshReport r = analyseMesh(TriangleMesh{});
  EXPECT_FALSE(r.closed());
  EXPECT_FALSE(r.usable());
  EXPECT_FALSE(repairMesh(TriangleMesh{}).usable);
}

}  // namespace
}  // namespace coilsim::geometry
