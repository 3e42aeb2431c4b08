#pragma once
// The model behind `coilsim case edit`: a case made from a surface, its neck
// plane and catheter tip moved by the user, the morphology recomputed after
// every move, and the case saved back with only those changed. No GL: the
// window (src/ui/case_editor_window.*, wired to this in src/app/case_window.cpp)
// draws it and forwards the user's drags and clicks; tests drive it directly.
// Millimetres.
#include <string>

#include <nlohmann/json.hpp>

#include "geometry/mesh_query.h"
#include "geometry/sac_morphology.h"
#include "planning/case_maker.h"

namespace coilsim::planning {

class CaseEditor {
 public:
  // Reads a case whose sac is {"mesh": ..., "neck_plane": ...} and whose
  // scene is inline (as `coilsim case new` writes them). Throws
  // io::InputError naming the file and what is missing.
  explicit CaseEditor(const std::string& caseFile);

  const TriangleMesh& surface() const { return query_.mesh(); }
  const geometry::MeshQuery& query() const { return query_; }
  const geometry::Plane& neck() const { return neck_; }
  const Catheter& catheter() const { return catheter_; }
  const Vec3& sacCentre() const { return sacCentre_; }
  const geometry::SacMorphology& morphology() const { return morphology_; }
  // Edits since the case was read or last marked saved.
  bool edited() const { return edited_; }
  // Why the last refused edit was refused, in words (empty after an accepted one).
  const std::string& refusal() const { return refusal_; }

  // Drag the neck plane along its normal (mm, + toward the dome); refused
  // (false, nothing changes, refusal() says why) when the plane would leave the sac centre on
  // the vessel side or cut off no sac.
  bool moveNeck(double mm);
  // Tilt it about an axis through its point (radians); same refusals.
  bool tiltNeck(const Vec3& axis, double radians);
  // A click on the surface: the neck plane through that point, same normal.
  bool placeNeckThrough(const Vec3& point);
  // The catheter tip at `point` (inside the surface), or pointing along
  // `direction` (unit after normalising); false when outside or degenerate.
  bool placeTip(const Vec3& point);
  bool pointTip(const Vec3& direction);

  // The case as it would be saved: the original document with the new neck
  // plane, catheter tip and direction and morphology.
  nlohmann::ordered_json document() const;
  // Writes document() atomically. Throws std::runtime_error naming the file.
  void save(const std::string& path) const;
  // After a save: edited() is false until the next accepted edit.
  void markSaved();

 private:
  bool tryNeck(const geometry::Plane& plane);
  bool refuse(std::string why);  // records why; returns false

  std::string file_;
  nlohmann::ordered_json doc_;
  geometry::MeshQuery query_;
  geometry::Plane neck_;
  Catheter catheter_;
  Vec3 sacCentre_ = Vec3::Zero();
  double vesselDiameter_ = 0;
  geometry::SacMorphology morphology_;
  bool edited_ = false;
  bool catheterMoved_ = false;  // only then is the scene's catheter rewritten
  std::string refusal_;
};

}  // namespace coilsim::planning
