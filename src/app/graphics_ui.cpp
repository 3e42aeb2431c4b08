// The graphics of the command files with the ui layer (graphics.h); the
// build without it compiles graphics_none.cpp instead.
#include "app/graphics.h"

#include <cstdio>
#include <optional>

#include "app/case_window.h"
#include "app/exit_codes.h"
#include "app/sac_drawing.h"
#include "app/validate_plots.h"
#include "app/window_setup.h"
#include "planning/case_file.h"
#include "planning/plan.h"
#include "render/image.h"
#include "ui/viewer.h"

namespace coilsim::app {
namespace {

ui::ViewerOptions viewerOptions(const RunOptions& o) {
  ui::ViewerOptions v;
  v.scenePath = o.scene;
  if (o.view) v.view = *o.view;
  if (o.width) v.width = *o.width;
  if (o.height) v.height = *o.height;
  v.screenshotPath = o.screenshot;
  return v;
}

}  // namespace

bool haveUi() { return true; }

int runSceneWindow(Model& model, State& state, const io::SceneSpec& spec, const RunOptions& o,
                   const std::vector<TimedCommand>& timeline) {
  ui::ViewerOptions v = viewerOptions(o);
  v.screenshotPath.clear();
  v.windowScreenshotPath = o.screenshot;
  if (o.steps) v.runSeconds = double(*o.steps) * model.timeStep;
  if (o.durationS) v.runSeconds = *o.durationS;
  // The window plays the timeline as the headless run does (ui::Session).
  if (model.device) {
    v.timeline = timeline;
    // Packing, protrusion and wall-force warnings live when an obstacle is a phantom with its sac.
    std::string note;
    const std::optional<planning::Sac> sac = planning::sceneSac(spec, note);
    if (sac) v.readouts = liveReadouts(*sac, *model.device, planning::Goal{}.maxWallForce, "Aneurysm read-outs");
    std::printf("coilsim: live read-outs: %s\n", sac ? note.c_str() : ("none: " + note).c_str());
    v.setup = sceneSetupChoices(spec, sac);
  }
  // A coil or catheter chosen in the panel replaces the model.
  return ui::runWindow(model, state, v);
}

bool sceneScreenshot(const Model& model, const State& state, const io::SceneSpec& spec, const RunOptions& o,
                     std::string& error) {
  ui::ViewerOptions v = viewerOptions(o);
  // The panel's sections as the window shows them: the read-outs, the coil and catheter.
  if (model.device) {
    std::string note;
    const std::optional<planning::Sac> sac = planning::sceneSac(spec, note);
    if (sac) v.readouts = liveReadouts(*sac, *model.device, planning::Goal{}.maxWallForce, "Aneurysm read-outs");
    v.setup = sceneSetupChoices(spec, sac);
  }
  return ui::renderOffscreen(model, state, v, error);
}

bool planPicture(const Model& model, const State& state, const std::string& title, int width, int height,
                 const planning::Sac& sac, const std::string& path, std::string& error) {
  ui::ViewerOptions v;
  v.scenePath = title;
  v.width = width, v.height = height;
  v.screenshotPath = path;
  v.drawPanel = false;
  const auto mesh = sac.mesh;
  const DrawMesh neck = neckDisc(sac);
  // Runs have the sac as a wall (drawn with the model's obstacles); a scene's own wall may be another mesh.
  v.addDrawData = [mesh, neck](const Model& m, const State&, DrawData& d) {
    if (!neck.triangles.empty()) d.meshes.push_back(neck);
    if (!mesh) return;
    for (const Obstacle& o : m.obstacles)
      if (o.mesh == mesh) return;
    DrawMesh dm;
    dm.name = mesh->name;
    dm.vertices = mesh->vertices;
    dm.triangles = mesh->triangles;
    d.meshes.push_back(std::move(dm));
  };
  v.legend = sacLegend(sac);
  return ui::renderOffscreen(model, state, v, error);
}

int caseEditorGraphics(planning::CaseEditor& editor, const std::string& caseFile, const std::string& savePath,
                       bool window, const std::string& screenshot) {
  const ui::CaseEditorHooks hooks = caseEditorHooks(editor, caseFile, savePath);
  ui::CaseEditorWindowOptions wo;
  wo.screenshotPath = screenshot;
  if (window) return ui::runCaseEditorWindow(hooks, wo);
  std::string error;
  if (!ui::renderCaseEditorOffscreen(hooks, wo, error)) {
    std::fprintf(stderr, "coilsim case edit: %s\n", error.c_str());
    return kExitFailure;
  }
  return -1;
}

bool savePng(const std::string& path, const Canvas& c, std::string& error) {
  render::Image img;
  img.width = c.width, img.height = c.height, img.pixels = c.pixels;
  return render::writePng(path, img, error);
}

}  // namespace coilsim::app
