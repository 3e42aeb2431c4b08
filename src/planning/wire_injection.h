#pragma once
// The wire-injection experiment of the dense-packing literature, in
// coilsim: a straight elastic wire pushed in strokes at constant speed through a
// catheter tip at the wall into a rigid spherical cavity (Stoop, Najafi,
// Wittel, Habibi, Herrmann, PRL 106, 214102, 2011; Vetter, Wittel, Stoop,
// Herrmann, Eur. J. Mech. A 37, 160, 2013). Stated, as they state it, in
// dimensionless terms: the cavity-to-wire diameter ratio D/d, the Coulomb
// friction coefficient mu (wall and wire-wire alike), the torsion injected
// with the wire (turns per cavity diameter pushed) and the injected length
// as a packing fraction phi = (pi d^2 / 4) L / (pi D^3 / 6). The wire has
// the bending and torsional stiffness of a 0.010-inch platinum primary coil
// (the catalogue's filling-helical-4x80, docs/coils.md) but a straight rest
// shape, as the papers' wires. No gravity or fluid, so that D/d, mu and the
// torsion alone set the shape.
// docs/planning.md, "A published check of dense packing".
#include <string>
#include <vector>

#include "physics/model.h"

namespace coilsim::planning {

struct WireInjectionSpec {
  double cavityRatio = 20;        // D / d
  double friction = 0;            // mu: static coefficient; dynamic 0.9 mu (Vetter et al. 2015's ratio)
  double turnsPerDiameter = 0;    // twist turned at the catheter per cavity diameter of wire pushed
  double targetPacking = 0.10;    // phi at which the injection stops
  double wireDiameter = 0.254e-3; // m
  double beam = 0.5e-3;           // m, the coil spacing of planning's runs
  double pushSpeed = 20e-3;       // m/s
  double stroke = 1e-3;           // m pushed between two feels of the force
  double jamForceRatio = 200;     // stop (jammed) when the felt push force exceeds this times B / R^2
  double tilt = 0.05;             // rad the tip leans off the radial direction (breaks the symmetry)
  int wallSubdivisions = 4;       // icosphere of 20 * 4^n triangles
};

// One felt force: after a stroke, the pusher at rest.
struct InjectionSample {
  double injected = 0;  // m out of the catheter
  double packing = 0;   // phi
  double force = 0;     // N, axial force felt at the pusher
};

struct WireInjectionResult {
  bool ok = true;         // false: a step was refused, or twice the time the strokes need ran out (error says why)
  std::string error;
  bool jammed = false;    // stopped by the force, before the target packing
  double injected = 0;    // m
  double packing = 0;     // phi reached
  double order = 0;       // winding order W of the wire (planning/winding_order.h), 0..1
  double maxForce = 0;    // N felt
  double forceScale = 0;  // B / R^2, N
  double maxWallPenetrationOfRadius = 0;
  double simulated = 0;   // s
  long steps = 0;
  std::vector<InjectionSample> samples;
  std::vector<Vec3> wire; // m, the wire's centre line at the end, from the tip
};

// The model of the spec: cavity of diameter D centred at the origin, the
// catheter tip just inside the wall at -z, pushing towards +z. Throws
// std::invalid_argument naming the field when a value is out of range.
Model wireInjectionModel(const WireInjectionSpec& spec);

// Runs the injection to the target packing, a jam, a refused step or twice
// the simulated time the strokes and rests need (then not ok).
WireInjectionResult runWireInjection(const WireInjectionSpec& spec);

// phi of `length` m of wire of diameter d in a sphere of diameter D.
double injectedPacking(double length, double wireDiameter, double cavityDiameter);

}  // namespace coilsim::planning
