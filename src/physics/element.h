#pragma once
// Per-element and per-node constants of a rod, as the step integrates them.
// The Model holds each rod's nominal ones; a deployment rewrites a copy in
// the State as coil material slides through the catheter tip, and the step
// integrates the State's copy (RodState::beams, RodState::nodes).
#include "physics/math.h"

namespace coilsim {

// Per-element constants of the co-rotational beam (see beam.h).
struct BeamRest {
  double length = 0;               // rest chord length L0
  Quat nodeToElement;              // Q: rest element frame expressed in node a's frame
  Quat restRelative;               // P: node b's rest frame in the rest element frame
  Mat12 stiffness;                 // local 12x12 stiffness (Przemieniecki, Timoshenko)
  // The few distinct entries of `stiffness` (its 3x3 blocks are diagonal or
  // hold two off-diagonal terms), so the global tangent is a handful of
  // outer products instead of twelve 3x3 triple products.
  Vec3 axial;      // K(0,0), K(1,1), K(2,2): translational diagonal
  Vec3 rotSelf;    // K(3,3), K(4,4), K(5,5): rotational diagonal
  Vec3 rotCross;   // K(3,9), K(4,10), K(5,11): rotational coupling a-b
  double shearY = 0, shearZ = 0;  // K(1,5) and -K(2,4): bending-shear coupling
};

// Lumped properties of one node as the step uses them.
struct NodeProps {
  double mass = 0;              // kg
  Vec3 inertia = Vec3::Zero();  // rotational inertia in the material frame (t, d1, d2), kg m^2
  double length = 0;            // length of rod the node stands for, m
  double radius = 0;            // outer radius there (buoyancy, drag, contact), m
};

}  // namespace coilsim
