// Tube, sphere and arrow geometry without GL: vertices at the radius from
// the centre line, outward normals, closed surfaces wound counter-clockwise
// from outside (the X-ray pass depends on it), and bad nodes skipped.
#include "render/geometry.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <utility>

#include "physics/rest_shape.h"
#include "render/camera.h"

namespace coilsim::render {
namespace {

Vec3 pos(const Vertex& v) { return Vec3(v.position[0], v.position[1], v.position[2]); }
Vec3 nrm(const Vertex& v) { return Vec3(v.normal[0], v.normal[1], v.normal[2]); }

// Distance from p to the polyline.
double distanceToPolyline(const Vec3& p, const std::vector<Vec3>& line) {
  double best = 1e300;
  for (size_t i = 0; i + 1 < line.size(); ++i) {
    const Vec3 a = line[i], d = line[i + 1] - a;
    const double t = std::clamp((p - a).dot(d) / d.squaredNorm(), 0.0, 1.0);
    best = std::min(best, (a + t * d - p).norm());
  }
  return best;
}

// Every edge used exactly once in each direction: a closed, consistently
// wound surface. Positions are compared, since caps and bodies share them.
void expectClosed(const TriangleMesh& m) {
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> edges;
  for (size_t k = 0; k + 2 < m.indices.size(); k += 3)
    for (int e = 0; e < 3; ++e) ++edges[{m.indices[k + e], m.indices[k + (e + 1) % 3]}];
  for (const auto& [edge, count] : edges) {
    EXPECT_EQ(count, 1) << "edge " << edge.first << "-" << edge.second << " used " << count << " times";
    EXPECT_EQ(edges.count({edge.second, edge.first}), 1u) << "edge " << edge.first << "-" << edge.second << " is open";
  }
}

// The signed volume (divergence theorem) is positive for outward winding.
double signedVolume(const TriangleMesh& m) {
  double v = 0;
  for (size_t k = 0; k + 2 < m.indices.size(); k += 3)
    v += pos(m.vertices[m.indices[k]]).dot(pos(m.vertices[m.indices[k + 1]]).cross(pos(m.vertices[m.indices[k + 2]])));
  return v / 6.0;
}

DrawTube helixTube(double radius) {
  const RestCurve c = makeHelix(0.03, 60, 0.006, 0.001, true);
  DrawTube t;
  t.radius = radius;
  t.centre = c.points;
  t.frames = c.frames;
  t.colours.assign(c.points.size(), Colour(1, 0, 0, 1));
  t.colours.back() = Colour(0, 0, 1, 1);
  return t;
}

TEST(TubeGeometry, VerticesLieAtTheRadiusWithOutwardNormals) {
  const double r = 0.2e-3;
  const DrawTube t = helixTube(r);
  TriangleMesh m;
  TubeOptions o;
  appendTube(t, o, m);
  // Rings at every node plus two caps of (capRings - 1) rings and a pole each.
  const size_t n = t.centre.size();
  EXPECT_EQ(m.vertices.size(), n * o.sides + 2 * (size_t(o.capRings - 1) * o.sides + 1));
  // Cap vertices (before and after the body rings) sit at r from their end node.
  const size_t firstBody = 1 + size_t(o.capRings - 1) * o.sides, endCap = firstBody + n * o.sides;
  for (size_t k = 0; k < m.vertices.size(); ++k) {
    if (k >= firstBody && k < endCap) continue;
    const Vec3 end = k < firstBody ? t.centre.front() : t.centre.back();
    EXPECT_NEAR((pos(m.vertices[k]) - end).norm(), r, 1e-4 * r) << "cap vertex " << k;
  }
  for (const Vertex& v : m.vertices) EXPECT_NEAR(nrm(v).norm(), 1.0, 1e-5);
  // Body vertices sit at r from their node (to float precision: positions are
  // float), normals point from the node to them.
  for (size_t i = 0; i < n; ++i)
    for (int j = 0; j < o.sides; ++j) {
      const Vertex& v = m.vertices[firstBody + i * o.sides + j];
      EXPECT_NEAR((pos(v) - t.centre[i]).norm(), r, 1e-4 * r) << "node " << i << " side " << j;
      const Vec3 out = (pos(v) - t.centre[i]).normalized();
      EXPECT_GT(out.dot(nrm(v)), 0.999) << "node " << i << " side " << j;
      // The ring is perpendicular to the centre line.
      const Vec3 tangent = (t.centre[std::min(i + 1, n - 1)] - t.centre[i == 0 ? 0 : i - 1]).normalized();
      EXPECT_NEAR(out.dot(tangent), 0.0, 1e-3);
    }
}

TEST(TubeGeometry, IsClosedAndWoundOutwards) {
  const double r = 0.3e-3;
  DrawTube t;
  t.radius = r;
  t.centre = makeStraight(0.01, 10).points;
  TriangleMesh m;
  appendTube(t, TubeOptions{}, m);
  expectClosed(m);
  // Around a straight line every body vertex is at the radius from the line itself.
  for (const Vertex& v : m.vertices)
    if (pos(v).x() >= 0 && pos(v).x() <= 0.01) {
      EXPECT_NEAR(distanceToPolyline(pos(v), t.centre), r, 1e-4 * r);
    }
  // Cylinder plus two hemispheres, within the polygon's shortfall (16 sides, 3 cap rings).
  const double exact = M_PI * r * r * 0.01 + 4.0 / 3.0 * M_PI * r * r * r;
  const double v = signedVolume(m);
  EXPECT_GT(v, 0.9 * exact);
  EXPECT_LT(v, exact);
  TriangleMesh h;
  appendTube(helixTube(r), TubeOptions{}, h);
  expectClosed(h);
  EXPECT_GT(signedVolume(h), 0.0);
}

TEST(TubeGeometry, SubdivisionPassesThroughTheNodes) {
  const double r = 0.2e-3;
  const DrawTube t = helixTube(r);
  TubeOptions o;
  o.subdivisions = 3;
  TriangleMesh m;
  appendTube(t, o, m);
  expectClosed(m);
  const size_t firstBody = 1 + size_t(o.capRings - 1) * o.sides;
  const size_t rings = (t.centre.size() - 1) * 4 + 1;
  EXPECT_EQ(m.vertices.size(), rings * o.sides + 2 * (firstBody));
  // Every fourth ring is centred on a node.
  for (size_t i = 0; i < t.centre.size(); ++i) {
    Vec3 centre = Vec3::Zero();
    for (int j = 0; j < o.sides; ++j) centre += pos(m.vertices[firstBody + 4 * i * o.sides + j]);
    EXPECT_LT((centre / o.sides - t.centre[i]).norm(), 1e-4 * r) << "node " << i;
  }
}

TEST(TubeGeometry, PerNodeColoursAndMissingColours) {
  DrawTube t = helixTube(1e-4);
  TriangleMesh m;
  appendTube(t, TubeOptions{}, m);
  EXPECT_EQ(m.vertices.front().colour[0], 1.0f);  // start cap: first node's colour
  EXPECT_EQ(m.vertices.back().colour[2], 1.0f);   // end pole: last node's colour
  t.colours.clear();
  m.clear();
  appendTube(t, TubeOptions{}, m);
  const Colour c = defaultColour(RodRole::Coil);
  EXPECT_EQ(m.vertices[5].colour[1], c[1]);
}

TEST(TubeGeometry, SkipsNonFiniteNodesAndDegenerateTubes) {
  DrawTube t = helixTube(1e-4);
  t.centre[10] = Vec3(NAN, 0, 0);
  TriangleMesh m;
  appendTube(t, TubeOptions{}, m);
  for (const Vertex& v : m.vertices) EXPECT_TRUE(pos(v).allFinite());
  expectClosed(m);

  TriangleMesh empty;
  DrawTube one;
  one.radius = 1e-4;
  one.centre = {Vec3::Zero()};
  appendTube(one, TubeOptions{}, empty);
  DrawTube flat = helixTube(0.0);
  appendTube(flat, TubeOptions{}, empty);
  EXPECT_TRUE(empty.vertices.empty());

  // Repeated nodes borrow a neighbour's tangent instead of producing NaN.
  DrawTube repeated;
  repeated.radius = 1e-4;
  repeated.centre = {Vec3::Zero(), Vec3::Zero(), Vec3(1e-3, 0, 0), Vec3(1e-3, 0, 0), Vec3(2e-3, 1e-3, 0)};
  TriangleMesh r;
  appendTube(repeated, TubeOptions{}, r);
  for (const Vertex& v : r.vertices) {
    EXPECT_TRUE(pos(v).allFinite());
    EXPECT_TRUE(nrm(v).allFinite());
  }
}

TEST(TubeGeometry, ParallelTransportHasNoTwist) {
  // On a planar curve the transported normal stays in or out of the plane.
  const RestCurve c = makeHelix(0.02, 40, 0.006, 0.0, true);  // a flat circle arc
  std::vector<Vec3> t, n;
  tubeFrames(c.points, t, n);
  for (size_t i = 0; i < t.size(); ++i) {
    EXPECT_NEAR(t[i].norm(), 1.0, 1e-12);
    EXPECT_NEAR(n[i].norm(), 1.0, 1e-12);
    EXPECT_NEAR(t[i].dot(n[i]), 0.0, 1e-12);
    EXPECT_NEAR(std::abs(n[i].dot(Vec3::UnitZ())), std::abs(n[0].dot(Vec3::UnitZ())), 1e-6);
  }
}

// Reference: a regular n-gon inscribed in a circle of radius r strays from
// it by its sagitta r (1 - cos(pi / n)); tubeDetail takes the fewest sides
// that keep it within the tolerance (at least 6, at most the cap).
TEST(TubeDetail, FewestSidesWithinTheSilhouetteTolerance) {
  const TubeOptions most{64, 3, 1.0, 3};
  const double tol = 0.5;
  for (const double r : {0.3, 1.0, 2.0, 3.0, 5.0, 8.0, 13.0, 40.0, 200.0}) {
    const int n = tubeDetail(most, r, 0, tol).sides;
    auto sagitta = [r](int sides) { return r * (1 - std::cos(M_PI / sides)); };
    EXPECT_GE(n, 6) << r;
    EXPECT_LE(n, 64) << r;
    if (n < 64) EXPECT_LE(sagitta(n), tol + 1e-12) << r << " px: " << n << " sides";
    if (n > 6) EXPECT_GT(sagitta(n - 1), tol) << r << " px: " << n - 1 << " sides would do";
  }
  EXPECT_EQ(tubeDetail(TubeOptions{16, 3, 1.0, 3}, 200.0, 0).sides, 16);  // never above the cap
  // No size known: the full detail.
  const TubeOptions full = tubeDetail(most, 0, 0);
  EXPECT_EQ(full.sides, 64);
  EXPECT_EQ(full.subdivisions, 3);
}

// Each of the sub + 1 pieces a segment is cut into is at most the longest
// allowed, and one piece fewer would not be (below the cap).
TEST(TubeDetail, PiecesBetweenNodesNoLongerThanAsked) {
  const TubeOptions most{16, 3, 1.0, 8};
  for (const double seg : {1.0, 5.9, 6.0, 6.1, 12.0, 20.0, 47.0}) {
    const int sub = tubeDetail(most, 4.0, seg, 0.5, 6.0).subdivisions;
    EXPECT_LE(seg / (sub + 1), 6.0 + 1e-12) << seg;
    if (sub > 0) EXPECT_GT(seg / sub, 6.0) << seg;
  }
  EXPECT_EQ(tubeDetail(most, 4.0, 1000.0).subdivisions, 8);
}

TEST(SphereAndArrow, ClosedAndOutwards) {
  TriangleMesh s;
  appendSphere(Vec3(1, 2, 3), 0.5, Colour(1, 1, 0, 1), s);
  expectClosed(s);
  for (const Vertex& v : s.vertices) EXPECT_NEAR((pos(v) - Vec3(1, 2, 3)).norm(), 0.5, 1e-6);
  TriangleMesh a;
  appendArrow(Vec3::Zero(), Vec3(0, 0, 0.01), 1e-4, Colour(1, 1, 0, 1), a);
  EXPECT_GT(signedVolume(a), 0.0);
  double top = -1;
  for (const Vertex& v : a.vertices) top = std::max(top, double(v.position[2]));
  EXPECT_NEAR(top, 0.01, 1e-9);  // the tip ends at from + vector
  TriangleMesh none;
  appendArrow(Vec3::Zero(), Vec3::Zero(), 1e-4, Colour(1, 1, 0, 1), none);
  EXPECT_TRUE(none.vertices.empty());
}

TEST(Camera, FitKeepsTheBoxInView) {
  Bounds b;
  b.add(Vec3(-0.01, -0.002, 0.0));
  b.add(Vec3(0.012, 0.004, 0.005));
  for (double aspect : {0.5, 1.0, 16.0 / 9.0}) {
    Camera c;
    c.fit(b, aspect);
    const Mat4f pv = c.projection(aspect) * c.view();
    for (int k = 0; k < 8; ++k) {
      const Eigen::Vector4f p((k & 1) ? b.hi.x() : b.lo.x(), (k & 2) ? b.hi.y() : b.lo.y(),
                              (k & 4) ? b.hi.z() : b.lo.z(), 1.0f);
      const Eigen::Vector4f q = pv * p;
      EXPECT_LE(std::abs(q.x() / q.w()), 1.0f) << "aspect " << aspect;
      EXPECT_LE(std::abs(q.y() / q.w()), 1.0f) << "aspect " << aspect;
      EXPECT_LE(std::abs(q.z() / q.w()), 1.0f) << "aspect " << aspect;
    }
  }
  // The lateral view looks along -x, a quarter turn from AP (along +y).
  const Camera ap = apView(Camera{});
  EXPECT_NEAR(ap.forward().dot(Vec3::UnitY()), 1.0, 1e-12);
  EXPECT_NEAR(lateralView(ap).forward().dot(-Vec3::UnitX()), 1.0, 1e-12);
}

}  // namespace
}  // namespace coilsim::render
