#pragma once
// Case files ("coilsim-case/1", scenes/cases/*.json, docs/planning.md): an
// aneurysm (scene with a deployment block, and the sac: surface and neck
// plane), the catheter position (the scene's), the coil set a trainee or a
// plan may use, and the goal. Read through the io layer; errors are
// io::InputErrors naming the file, the JSON path and what was expected.
#include <optional>
#include <string>
#include <vector>

#include "io/coil_catalogue.h"
#include "io/json_reader.h"
#include "io/scene.h"
#include "planning/sac_geometry.h"

namespace coilsim::planning {

inline constexpr const char* kCaseFormat = "coilsim-case/1";

struct Goal {
  double minPackingDensity = 0.25;   // 0-1
  bool noProtrusion = true;
  double maxWallForce = 0.1;         // N (safety threshold for the score's "time above")
  bool detachInSac = true;
};

// A named deployment order of coils from the case's set (framing, filling,
// finishing), the sequence `coilsim plan CASE --sequence NAME` deploys.
struct CoilSequence {
  std::string name;
  std::vector<io::CoilSpec> coils;  // in deployment order
};

struct PracticeCase {
  std::string file, name, description;
  io::SceneSpec scene;               // with a deployment block
  Sac sac;
  std::vector<io::CoilSpec> coils;   // the coil set, from the catalogue
  std::vector<CoilSequence> sequences;  // "sequences": each a list of names from the coil set
  Goal goal;
  double spacingMm = 0.5;            // beam length of the coils
};

// The "sac" block: {"sphere": {"centre_mm", "radius_mm", "subdivisions"}, "neck_plane": {"point_mm", "normal"}}.
// The normal points into the sac. Throws InputError.
Sac readSac(const io::JsonNode& node);

// Reads a case: "scene" is a path relative to the case file or an inline
// scene object; "coils" names catalogue coils ("catalogue": directory
// relative to the case file, default the project's assets/coils);
// "sequences" (optional) is [{"name": ..., "coils": [names of the set]}].
// A sequence naming a coil outside the set, or two sequences of one name,
// is an InputError naming the file and the field.
PracticeCase loadCase(const std::string& path);
PracticeCase parseCase(const nlohmann::json& document, const std::string& file);

// The case's sequence called `name`; throws io::InputError naming the case
// file and the sequences it has when there is none.
const CoilSequence& findSequence(const PracticeCase& c, const std::string& name);

// The coil catalogue directory: assets/coils of the data directory set by
// setDataDirectory (an installed program's share/coilsim), else of the source
// tree this library was built from.
std::string defaultCatalogue();
void setDataDirectory(const std::string& dir);

// The sac of a phantom STL made by `coilsim phantom`: its surface and the
// neck plane of its sidecar (io::phantomSidecarPath). Throws InputError
// naming the file when either cannot be read.
Sac phantomSac(const std::string& stlPath);

// The sac of a scene, for live read-outs in a plain window: the first
// obstacle whose mesh has a phantom sidecar, placed as the scene places it
// (scale, rotation, offset). Empty when no obstacle has one; `note` then
// says why (or names the sidecar used).
std::optional<Sac> sceneSac(const io::SceneSpec& scene, std::string& note);

// A sac from a stand-alone JSON file holding a "sac" block at its root
// ({"sac": {...}}), for `coilsim plan SCENE --sac FILE`.
Sac loadSac(const std::string& path);

}  // namespace coilsim::planning
