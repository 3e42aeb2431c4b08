#pragma once
// What the app hands the window (ui::ViewerOptions) beyond the scene: live
// planning read-outs (packing, protrusion, wall-force warnings) and the
// panel's coil and catheter choice, built here because they need the io and
// planning layers that the ui does not link.
#include <optional>
#include <string>
#include <vector>

#include "io/coil_catalogue.h"
#include "io/scene.h"
#include "physics/deployment.h"
#include "planning/case_file.h"
#include "planning/sac_geometry.h"
#include "ui/readouts.h"
#include "ui/setup.h"

namespace coilsim::app {

// Read-outs of the coil of `dep` in `sac`, warning above `wallForceLimit` N.
ui::ReadoutHook liveReadouts(const planning::Sac& sac, const Deployment& dep, double wallForceLimit,
                             const std::string& title);

// "finishing-3x40: helical, 3 mm loops, 40 mm, B 0.00082 N mm2".
std::string coilLabel(const io::CoilSpec& coil);

// A catheter tip shape the panel offers.
struct CatheterChoice {
  std::string label;
  bool keepScene = false;  // the scene's own catheter
  bool flexible = false;
  CatheterShape::Type type = CatheterShape::Type::Straight;
  double angleDeg = 0, radiusMm = 0;
};
// The scene's own catheter first, then rigid straight and the flexible
// pre-shaped tips the physics supports (straight, 45 and 90 deg, J, S).
std::vector<CatheterChoice> catheterChoices(const io::CatheterSpec& scene);
// Puts a choice into a deployment spec: the catheter keeps its approach and
// tip position, the tip points where the shape turns it; a flexible tip
// keeps the scene's tube if it is flexible, else takes a soft polymer tube
// (README, "The window, views and screenshots").
void applyCatheter(const CatheterChoice& choice, io::DeploymentSpec& deployment);

// The plain window's choice: the whole catalogue and every tip shape for
// `scene` (which must have a deployment); each build recompiles the scene
// and, when it has a phantom sac, gives the live read-outs. `sac` may be empty.
ui::SetupChoices sceneSetupChoices(const io::SceneSpec& scene, const std::optional<planning::Sac>& sac);

}  // namespace coilsim::app
