#pragma once
// One rod as files describe it, in SI, before it is cut into beams: its
// length, rest shape, material constants and cross-section, the quantities
// physics/rod_quantities.h declares. The scene reader builds one per rod and
// for the deployed coil, the measurement reader one for the bench coil; a
// fit changes a copy (Young's modulus, loop diameter...) and samples again.
#include "physics/rest_shape.h"
#include "physics/section.h"

namespace coilsim {

struct RodSpec {
  double length = 0;        // m
  RestShapeDef rest;
  double youngModulus = 0;  // Pa
  double poissonRatio = 0;
  double density = 0;       // kg/m^3
  double wireRadius = 0;    // m: a solid circular wire; 0: the explicit constants below
  Section explicitSection;  // area, second moments, torsion, shear factor, outer radius (wireRadius 0)
};

// E, G = E / (2 (1 + nu)) and density of the rod.
Material materialOf(const RodSpec& rod);

// The circular wire's section (circularSection) or the explicit constants.
Section sectionOf(const RodSpec& rod);

// kg/m: density times the section's area.
double massPerLength(const RodSpec& rod);

}  // namespace coilsim
