#pragma once
// Material and cross-section of a rod, SI units.
namespace coilsim {

struct Material {
  double youngModulus = 0;   // E, Pa
  double shearModulus = 0;   // G, Pa
  double density = 0;        // kg/m^3 (mass per length = density * area)
};

struct Section {
  double area = 0;         // A, m^2
  double iy = 0, iz = 0;   // second moments about the local d1 / d2 axes, m^4
  double torsion = 0;      // torsion constant J, m^4
  double shearFactor = 0;  // Timoshenko kappa; 0 = no shear deformation (Euler-Bernoulli)
  double radius = 0;       // outer radius, m: contact and drawing
};

// Solid circular wire: A = pi r^2, I = pi r^4 / 4, J = 2 I, and Cowper's
// shear factor kappa = 6 (1 + nu) / (7 + 6 nu) for a circle.
Section circularSection(double radius, double poisson);

// Shear modulus of an isotropic material: G = E / (2 (1 + nu)).
inline double shearModulusOf(double young, double poisson) { return young / (2.0 * (1.0 + poisson)); }

}  // namespace coilsim
