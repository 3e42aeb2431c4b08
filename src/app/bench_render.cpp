// Compiled with the ui layer only (src/app/CMakeLists.txt); graphics_none.cpp
// stands in for it without.
#include "app/bench_render.h"

#include <cstdio>
#include <exception>
#include <filesystem>

#include "io/scene.h"
#include "io/units.h"
#include "physics/run.h"
#include "ui/render_bench.h"

namespace coilsim {
namespace {

namespace fs = std::filesystem;

}  // namespace

fs::path findSourceFile(const fs::path& rel) {
  std::error_code ec;
  if (fs::exists(rel, ec)) return rel;
  // build*/src/app/coilsim is three levels down.
  fs::path dir = fs::read_symlink("/proc/self/exe", ec);
  if (ec) return {};
  for (int up = 0; up < 6 && dir.has_parent_path() && dir != dir.parent_path(); ++up) {
    dir = dir.parent_path();
    if (fs::exists(dir / rel, ec)) return dir / rel;
  }
  return {};
}

void benchRenderFigures(const std::function<void(const std::string&, double)>& set, bool quick, bool json) {
  const fs::path scene = findSourceFile(fs::path("scenes") / "default.json");
  if (scene.empty()) {
    std::fprintf(stderr, "bench: render figures skipped: scenes/default.json not found (run from the source tree)\n");
    return;
  }
  if (!json) std::fprintf(stderr, "bench: drawing %s at 1280x720 off-screen...\n", scene.c_str());
  ui::RenderBenchOptions o;
  Model model;
  State state;
  try {
    model = compileModel(io::compileScene(io::loadScene(scene.string())));
    state = makeState(model);
    if (model.device) {
      // Physics as in use: the coil pushed at a clinical 5 mm/s while drawing.
      DeviceCommand push;
      push.kind = DeviceCommand::Kind::Push;
      push.rate = units::mmPerSToMPerS(5.0);
      o.timeline = {{0.0, push}};
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bench: render figures skipped: %s\n", e.what());
    return;
  }
  o.frames = quick ? 10 : 30;
  ui::RenderBenchResult r;
  std::string error;
  if (!ui::benchRender(model, state, o, r, error)) {
    std::fprintf(stderr, "bench: render figures skipped: %s\n", error.c_str());
    return;
  }
  set("render_fps_3d_1280x720", r.fps3d);
  set("render_fps_xray_1280x720", r.fpsXRay);
  set("render_fps_biplane_1280x720", r.fpsBiplane);
  set("frame_steps", r.stepsPerFrame);
  set("frame_physics_ms", r.physicsMsPerFrame);
  set("frame_render_ms", r.renderMsPerFrame);
  set("frame_physics_share", r.physicsShare);
  set("frame_render_share", r.renderShare);
  if (json) return;
  std::printf("default scene drawn off-screen at 1280x720 (%s, %d samples in 3D):\n", r.gl.c_str(), r.samples);
  std::printf("  3D %.1f fps (%.1f ms), X-ray %.1f fps (%.1f ms), biplane %.1f fps (%.1f ms)\n", r.fps3d, r.ms3d,
              r.fpsXRay, r.msXRay, r.fpsBiplane, r.msBiplane);
  std::printf("  a real-time frame (%d steps while pushing at 5 mm/s, then the 3D view): physics %.1f ms (%.0f%%), "
              "drawing %.1f ms (%.0f%%)%s\n",
              r.stepsPerFrame, r.physicsMsPerFrame, 100 * r.physicsShare, r.renderMsPerFrame, 100 * r.renderShare,
              r.refusedSteps ? " - some steps were refused" : "");
}

}  // namespace coilsim

