#pragma once
// The flexible microcatheter of a deployment and the paper's composite
// model of the coil lying inside it (Dequidt et al., MICCAI 2008, sec. 2.3).
//
// The catheter is a beam chain of its own polymer tube whose proximal part
// is held (the guide catheter) and whose tip region is free, with a rest
// shape that is straight or steam-shaped (an angled tip of 45 or 90 deg, a J,
// an S). Where the coil lies inside a catheter element, the two share one
// composite element: stiffnesses add (EA, EI, GJ, kappa G A), and the rest
// rotation across the element blends the catheter's and the coil's
// (the coil's from the coil material that is there now, so it changes as the
// coil slides).
#include "physics/math.h"
#include "physics/element.h"
#include "physics/rest_shape.h"
#include "physics/section.h"

namespace coilsim {

// Steam-shaped tips, all bending towards the catheter's d1 (+y in the
// canonical placement) at the distal end: a straight stretch, then the arcs,
// ending at the tip.
struct CatheterShape {
  enum class Type { Straight, Angled, J, S } type = Type::Straight;
  double angle = 0;   // rad: the bend of Angled and J; each of the two opposite bends of S
  double radius = 0;  // m, radius of curvature of the bends
  // Arc length the bends take (0 for straight).
  double bendLength() const;
};

// How the composite rest rotation weighs catheter and coil.
//  - BendingStiffness (default): rotation vectors averaged with weights EI.
//    Two coaxial beams forced onto one centre line, each bending towards its
//    own rest curvature, are in equilibrium (moment balance
//    EI_1 (k - k_1) + EI_2 (k - k_2) = 0) at k = (EI_1 k_1 + EI_2 k_2) / (EI_1 + EI_2):
//    the minimum of the summed strain energy, for any two sections.
//  - YoungModulus: the paper's q = q_1 E_1/(E_1+E_2) + q_2 E_2/(E_1+E_2),
//    normalised. It equals the moment balance only when the two sections are
//    alike, which a polymer tube and a platinum wire are not; kept to
//    reproduce the paper.
enum class CompositeWeighting { BendingStiffness, YoungModulus };

struct CatheterDef {
  bool flexible = false;     // false: the rigid straight tip (nothing below is used)
  Material material;         // polymer, E about 0.1-1 GPa
  double outerRadius = 0.3e-3, innerRadius = 0.21e-3;  // m
  CatheterShape shape;
  double heldLength = 0.005;  // m held from the proximal end (guide catheter)
  double freeLength = 0.02;   // m of free tip region
  int beams = 25;
  CompositeWeighting weighting = CompositeWeighting::BendingStiffness;
};

// Tube of outer radius ro and inner ri: A = pi (ro^2 - ri^2),
// I = pi (ro^4 - ri^4) / 4, J = 2 I, Cowper's hollow-circle shear factor
// kappa = 6 (1+nu)(1+m^2)^2 / ((7+6nu)(1+m^2)^2 + (20+12nu) m^2), m = ri/ro
// (the solid circle's 6(1+nu)/(7+6nu) at m = 0).
Section tubeSection(double outerRadius, double innerRadius, double poisson);

// Canonical catheter centre line and frames (base at the origin, along +x,
// d1 +y, bends about d2 = +z), sampled exactly (straight pieces and circular
// arcs) at `beams` + 1 equally spaced arc lengths. Throws
// PhysicsError (physics/failure.h) if the bends are longer than `length`.
RestCurve makeCatheterRest(const CatheterShape& shape, double length, int beams);

// The composite rest rotation of node b in node a's frame, from the
// catheter's (`catheter`) and the coil's (`coil`), weights >= 0 (see
// CompositeWeighting for what they are).
Quat blendRestRotation(const Quat& catheter, const Quat& coil, double wCatheter, double wCoil, CompositeWeighting rule);

// Element constants of a composite element: catheter element of rest chord
// length `chord` and rest rotation `catheterRel` (b in a), with a fraction
// `coverage` in (0, 1] of it filled by coil material of rest rotation
// `coilRel` (expressed in the catheter's frames). Stiffnesses add (the coil's
// times the coverage); the rest rotation is blended with weights E or EI.
BeamRest compositeBeamRest(const Quat& catheterRel, double chord, const Quat& coilRel, double coverage,
                           const Material& catheter, const Section& catheterSection, const Material& coil,
                           const Section& coilSection, CompositeWeighting rule);

}  // namespace coilsim
