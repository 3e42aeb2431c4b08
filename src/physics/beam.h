#pragma once
// The co-rotational 3D beam element of Dequidt et al. (MICCAI 2008), after
// Przemieniecki's Timoshenko beam (Theory of Matrix Structural Analysis,
// 1968, sec. 5.6). Why Timoshenko: its 12x12 stiffness uses the exact
// solution of the straight beam with shear, so one element is exact under
// end loads for any length-to-radius ratio (no shear locking), and it tends
// to Euler-Bernoulli as the shear factor Phi -> 0 for slender beams.
//
// Co-rotation, as in SOFA's BeamFEMForceField that the paper builds on: each
// element's x axis follows its current chord; its roll is that of the mean
// of the frames its two nodes carry (R_a Q and R_b P^T), so frames propagate
// from node to node along the chain from the constrained first node:
//   R_m = R_a Q exp(log((R_a Q)^T R_b P^T) / 2),  R_e = M R_m,
// M the least rotation taking R_m e_x onto the chord, Q the constant rest
// offset of the element frame in node a's frame. (The paper takes the roll
// from the first node alone; under bending plus torsion of a curved rod that
// is a first-order error in the beam length, the mean is second order.) In R_e
// the deformation is an axial stretch and two end rotations,
//   u_b = (|x_b - x_a| - L0, 0, 0),  theta_a = log(R_e^T R_a Q),  theta_b = log(R_e^T R_b P^T),
// P = rest rotation of b in the rest element frame. A rigid motion changes
// none of them (no spurious strain), and because x follows the chord the
// element's end forces balance moments about the deformed element, which a
// frame rigidly attached to node a does not (that error made large
// deflections converge at first order only).
#include "physics/math.h"
#include "physics/model.h"

namespace coilsim {

// Local 12x12 stiffness, DOFs (u, theta) of node a then node b; x along the
// element, y along d1, z along d2. shearFactor 0 gives Euler-Bernoulli.
Mat12 localBeamStiffness(double length, const Material& material, const Section& section);

struct BeamEval {
  Quat frame;         // current element frame R_e
  Mat3 rotation;      // the same as a rotation matrix
  Vec6 deformation;   // (u_b, theta_b) in the element frame
  Vec3 rotationA;     // theta_a in the element frame
  Vec6 forceA, forceB;  // elastic restoring force and moment on each node, global
  Mat6 kaa, kba, kbb;   // global tangent blocks (kab = kba^T), without geometric stiffness
  double energy = 0;    // strain energy, J
};

// Evaluates one element at the current node poses. Tangent blocks are filled
// only when `withTangent` is true.
void evalBeam(const BeamRest& rest, const Vec3& xa, const Quat& qa, const Vec3& xb, const Quat& qb,
              bool withTangent, BeamEval& out);

// Adds the global tangent of an element evaluated with rotation
// `BeamEval::rotation`, times `scale`, straight into a block-tridiagonal
// chain without the copies through BeamEval: K(a,a) += s kaa, K(b,a) = s kba,
// K(b,b) = s kbb. With `velocity` (the two nodes' (v, w)) it also adds this
// element's s K velocity to `product` (two entries). `string` > 0 adds the
// geometric stiffness of a tensile axial force N, string = s N / l (l the
// current length): string (1 - t t^T) on the translations, the stiffness of
// a taut string (the P / l term of a bar's geometric stiffness matrix, e.g.
// Przemieniecki, Theory of Matrix Structural Analysis, the chapter on
// stability), in the blocks and in the product.
void addBeamTangent(const BeamRest& rest, const Mat3& rotation, double scale, Mat6& diagA, Mat6& lowerBA,
                    Mat6& diagB, const Vec6* velocity = nullptr, Vec6* product = nullptr, double string = 0);

// Element rest constants from the rest poses of its two nodes.
BeamRest makeBeamRest(const Vec3& xa, const Quat& qa, const Vec3& xb, const Quat& qb,
                      const Material& material, const Section& section);

}  // namespace coilsim
