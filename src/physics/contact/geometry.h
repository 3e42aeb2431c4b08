#pragma once
// Closest points between segments, points and triangles (Ericson, Real-Time
// Collision Detection, 2005, sections 5.1.5 and 5.1.9). Capsules are
// segments with a radius, so these are the whole narrow phase.
#include "physics/math.h"

namespace coilsim {

struct SegmentPair {
  double s = 0, t = 0;  // parameters in [0, 1] on the first and second segment
  Vec3 p, q;            // the closest points
  double distance = 0;
};

// Closest points of segments [p0, p1] and [q0, q1]. Nearly parallel
// segments get the middle of their overlap, so the contact does not jump
// to an end.
SegmentPair closestSegmentSegment(const Vec3& p0, const Vec3& p1, const Vec3& q0, const Vec3& q1);

// Closest point of triangle (a, b, c) to p.
Vec3 closestPointTriangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c);

struct SegmentTriangle {
  double s = 0;     // parameter on the segment
  Vec3 onSegment;   // closest point on the segment
  Vec3 onTriangle;  // closest point on the triangle
  double distance = 0;
};

// Closest points of segment [p0, p1] and triangle (a, b, c); distance 0 when they cross.
SegmentTriangle closestSegmentTriangle(const Vec3& p0, const Vec3& p1, const Vec3& a, const Vec3& b, const Vec3& c);

}  // namespace coilsim
