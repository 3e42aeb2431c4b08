#pragma once
// Shared set-ups for the reference model's tests.
#include "rod.h"
#include "solver.h"

namespace refrod::testing {

// A straight platinum-like wire (r = 0.15 mm, E = 6 GPa, nu = 0.39), clamped
// at the origin along +x with d1 = +z, under gravity g (m/s^2) along -z.
inline RodSpec straightWire(double length, int edges, double g = 0.0) {
  RodSpec s;
  s.length = length;
  s.coilEdges = edges;
  s.coil = wireSection(0.15e-3, 6e9, 0.39, 21450, 0, Vec3(0, 0, -g));
  return s;
}

// The whole rod deployed (slow push) and at equilibrium.
inline Rod fullyDeployed(const RodSpec& spec, SolveReport* rep) {
  return deployStatic(spec, spec.length, 0.0, spec.length / 10, rep);
}

}  // namespace refrod::testing

namespace refrod::testing {

// Material Darboux vector (kappa1, kappa2, tau) of a helix of loop diameter D
// and pitch p (m) with d1 the principal normal: (0, kappa, +-tau),
// kappa = R / (R^2 + c^2), tau = c / (R^2 + c^2), c = p / 2 pi.
inline Vec3 helixDarboux(double D, double p, bool right) {
  const double R = D / 2, c = p / (2 * M_PI), den = R * R + c * c;
  return Vec3(0, R / den, (right ? 1 : -1) * c / den);
}

}  // namespace refrod::testing
