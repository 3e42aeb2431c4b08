#pragma once
// A sac already packed with coil: coil laid in nested spherical spirals
// inside the practice case's 7 mm sac, with planning's contacts, for the
// dense-packing bench (`coilsim bench --contact`) and the test that the
// contacts keep such a packing apart (tests/planning/dense_sac_test.cpp).
#include "physics/model.h"

namespace coilsim::planning {

struct DenseSacSpec {
  double sacRadius = 3.5e-3;     // m: the practice case's 7 mm sac
  double wireRadius = 0.127e-3;  // m: a 0.010 inch primary coil
  double beam = 0.5e-3;          // m: planning's coil spacing
  double gap = 10e-6;            // m: clearance between neighbouring turns and shells
  double capRadius = 1.2e-3;     // m: polar caps this close to the axis are left empty
  int subdivisions = 4;          // of the icosphere wall (20 * 4^n triangles)
};

// `coilLength` m of coil in shells from the wall inwards, one rod per shell,
// turns and shells 2 r + gap apart: every segment lies within the contact
// margin of its neighbours and the outer shell within it of the wall. The
// rods rest in the shape they are laid in (no load but gravity, buoyancy and
// drag, which the model carries). The wire is the catalogue's
// filling-helical-4x80 (docs/coils.md). Fewer metres are laid when the
// shells down to 1.5 mm radius are full. Throws std::invalid_argument for a
// non-positive length.
ModelDef denseSacModel(double coilLength, const DenseSacSpec& spec = {});

// The packing of `coilLength` m of the spec's wire in its sphere (0-1).
double densePacking(double coilLength, const DenseSacSpec& spec = {});

}  // namespace coilsim::planning
