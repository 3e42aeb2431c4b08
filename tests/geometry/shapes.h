#pragma once
// Hand-built and analytic test surfaces for the geometry tests.
#include <cmath>

#include "geometry/marching_tets.h"
#include "physics/triangle_mesh.h"

namespace coilsim::test {

// The unit cube [0,1]^3 (scaled by `side`), 8 shared vertices, 12 triangles,
// counter-clockwise seen from outside.
inline TriangleMesh unitCube(double side = 1.0, const Vec3& origin = Vec3::Zero()) {
  TriangleMesh m;
  m.name = "cube";
  for (int i = 0; i < 8; ++i) m.vertices.push_back(origin + side * Vec3(i & 1, (i >> 1) & 1, (i >> 2) & 1));
  // Each face as a quad (a, b, c, d) counter-clockwise from outside.
  const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& q : quads) {
    m.triangles.emplace_back(q[0], q[1], q[2]);
    m.triangles.emplace_back(q[0], q[2], q[3]);
  }
  return m;
}

// A ball of radius r about c, polygonised with spacing h (vertices lie on
// the sphere to interpolation accuracy; the solid is a polyhedron inscribed
// near it).
inline TriangleMesh sphereMesh(double r, double h, const Vec3& c = Vec3::Zero()) {
  const Vec3 reach = Vec3::Constant(r + 2 * h);
  return geometry::polygonise([&](const Vec3& p) { return (p - c).norm() - r; }, c - reach, c + reach, h);
}

// Volume of a ball of radius r above a plane at signed distance d from its
// centre (d > 0: the plane above the centre): the spherical cap of height r - d.
inline double capVolume(double r, double d) {
  const double h = r - d;
  return M_PI * h * h * (3 * r - h) / 3.0;
}

}  // namespace coilsim::test
