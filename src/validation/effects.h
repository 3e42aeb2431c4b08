#pragma once
// Effects that only the validation workbench uses, and how its model builder
// treats them. `catheter_compliance` is a spring between the rigid catheter
// and the tip node (the clamp of the base model released), so it is
// registered here, with the builder that releases the clamp, rather than
// among the physics built-ins.
#include <memory>

#include "physics/effect.h"

namespace coilsim {
// Defined in src/physics/effects/gravity_tilt.cpp.
std::unique_ptr<Effect> makeGravityTiltEffect();
}  // namespace coilsim

namespace coilsim::validation {

// Adds catheter_compliance to the global registry once (thread-safe).
void ensureValidationEffects();

// True for an effect that replaces the rigid clamp at the tip by its own
// spring: the builder then releases the tip node.
bool releasesClamp(const EffectUse& use);

// The flexible free catheter segment at the tip: a cantilever of length L_c
// and bending stiffness EI_c carrying the coil's tip node. Its end stiffness
// (Euler-Bernoulli cantilever, end load and moment) in the tip frame
// (x along the exit direction):
//   (v, theta_z): EI/L^3 [[12, -6L], [-6L, 4L^2]],  (w, theta_y): EI/L^3 [[12, 6L], [6L, 4L^2]],
// with axial and torsional stiffness 100 times the lateral scale (the
// catheter neither stretches nor twists appreciably).
std::unique_ptr<Effect> makeCatheterComplianceEffect();

}  // namespace coilsim::validation
