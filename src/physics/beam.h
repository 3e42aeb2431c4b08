#pragma once
// The co-rotational 3D beam element of Dequidt et al. (MICCAI 2008), after
// Przemieniecki's Timoshenko beam (Theory of Matrix Structural Analysis,
// 1968, sec. 5.6). Why Timoshenko: its 12x12 stiffness uses the exact
// solution of the straight beam with shear, so one element is exact under
// end loads for any length-to-radius ratio (no shear locking), and it tends
// to Euler-Bernoulli as the shear factor Phi -> 0 for slender beams.
//
// Co-rotation: each element's frame is carried by its first node a (the one
// nearer the rod's first, constrained node), R_e = R_a Q, Q the constant rest
// offset that aligns the frame's x with the chord. In that frame node a has
// zero displacement and rotation by construction; node b's deformation is
//   u_b = R_e^T (x_b - x_a) - (L0, 0, 0),   theta_b = log(R_e^T R_b P^T),
// P = rest rotation of b in the rest element frame. A rigid motion of the
// whole chain changes neither, so large rotations cause no spurious strain.
#include "physics/math.h"
#include "physics/model.h"

namespace coilsim {

// Local 12x12 stiffness, DOFs (u, theta) of node a then node b; x along the
// element, y along d1, z along d2. shearFactor 0 gives Euler-Bernoulli.
Mat12 localBeamStiffness(double length, const Material& material, const Section& section);

struct BeamEval {
  Quat frame;         // current element frame R_e
  Vec6 deformation;   // (u_b, theta_b) in the element frame
  Vec6 forceA, forceB;  // elastic restoring force and moment on each node, global
  Mat6 kaa, kba, kbb;   // global tangent blocks (kab = kba^T), without geometric stiffness
  double energy = 0;    // strain energy, J
};

// Evaluates one element at the current node poses. Tangent blocks are filled
// only when `withTangent` is true.
void evalBeam(const BeamRest& rest, const Vec3& xa, const Quat& qa, const Vec3& xb, const Quat& qb,
              bool withTangent, BeamEval& out);

// Element rest constants from the rest poses of its two nodes.
BeamRest makeBeamRest(const Vec3& xa, const Quat& qa, const Vec3& xb, const Quat& qb,
                      const Material& material, const Section& section);

}  // namespace coilsim
