// Tests of the rest shapes (src/physics/rest_shape.cpp).
// References:
//  - helix: /work/shared/formats/coil-measurement.md (coil-measurement/1):
//    loop diameter D, pitch p, c = p / 2pi, curvature R / (R^2 + c^2), torsion
//    +-c / (R^2 + c^2), positive for right-handed; its Frenet frame turns with
//    the constant Darboux vector tau t + kappa b (do Carmo, Differential
//    Geometry of Curves and Surfaces, sec. 1-5 and 1-6), so consecutive frames
//    of equally spaced samples differ by exactly ds (tau, 0, kappa) in frame
//    coordinates; the canonical helix is written out here in closed form;
//  - parallel transport (Bishop 1975, "There is more than one way to frame a
//    curve", Amer. Math. Monthly 82:246): frames turn about t x t' only, with
//    no twist about t; a Frenet frame twists relative to it at the rate tau;
//  - bird-cage: every point on the sphere of diameter D (fitted here by least
//    squares);
//  - a circle given as a polyline: Frenet curvature 1 / R everywhere, normal
//    towards the centre.
#include <gtest/gtest.h>

#include <cmath>

#include "physics/rest_shape.h"
#include "support/curve_geometry.h"
#include "support/known_bugs.h"
#include "support/tolerance.h"

namespace coilsim::test {
namespace {

// A typical detachable coil: 7 mm loops, pitch 2 mm (large enough that the
// torsion is not lost in the curvature), 60 mm long, 0.25 mm beams.
constexpr double kLength = 0.06, kLoopDiameter = 0.007, kPitch = 0.002;
constexpr int kBeams = 240;

struct HelixConstants {
  double radius, c, a, curvature, torsion;
};
HelixConstants helixConstants(bool rightHanded) {
  const double r = kLoopDiameter / 2, c = (rightHanded ? 1 : -1) * kPitch / (2 * M_PI);
  const double a2 = r * r + c * c;
  return {r, c, std::sqrt(a2), r / a2, c / a2};
}

// The helix in coilsim's canonical placement (first point at the origin,
// tangent +x, principal normal +y, binormal +z), from its axis-frame form
// p(phi) = (R cos phi, +-R sin phi, |c| phi), phi = s / sqrt(R^2 + c^2).
Vec3 canonicalHelixPoint(const HelixConstants& h, double s) {
  const double phi = s / h.a, r = h.radius;
  return Vec3((r * r * std::sin(phi) + h.c * h.c * phi) / h.a, r * (1 - std::cos(phi)),
              r * h.c * (phi - std::sin(phi)) / h.a);
}

TEST(RestShapeTest, HelixNodesLieOnTheAnalyticHelix) {
  for (const bool right : {true, false}) {
    const HelixConstants h = helixConstants(right);
    const RestCurve c = makeHelix(kLength, kBeams, kLoopDiameter, kPitch, right);
    ASSERT_EQ(int(c.points.size()), kBeams + 1);
    double worst = 0;
    for (int i = 0; i <= kBeams; ++i)
      worst = std::max(worst, (c.points[i] - canonicalHelixPoint(h, kLength * i / kBeams)).norm());
    EXPECT_TRUE(small(std::string(right ? "right" : "left") + " helix nodes vs closed form", worst / kLoopDiameter,
                      roundoff(1.0, 1e3, "trigonometry and the canonical rotation of coordinates of size D")));
  }
}

TEST(RestShapeTest, HelixPointsHaveTheCurvatureAndSignedTorsionOfCoilMeasurementFormat) {
  for (const bool right : {true, false}) {
    const HelixConstants h = helixConstants(right);
    const RestCurve c = makeHelix(kLength, kBeams, kLoopDiameter, kPitch, right);
    double worstK = 0, worstT = 0;
    for (int i = 0; i + 3 <= kBeams; ++i) {
      const HelixFit f = helixThrough(c.points[i], c.points[i + 1], c.points[i + 2], c.points[i + 3]);
      worstK = std::max(worstK, relativeError(f.curvature, h.curvature));
      worstT = std::max(worstT, relativeError(f.torsion, h.torsion));
    }
    const std::string tag = right ? "right-handed" : "left-handed";
    // Second differences of 0.25 mm chords lose ~eps |x| / (kappa ds^2) ~ 1e-11.
    const Tolerance tol{1e-8, "screw fit is exact; second differences amplify round-off ~1e3 times"};
    EXPECT_TRUE(small(tag + " curvature from points (relative)", worstK, tol));
    EXPECT_TRUE(small(tag + " torsion from points (relative)", worstT, tol));
    EXPECT_EQ(right, h.torsion > 0) << "coil-measurement/1: torsion > 0 for a right-handed helix";
  }
}

TEST(RestShapeTest, HelixFramesAreFrenetFramesTurningWithTheDarbouxVector) {
  const double ds = kLength / kBeams;
  for (const bool right : {true, false}) {
    const HelixConstants h = helixConstants(right);
    const RestCurve c = makeHelix(kLength, kBeams, kLoopDiameter, kPitch, right);
    const Vec3 darboux = ds * Vec3(h.torsion, 0, h.curvature);  // (t, d1 = n, d2 = b) coordinates
    double worst = 0, worstTangent = 0;
    for (int i = 0; i < kBeams; ++i) {
      worst = std::max(worst, (quatLog(c.frames[i].conjugate() * c.frames[i + 1]) - darboux).norm());
      // The frame's first axis is the tangent of the closed-form curve.
      const double s = kLength * i / kBeams, e = 1e-7;
      const Vec3 t = (canonicalHelixPoint(h, s + e) - canonicalHelixPoint(h, s - e)).normalized();
      worstTangent = std::max(worstTangent, (c.frames[i] * Vec3::UnitX() - t).norm());
    }
    const std::string tag = right ? "right" : "left";
    EXPECT_TRUE(small(tag + " helix frame increments minus ds (tau, 0, kappa) (rad)", worst,
                      roundoff(1.0, 1e3, "unit quaternions composed over 240 nodes")));
    EXPECT_TRUE(small(tag + " helix frame tangent vs closed-form tangent", worstTangent,
                      {1e-8, "central difference of step 1e-7 m: (kappa e)^2 / 6 ~ 1e-10, round-off eps/e ~ 2e-9"}));
  }
}

TEST(RestShapeTest, BirdcagePointsLieOnTheSphereOfTheGivenDiameter) {
  SKIP_IF_OPEN(kPolylineResampleShift);
  const double diameter = 0.008, length = 0.15;
  const int beams = 300;
  const RestCurve c = makeBirdcage(length, beams, diameter, 0.8);
  ASSERT_EQ(int(c.points.size()), beams + 1);
  const Sphere s = fitSphere(c.points);
  double worst = 0, arc = 0;
  for (const Vec3& p : c.points) worst = std::max(worst, std::abs((p - s.centre).norm() - s.radius));
  for (int i = 0; i < beams; ++i) arc += (c.points[i + 1] - c.points[i]).norm();
  // The loops are sampled with 200 chords per turn before resampling; a chord
  // of a circle of radius r <= D/2 dips inside by r (1 - cos(pi / 200)) = 1.2e-4 D/2.
  const Tolerance sagitta{2.5e-4, "chords of the 200-per-loop sampling sag 1.2e-4 of the radius"};
  EXPECT_TRUE(nearRel("bird-cage sphere diameter", 2 * s.radius, diameter, sagitta));
  EXPECT_TRUE(small("bird-cage distance to the sphere / radius", worst / s.radius, sagitta));
  // Nodes are equally spaced along the curve (arc ds = L / n): the chords
  // are shorter than ds by kappa^2 ds^3 / 24, kappa read off the nodes
  // themselves (circle through three neighbours).
  const double ds = length / beams;
  double kappa2 = 0;
  for (int i = 1; i < beams; ++i) kappa2 += std::pow(1 / circumradius(c.points[i - 1], c.points[i], c.points[i + 1]), 2);
  kappa2 /= beams - 1;
  EXPECT_TRUE(nearRel("bird-cage node polygon length vs L (1 - kappa^2 ds^2 / 24)", arc,
                      length * (1 - kappa2 * ds * ds / 24),
                      {1e-4, "generator sampled with 200 chords per loop: (2 pi / 200)^2 / 24 = 4e-5"}));
}

// A three-quarter circle of radius 5 mm sampled by 3000 points.
std::vector<Vec3> circlePolyline(double radius, int samples) {
  std::vector<Vec3> p;
  for (int k = 0; k <= samples; ++k) {
    const double phi = 1.5 * M_PI * k / samples;
    p.emplace_back(radius * std::sin(phi), radius * (1 - std::cos(phi)), 0.0);
  }
  return p;
}

struct PolylineCircle {
  double radius, length, ds;
  int beams;
  RestCurve curve;
  Vec3 centre;  // from three nodes, independently of the frames
};

PolylineCircle polylineCircle() {
  PolylineCircle c;
  c.radius = 0.005;
  c.length = 1.5 * M_PI * c.radius;
  c.beams = 60;
  c.ds = c.length / c.beams;
  c.curve = makePolyline(circlePolyline(c.radius, 3000), c.length, c.beams, FrameRule::Frenet, 0.0);
  const Vec3 a = c.curve.points[0], b = c.curve.points[c.beams / 2], d = c.curve.points[c.beams];
  // Circumcentre of a, b, d.
  const Vec3 ab = b - a, ad = d - a, n = ab.cross(ad);
  c.centre = a + (ad.squaredNorm() * n.cross(ab) + ab.squaredNorm() * ad.cross(n)) / (2 * n.squaredNorm());
  return c;
}

// Fine sampling: chords of 3000 samples shorten the radius by (dphi)^2 / 24 = 1.0e-7.
const Tolerance kCircleSampling{1e-6, "3000-point sampling of the circle: (dphi)^2 / 24 = 1e-7"};

// Frenet curvature of beam i: the frame rotation over the arc between its nodes.
double beamCurvatureError(const PolylineCircle& c, int i) {
  const double turn = c.curve.frames[i].angularDistance(c.curve.frames[i + 1]);
  const double arc = 2 * c.radius * std::asin((c.curve.points[i + 1] - c.curve.points[i]).norm() / (2 * c.radius));
  return relativeError(turn / arc, 1 / c.radius);
}

double normalError(const PolylineCircle& c, int i) {
  return (c.curve.frames[i] * Vec3::UnitY() - (c.centre - c.curve.points[i]).normalized()).norm();
}

TEST(RestShapeTest, PolylineCircleNodesLieOnTheCircle) {
  const PolylineCircle c = polylineCircle();
  double worst = 0;
  for (const Vec3& p : c.curve.points) worst = std::max(worst, std::abs((p - c.centre).norm() - c.radius) / c.radius);
  EXPECT_TRUE(small("polyline circle: node distance to the centre / R - 1", worst, kCircleSampling));
  EXPECT_TRUE(nearRel("polyline circle: node spacing", (c.curve.points[1] - c.curve.points[0]).norm(),
                      2 * c.radius * std::sin(c.ds / (2 * c.radius)), kCircleSampling));
}

TEST(RestShapeTest, PolylineFrenetFramesReproduceACirclesCurvature) {
  const PolylineCircle c = polylineCircle();
  double worstCurvature = 0, worstNormal = 0;
  for (int i = 1; i + 1 < c.beams; ++i) worstCurvature = std::max(worstCurvature, beamCurvatureError(c, i));
  for (int i = 1; i < c.beams; ++i) worstNormal = std::max(worstNormal, normalError(c, i));
  EXPECT_TRUE(small("polyline circle: interior frame curvature vs 1/R", worstCurvature, kCircleSampling));
  EXPECT_TRUE(small("polyline circle: interior d1 towards the centre", worstNormal, kCircleSampling));
}

TEST(RestShapeTest, PolylineEndFramesFollowTheCurve) {
  SKIP_IF_OPEN(kPolylineEndTangents);
  const PolylineCircle c = polylineCircle();
  EXPECT_TRUE(small("polyline circle: first beam curvature vs 1/R", beamCurvatureError(c, 0), kCircleSampling));
  EXPECT_TRUE(small("polyline circle: last beam curvature vs 1/R", beamCurvatureError(c, c.beams - 1), kCircleSampling));
  EXPECT_TRUE(small("polyline circle: first node d1 towards the centre", normalError(c, 0), kCircleSampling));
  EXPECT_TRUE(small("polyline circle: last node d1 towards the centre", normalError(c, c.beams), kCircleSampling));
}

TEST(RestShapeTest, ParallelTransportHasNoTwistAndFrenetTwistsAtTheTorsionRate) {
  // A helix given as a polyline of its own nodes (so resampling is exact).
  const HelixConstants h = helixConstants(true);
  std::vector<Vec3> pts;
  for (int i = 0; i <= kBeams; ++i) pts.push_back(canonicalHelixPoint(h, kLength * i / kBeams));
  double polyLength = 0;
  for (int i = 0; i < kBeams; ++i) polyLength += (pts[i + 1] - pts[i]).norm();
  const RestCurve pt = makePolyline(pts, polyLength, kBeams, FrameRule::ParallelTransport, 0.0);
  const RestCurve fr = makePolyline(pts, polyLength, kBeams, FrameRule::Frenet, 0.0);
  const double ds = polyLength / kBeams;
  // Twist = component along t of a frame increment, in frame coordinates (x):
  // zero for parallel transport, tau ds for the Frenet frame (Darboux vector).
  double worstTwist = 0, worstRate = 0;
  for (int i = 0; i < kBeams; ++i) {
    worstTwist = std::max(worstTwist, std::abs(quatLog(pt.frames[i].conjugate() * pt.frames[i + 1]).x()));
    // Interior beams: the end frames copy their neighbour's normal.
    if (i >= 1 && i + 1 < kBeams) {
      const double twist = quatLog(fr.frames[i].conjugate() * fr.frames[i + 1]).x();
      worstRate = std::max(worstRate, relativeError(twist / ds, h.torsion));
    }
  }
  EXPECT_TRUE(small("parallel transport twist per beam (rad)", worstTwist,
                    roundoff(1.0, 1e3, "minimal rotations composed along 240 nodes")));
  // Discrete Frenet normals from chord binormals carry O((kappa ds)^2) = 5e-3.
  EXPECT_TRUE(small("Frenet twist rate vs tau (relative)", worstRate,
                    {2e-2, "discrete normals from chord binormals: O((kappa ds)^2), kappa ds = 0.07"}));
}

TEST(RestShapeTest, IntrinsicTwistTurnsFramesAboutTheTangentAtTheGivenRate) {
  const double length = 0.02, rate = 40.0;  // rad/m: 0.8 rad over the rod
  const int beams = 40;
  const RestCurve c = makePolyline({Vec3::Zero(), Vec3(length, 0, 0)}, length, beams, FrameRule::ParallelTransport, rate);
  double worst = 0;
  for (int i = 0; i <= beams; ++i) {
    const Vec3 w = quatLog(c.frames[0].conjugate() * c.frames[i]);
    worst = std::max(worst, (w - Vec3(rate * length * i / beams, 0, 0)).norm());
  }
  EXPECT_TRUE(small("intrinsic twist angle minus w s (rad)", worst, roundoff(1.0, 100, "one rotation per node")));
}

}  // namespace
}  // namespace coilsim::test
