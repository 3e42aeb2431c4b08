#pragma once
// The first (framing) coil from the sac's morphology, and its neighbours in
// the catalogue for `coilsim plan` to compare. The rule, its numbers and
// their sources are in docs/planning.md, "First coil".
#include <string>
#include <vector>

#include "geometry/sac_morphology.h"
#include "io/coil_catalogue.h"

namespace coilsim::planning {

// Share of the sac volume the framing coil alone should fill: one third of
// the 24 % total packing above which Sluzewski et al. (Radiology
// 2004;231:653-8) saw no compaction (the third is this project's convention).
inline constexpr double kFramingPacking = 0.08;

struct FirstCoil {
  double loopDiameterMm = 0;  // = the mean sac diameter
  double lengthMm = 0;        // kFramingPacking * volume / (pi r^2), r = primary radius
  double primaryDiameterMm = 0;
  std::string rule;           // the rule in one sentence, with its numbers
  std::string best;           // the catalogue coil nearest the sized one
  std::vector<std::string> neighbours;  // `best` first, then the next nearest (at most `count` in all)
};

// Sizes the framing coil for `m` (millimetres) with the primary diameter of
// the catalogue's framing coils (their median; 0.2921 mm when there is none)
// and ranks the catalogue's framing and complex coils by their distance to it
// (loop diameter first, length second). Throws std::invalid_argument when the
// sac has no volume.
FirstCoil recommendFirstCoil(const geometry::SacMorphology& m, const std::vector<io::CoilSpec>& catalogue, int count = 3);

}  // namespace coilsim::planning
