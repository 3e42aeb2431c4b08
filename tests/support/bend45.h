#pragma once
// The 45-degree bend cantilever of Bathe & Bolourchi (1979), shared by the
// benchmark (bend45_test.cpp) and the convergence test: an eighth of a circle
// of radius 100 in the x-y plane, clamped at the origin with its tangent
// along x, curving towards +y; unit square section, E = 1e7, G = E / 2
// (EA = 1e7, EI = 833333, GJ = 705000 with the square's torsion constant
// J = 0.141, kappa = 5/6); a dead tip load P along +z. Consistent units.
#include <cmath>

#include "support/rod_models.h"

namespace coilsim::test {

inline constexpr double kBend45Radius = 100;

// Nodes on the arc with their Frenet frames (tangent, towards the centre, +z).
inline RestCurve bend45Curve(int beams) {
  RestCurve c;
  for (int i = 0; i <= beams; ++i) {
    const double phi = M_PI / 4 * i / beams;
    c.points.emplace_back(kBend45Radius * std::sin(phi), kBend45Radius * (1 - std::cos(phi)), 0.0);
    Mat3 f;
    f.col(0) = Vec3(std::cos(phi), std::sin(phi), 0);
    f.col(1) = Vec3(-std::sin(phi), std::cos(phi), 0);
    f.col(2) = Vec3::UnitZ();
    c.frames.emplace_back(f);
  }
  return c;
}

inline RodDef bend45Rod(int beams, double tipLoad) {
  const double e = 1e7;
  const Section s = customSection(1.0, 1.0 / 12, 1.0 / 12, 0.141, 5.0 / 6, 0.5);
  RodDef r = clamped(rodWithRest(bend45Curve(beams), kBend45Radius * M_PI / 4, beams, {e, e / 2, 1.0}, s));
  r.loads.push_back({beams, Vec3(0, 0, tipLoad), Vec3::Zero()});
  return r;
}

}  // namespace coilsim::test
