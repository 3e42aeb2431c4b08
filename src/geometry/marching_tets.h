#pragma once
// Polygonising an implicit surface: the zero set of a field (negative inside)
// sampled on a regular grid, each cube split into six tetrahedra around its
// main diagonal (Freudenthal/Kuhn), so neighbouring cubes share faces and the
// linear pieces join without the ambiguous cases of marching cubes.
#include <functional>

#include "physics/triangle_mesh.h"

namespace coilsim::geometry {

using Field = std::function<double(const Vec3&)>;

// The surface f = 0 inside the box [lower, upper] sampled every `spacing`.
// The field must be positive on the box's faces (the solid strictly inside
// the box): the result is then closed, every edge shared by two triangles,
// normals outward. Vertices on grid edges are shared, not duplicated.
// Throws std::invalid_argument on a non-positive spacing, an empty box, more
// than `maxPoints` samples or a field that is not positive on the faces.
TriangleMesh polygonise(const Field& f, const Vec3& lower, const Vec3& upper, double spacing,
                        long maxPoints = 64'000'000);

}  // namespace coilsim::geometry
