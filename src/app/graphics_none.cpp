// The graphics of the command files in a build without the ui layer
// (graphics.h): each function says so and fails as its contract says. CMake
// compiles this file instead of graphics_ui.cpp, bench_render.cpp,
// practice_window.cpp, validate_window.cpp and window_setup.cpp.
#include <cstdio>

#include "app/bench_render.h"
#include "app/exit_codes.h"
#include "app/graphics.h"
#include "app/practice_window.h"
#include "app/validate_plots.h"
#include "app/validate_window.h"

namespace coilsim::app {
namespace {

const std::string kNoGraphics = "built without graphics (no ui layer)";

}  // namespace

bool haveUi() { return false; }

int runSceneWindow(Model&, State&, const io::SceneSpec&, const RunOptions&, const std::vector<TimedCommand>&) {
  std::fprintf(stderr, "coilsim: no window: %s; run with --headless\n", kNoGraphics.c_str());
  return kExitUsage;
}

bool sceneScreenshot(const Model&, const State&, const io::SceneSpec&, const RunOptions& o, std::string& error) {
  error = o.screenshot + ": not written: " + kNoGraphics;
  return false;
}

bool planPicture(const Model&, const State&, const std::string&, int, int, const planning::Sac&, const std::string& path,
                 std::string& error) {
  error = path + ": not written: " + kNoGraphics;
  return false;
}

int caseEditorGraphics(planning::CaseEditor&, const std::string&, const std::string&, bool, const std::string&) {
  std::fprintf(stderr, "coilsim case edit: no window or screenshot: %s\n", kNoGraphics.c_str());
  return kExitUsage;
}

bool savePng(const std::string& path, const Canvas&, std::string& error) {
  error = path + ": not written (this build has no PNG writer: " + kNoGraphics + ")";
  return false;
}

bool practicePicture(const planning::PracticeCase&, const planning::PracticeSession&, const std::string& path,
                     PictureSize, std::string& error) {
  error = path + ": not written: " + kNoGraphics;
  return false;
}

int practiseInWindow(const planning::PracticeCase&, std::string, const std::string&, const std::vector<TimedCommand>&,
                     const std::vector<std::pair<double, std::string>>&, double, const std::string&, PictureSize,
                     std::shared_ptr<WindowOutputs>) {
  std::fprintf(stderr, "coilsim practice: no window: %s\n", kNoGraphics.c_str());
  return kExitUsage;
}

int runValidateWindow(const WorkbenchArgs&, const WindowArgs&) {
  std::fprintf(stderr, "coilsim validate: no panel (--window, --screenshot): %s\n", kNoGraphics.c_str());
  return kExitUsage;
}

}  // namespace coilsim::app

// The bench's render figures: none to report.
void coilsim::benchRenderFigures(const std::function<void(const std::string&, double)>&, bool, bool) {}
void coilsim::benchPracticeWindowFigures(const std::function<void(const std::string&, double)>&, bool, bool) {}
std::filesystem::path coilsim::findSourceFile(const std::filesystem::path&) { return {}; }
