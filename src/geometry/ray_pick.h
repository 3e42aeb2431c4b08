#pragma once
// Where a ray (a click in a view) meets a triangle surface: every crossing
// along it, and the stretch of lumen it first passes through. Mesh units.
// Brute force over the triangles: a click is one ray, and a patient's
// surface has some ten thousand triangles.
#include <optional>
#include <vector>

#include "physics/triangle_mesh.h"

namespace coilsim::geometry {

// Distances t >= 0 along `direction` (normalised here) from `origin` at which
// the ray crosses a triangle of `mesh`, ascending. Empty for a zero or
// non-finite direction.
std::vector<double> rayHits(const TriangleMesh& mesh, const Vec3& origin, const Vec3& direction);

// The first surface point the ray meets, or nullopt when it misses.
std::optional<Vec3> firstHit(const TriangleMesh& mesh, const Vec3& origin, const Vec3& direction);

// The middle of the first stretch of the ray inside a closed surface seen
// from outside: halfway between the first crossing (in) and the second (out).
// Nullopt when the ray crosses fewer than two triangles.
std::optional<Vec3> firstLumenMiddle(const TriangleMesh& mesh, const Vec3& origin, const Vec3& direction);

}  // namespace coilsim::geometry
