#pragma once
// A case (coilsim-case/1) made from a patient's surface: the surface checked
// and repaired as `coilsim mesh` does, the sac and neck found
// (geometry/sac_finder.h), the morphology measured, the first coil sized and
// the catheter tip placed inside the neck, coming from the parent vessel.
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "geometry/sac_finder.h"
#include "geometry/sac_morphology.h"
#include "planning/first_coil.h"

namespace coilsim::planning {

struct CaseRequest {
  std::string surface;           // STL, OBJ, PLY or OFF, millimetres
  std::string out;               // the case file to write (paths in it are relative to it)
  std::optional<Vec3> sacPoint;  // mm: a point in the sac when the search is unsure
  std::string catalogue;         // coil catalogue directory (empty: the project's)
};

struct Catheter {
  Vec3 tip = Vec3::Zero();             // mm
  Vec3 direction = Vec3::UnitZ();      // unit, into the sac
  Vec3 referenceNormal = Vec3::UnitX();  // unit, across `direction`
};

struct MadeCase {
  geometry::SacFinding sac;            // mm
  geometry::SacMorphology morphology;  // mm
  FirstCoil firstCoil;
  Catheter catheter;
  nlohmann::ordered_json document;     // the case file's content
};

// Raised when the surface cannot be used or the sac is not clear; `what()`
// names the file and the reason (for a CLI: exit 2).
struct CaseError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// The tip: on the neck's centre, 0.3 of the dome height into the sac along
// the neck normal, pointing into the sac; its bend plane holds the parent
// vessel's tangent.
Catheter placeCatheter(const geometry::SacFinding& sac, const geometry::SacMorphology& m);

// The "morphology" block of a case (mm, mm^3, ratios).
nlohmann::ordered_json morphologyJson(const geometry::SacMorphology& m, double vesselDiameterMm);

// Does everything but writing. Throws CaseError (or io::InputError for an
// unreadable file).
MadeCase makeCase(const CaseRequest& request);

}  // namespace coilsim::planning
