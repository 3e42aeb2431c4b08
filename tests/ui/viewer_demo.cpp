// A small driver of the ui layer on inline scenes, until the CLI calls it:
// opens the window (scripts/window-test runs it under Xvfb), renders
// off-screen, runs the render benchmark, and checks a window screenshot.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "coil_pixels.h"
#include "physics/state.h"
#include "render/image.h"
#include "scenes.h"
#include "ui/render_bench.h"
#include "ui/viewer.h"

namespace {

using namespace coilsim;

int usage() {
  std::fprintf(stderr,
               "usage: coilsim_viewer_demo window    [--scene helix|rod] [--view V] [--size WxH] [--seconds S]\n"
               "                                      [--screenshot PATH] [--paused]\n"
               "       coilsim_viewer_demo offscreen --screenshot PATH [--scene helix|rod] [--view V] [--size WxH]\n"
               "                                      [--no-panel]\n"
               "       coilsim_viewer_demo bench     [--scene helix|rod] [--size WxH] [--frames N]\n"
               "       (all but check-coil: [--samples N] multisampling of the 3D view)\n"
               "       coilsim_viewer_demo check-coil PATH [--min N] [--from-x X]\n"
               "       coilsim_viewer_demo compare-coil WINDOW.png REFERENCE.png [--min N] [--from-x X]\n"
               "                                      [--max-shift PX]\n");
  return 2;
}

bool parseSize(const std::string& s, int& w, int& h) { return std::sscanf(s.c_str(), "%dx%d", &w, &h) == 2; }

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) return usage();
  const std::string command = argv[1];
  std::string scene = "helix", view = "3d", shot;
  int width = 1024, height = 640, frames = 20, samples = -1;
  double seconds = -1;
  long minPixels = 300;
  int fromX = 400;
  double maxShift = 12;
  bool paused = false, panel = true;
  std::vector<std::string> positional;
  for (int i = 2; i < argc; ++i) {
    const std::string a = argv[i];
    auto next = [&]() -> std::string {
      if (i + 1 >= argc) {
        std::fprintf(stderr, "%s needs a value\n", a.c_str());
        std::exit(2);
      }
      return argv[++i];
    };
    if (a == "--scene") scene = next();
    else if (a == "--view") view = next();
    else if (a == "--size") { if (!parseSize(next(), width, height)) return usage(); }
    else if (a == "--seconds") seconds = std::atof(next().c_str());
    else if (a == "--screenshot") shot = next();
    else if (a == "--frames") frames = std::atoi(next().c_str());
    else if (a == "--samples") samples = std::atoi(next().c_str());
    else if (a == "--min") minPixels = std::atol(next().c_str());
    else if (a == "--from-x") fromX = std::atoi(next().c_str());
    else if (a == "--max-shift") maxShift = std::atof(next().c_str());
    else if (a == "--paused") paused = true;
    else if (a == "--no-panel") panel = false;
    else if (!a.empty() && a[0] != '-') positional.push_back(a);
    else return usage();
  }

  if (command == "check-coil") {
    if (positional.size() != 1) return usage();
    render::Image image;
    std::string error;
    if (!render::readPng(positional[0], image, error)) {
      std::fprintf(stderr, "%s\n", error.c_str());
      return 1;
    }
    const long n = testing::countCoilPixels(image, fromX);
    std::printf("%s: %dx%d, %ld coil-coloured pixels right of x = %d (need %ld)\n", positional[0].c_str(), image.width,
                image.height, n, fromX, minPixels);
    return n >= minPixels ? 0 : 1;
  }

  // The window's picture of a pushed coil against the headless picture of
  // the same run: the coil must be there, as large, in the same place.
  if (command == "compare-coil") {
    if (positional.size() != 2) return usage();
    render::Image shot, ref;
    std::string error;
    if (!render::readPng(positional[0], shot, error) || !render::readPng(positional[1], ref, error)) {
      std::fprintf(stderr, "%s\n", error.c_str());
      return 1;
    }
    const testing::CoilSpot a = testing::coilSpot(shot, fromX), b = testing::coilSpot(ref, fromX);
    const double shift = std::hypot(a.x - b.x, a.y - b.y);
    std::printf("coil pixels right of x = %d: window %ld at (%.1f, %.1f), reference %ld at (%.1f, %.1f): "
                "%.1f px apart (at most %.1f), count ratio %.2f (0.6 to 1.6), need %ld\n",
                fromX, a.count, a.x, a.y, b.count, b.x, b.y, shift, maxShift,
                b.count ? double(a.count) / double(b.count) : 0.0, minPixels);
    const bool ok = a.count >= minPixels && b.count >= minPixels && shift <= maxShift &&
                    double(a.count) >= 0.6 * double(b.count) && double(a.count) <= 1.6 * double(b.count);
    return ok ? 0 : 1;
  }

  const bool helix = scene == "helix";
  if (!helix && scene != "rod") return usage();
  Model model = helix ? testing::helixModel() : testing::straightRodModel();
  State state = makeState(model);
  ui::ViewerOptions o;
  o.scenePath = "inline " + scene + " scene";
  o.view = view;
  o.width = width;
  o.height = height;
  o.drawPanel = panel;
  o.runSeconds = seconds;
  o.startPaused = paused;
  o.samples = samples;
  o.addDrawData = helix ? testing::decorateHelix : testing::decorateRod;

  if (command == "window") {
    o.windowScreenshotPath = shot;
    const int code = ui::runWindow(model, state, o);
    std::printf("window closed at t = %.4f s, %ld refused steps, exit %d\n", state.time, state.blowups, code);
    return code;
  }
  if (command == "offscreen") {
    o.screenshotPath = shot;
    std::string error;
    if (!ui::renderOffscreen(model, state, o, error)) {
      std::fprintf(stderr, "%s\n", error.c_str());
      return 1;
    }
    std::printf("wrote %s\n", shot.c_str());
    return 0;
  }
  if (command == "bench") {
    ui::RenderBenchOptions b;
    b.width = width;
    b.height = height;
    b.frames = frames;
    b.samples = samples;
    b.addDrawData = o.addDrawData;
    ui::RenderBenchResult r;
    std::string error;
    if (!ui::benchRender(model, state, b, r, error)) {
      std::fprintf(stderr, "%s\n", error.c_str());
      return 1;
    }
    std::printf("%dx%d on %s, %d samples in 3d\n", width, height, r.gl.c_str(), r.samples);
    std::printf("3d       %7.1f fps  (%.2f ms)\n", r.fps3d, r.ms3d);
    std::printf("xray     %7.1f fps  (%.2f ms)\n", r.fpsXRay, r.msXRay);
    std::printf("biplane  %7.1f fps  (%.2f ms)\n", r.fpsBiplane, r.msBiplane);
    std::printf("stepping %d steps/frame: physics %.2f ms (%.0f%%), drawing %.2f ms (%.0f%%), %ld refused\n",
                r.stepsPerFrame, r.physicsMsPerFrame, 100 * r.physicsShare, r.renderMsPerFrame, 100 * r.renderShare,
                r.refusedSteps);
    return 0;
  }
  return usage();
}
