#pragma once
// The quantities of a rod (coil, wire, catheter tube) that files, the command
// line, the panel and fits name, declared once: JSON key (edge unit in the
// name), unit, meaning, bounds of what is physical for a coil simulator,
// and the factor to SI. The scene reader, the measurement reader and the
// coil catalogue check their values against these bounds; the workbench
// fits them under these names.
#include <string_view>

#include "physics/param.h"

namespace coilsim::rodq {

// A rod quantity: its ParamSpec, and whether its lower bound is excluded
// (a length of 0 is no rod; a pitch of 0 is a closed helix).
struct Quantity {
  ParamSpec spec;
  bool minOpen = false;
};

// Geometry.
inline constexpr Quantity kLength{{"length_mm", "mm", "arc length of the rod or coil", 100.0, 0.0, 2000.0, 1e-3}, true};
inline constexpr Quantity kWireRadius{
    {"wire_radius_mm", "mm", "radius of the solid circular wire (or its stiffness equivalent)", 0.15, 0.0, 5.0, 1e-3},
    true};
inline constexpr Quantity kLoopDiameter{
    {"loop_diameter_mm", "mm", "diameter of the helical rest shape's loops", 7.0, 0.0, 100.0, 1e-3}, true};
inline constexpr Quantity kPitch{{"pitch_mm", "mm", "rise of the helical rest shape per loop", 0.5, 0.0, 100.0, 1e-3}};
// Material.
inline constexpr Quantity kYoungModulus{
    {"young_modulus_gpa", "GPa", "Young's modulus (platinum-tungsten coils 5-10 effective, polymer tubes 0.1-3)", 7.5, 0.1,
     1000.0, 1e9}};
inline constexpr Quantity kPoissonRatio{
    {"poisson_ratio", "1", "Poisson's ratio (isotropic stability: -1 < nu <= 0.5)", 0.39, -1.0, 0.5, 1.0}, true};
inline constexpr Quantity kDensity{
    {"density_g_cm3", "g/cm3", "density of the material (platinum 21.45, polymer 1.1-1.4)", 21.45, 0.5, 30.0, 1e3}};
// Explicit section constants.
inline constexpr Quantity kArea{{"area_mm2", "mm2", "cross-section area", 0.07, 0.0, 100.0, 1e-6}, true};
inline constexpr Quantity kInertia{{"inertia_mm4", "mm4", "second moment of area", 4e-4, 0.0, 1000.0, 1e-12}, true};
inline constexpr Quantity kTorsion{{"torsion_mm4", "mm4", "torsion constant", 8e-4, 0.0, 2000.0, 1e-12}, true};
inline constexpr Quantity kShearFactor{{"shear_factor", "1", "Timoshenko shear factor (0: Euler-Bernoulli)", 0.9, 0.0, 10.0, 1.0}};
inline constexpr Quantity kOuterRadius{
    {"outer_radius_mm", "mm", "outer radius the fluid and walls see", 0.15, 0.0, 5.0, 1e-3}, true};

// Every quantity above, in the order `coilsim help` lists them; a new
// quantity is declared above and named here.
inline constexpr const Quantity* kAll[] = {&kLength,  &kWireRadius, &kLoopDiameter, &kPitch,
                                           &kYoungModulus, &kPoissonRatio, &kDensity, &kArea,
                                           &kInertia, &kTorsion, &kShearFactor, &kOuterRadius};

// Discretisation and time (bounds the solver honours).
inline constexpr int kMaxBeams = 20000;           // beams of one rod
inline constexpr double kMaxTimeStepS = 0.01;     // s: a coil's fastest modes need far less

}  // namespace coilsim::rodq
