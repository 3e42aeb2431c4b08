#pragma once
// Enclosed volumes of closed, outward-oriented triangle surfaces, whole or
// on one side of a plane (an aneurysm sac closed by its neck plane).
#include "physics/triangle_mesh.h"

namespace coilsim::geometry {

// A plane through `point`; `normal` (unit) points to the side that counts
// (for a neck plane: toward the dome).
struct Plane {
  Vec3 point = Vec3::Zero();
  Vec3 normal = Vec3::UnitZ();
  double side(const Vec3& x) const { return (x - point).dot(normal); }
};

// Signed enclosed volume (divergence theorem); positive for an outward
// surface. Mesh units cubed.
double enclosedVolume(const TriangleMesh& mesh);

// Volume of the solid on the normal side of `plane`: the surface is clipped
// by the plane and closed by the cut, which is exact for a polyhedron. The
// cut's cap needs no triangulation: each clipped triangle is summed as
// tetrahedra whose apex lies on the plane, so the cap contributes nothing.
// Expects a closed, outward surface; a unit normal.
double volumeAbovePlane(const TriangleMesh& mesh, const Plane& plane);

// Area of the surface's cross-section with the plane (the neck area, for a
// neck plane): the cap's area, from the clipped edges. Same expectations.
double sectionArea(const TriangleMesh& mesh, const Plane& plane);

}  // namespace coilsim::geometry
