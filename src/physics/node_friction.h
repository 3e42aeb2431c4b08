#pragma once
// Coulomb friction on a node held against a wall by unilateral constraints
// (physics/unilateral.h): what an effect tells the step's solve about it,
// and what the solve leaves for the next step. The normal force is the
// node's multiplier from the same solve, so stick or slide is decided on
// the force the wall exerts in this step, not the last one's
// (docs/contact.md, "Friction under the constraint").
#include "physics/math.h"

namespace coilsim {

// A held node's friction as one step's solve ended it: the regularised
// Coulomb spring's stretch (m, in the wall's tangent plane; at most the
// dynamic cone's while sliding), the node's normal force from all its wall
// constraints (N) and whether it slid.
struct NodeFrictionMemory {
  Vec3 stretch = Vec3::Zero();
  double force = 0;
  bool sliding = false;
};

// Friction of one constrained node: static and dynamic coefficients, the
// stick spring (N/m) and its damping (N s/m), the memory the last step
// left (`start`), and where the solve writes this step's (`end`, may be
// null).
struct NodeFriction {
  double muStatic = 0, muDynamic = 0;
  double stiffness = 0, damping = 0;
  NodeFrictionMemory start;
  NodeFrictionMemory* end = nullptr;
  bool any() const { return muStatic > 0 || muDynamic > 0; }
};

}  // namespace coilsim
