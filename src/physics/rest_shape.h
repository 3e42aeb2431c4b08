#pragma once
// Stress-free (shape-memory) centre lines and material frames, sampled at the
// nodes of a rod. All are built in a canonical placement: the first node at
// the origin, its tangent along +x and its material normal d1 along +y; a
// Placement moves them rigidly. Frame columns: (tangent, d1, d2).
#include <string>
#include <vector>

#include "physics/math.h"

namespace coilsim {

struct RestCurve {
  std::vector<Vec3> points;  // (nnode) positions along the rod, SI
  std::vector<Quat> frames;  // (nnode) material frames
};

// Straight rod of length L with n beams.
RestCurve makeStraight(double length, int beams);

// Helix of loop diameter D and pitch p (coil-measurement/1 definition):
// curvature R/(R^2+c^2), torsion +-c/(R^2+c^2), c = p/(2 pi), positive for a
// right-handed helix. d1 is the principal normal (towards the helix axis).
RestCurve makeHelix(double length, int beams, double loopDiameter, double pitch, bool rightHanded);

// How frames are attached to a polyline's sampled centre line.
enum class FrameRule { Frenet, ParallelTransport };

// Any centre line, given as points from the first node on; resampled at equal
// arc length. Frenet frames need curvature everywhere (straight stretches fall
// back to parallel transport); `twistPerLength` (rad/m) adds intrinsic twist.
// Throws PhysicsError (physics/failure.h) on fewer than 2 distinct points.
RestCurve makePolyline(const std::vector<Vec3>& points, double length, int beams, FrameRule rule,
                       double twistPerLength);

// Framing ("bird-cage", complex 3D) coil: loops on a sphere of diameter D,
// each loop a near-great circle whose plane turns by a fixed angle per loop,
// so that successive loops cage the sphere as framing coils do.
RestCurve makeBirdcage(double length, int beams, double sphereDiameter, double planeTurnPerLoopRad);

// A rest shape as files and fits describe it, before it is sampled: the
// kind and its few numbers (SI). Fits change the numbers (loop diameter,
// pitch) and sample again, so the description is kept, not the samples.
struct RestShapeDef {
  enum class Type { Straight, Helix, Polyline, Birdcage } type = Type::Straight;
  double loopDiameter = 0, pitch = 0;  // m (helix)
  bool rightHanded = true;             // (helix)
  std::vector<Vec3> points;            // m (polyline), from the rod's first node on (a coil's proximal end)
  FrameRule frames = FrameRule::Frenet;  // (polyline)
  double twistPerLength = 0;           // rad/m (polyline)
  double sphereDiameter = 0;           // m (birdcage)
  double planeTurnPerLoop = 0;         // rad (birdcage)
};

// Samples `rest` on a rod of `length` with `beams` beams, canonical (as the
// makers above). Throws PhysicsError (physics/failure.h) as they do.
RestCurve makeRest(const RestShapeDef& rest, double length, int beams);

// Rigid placement of a canonical curve: first node at `position`, tangent
// along `direction`, d1 along `normal` (made orthogonal to direction).
struct Placement {
  Vec3 position = Vec3::Zero();
  Vec3 direction = Vec3::UnitX();
  Vec3 normal = Vec3::UnitY();
  Quat rotation() const;
};
RestCurve placed(const RestCurve& curve, const Placement& placement);

}  // namespace coilsim
