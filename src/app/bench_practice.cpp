// The practice window's line of `coilsim bench` (bench_render.h): the 7 mm
// case with four coils of its set detached in the sac and a fifth pushed at
// 5 mm/s, drawn off-screen as the window draws it. Compiled with the ui layer
// only (src/app/CMakeLists.txt).
#include <cstdio>
#include <exception>
#include <filesystem>
#include <optional>

#include "app/bench_render.h"
#include "io/units.h"
#include "planning/case_file.h"
#include "planning/practice.h"
#include "planning/run_contacts.h"
#include "ui/render_bench.h"

namespace coilsim {
namespace {

namespace fs = std::filesystem;

// The four coils in the sac and the fifth: a framing, a filling and two
// finishing coils of the 7 mm case's set, as a coiling would go.
const char* const kPlaced[] = {"framing-3d-5x100", "filling-helical-4x80", "finishing-3x40", "finishing-2x20"};
const char* const kFifth = "finishing-2x10";
constexpr double kPlacingSpeedMmS = 20;  // the case's device limit: the quickest way to fill the sac
constexpr double kPushSpeedMmS = 5;      // the fifth coil, at a clinical speed

// The session that leaves four coils detached in the sac and the fifth in
// the catheter: each pushed out whole, detached 0.1 s later, the next one
// pushed 0.1 s after it went in.
std::vector<TimedCommand> placingTimeline(const planning::PracticeCase& pc, double& end) {
  std::vector<TimedCommand> t;
  double at = 0;
  for (const char* name : kPlaced) {
    double lengthMm = 0;
    for (const io::CoilSpec& c : pc.coils)
      if (c.name == name) lengthMm = c.lengthMm;
    t.push_back({at, {DeviceCommand::Kind::Push, units::mmPerSToMPerS(kPlacingSpeedMmS), 0}});
    at += lengthMm / kPlacingSpeedMmS + 0.1;
    t.push_back({at, {DeviceCommand::Kind::Detach, 0, 0}});
    at += 0.1;
  }
  end = at;
  return t;
}

ui::DrawDataHook practiceDrawing(const planning::PracticeCase&) {
  return [](const Model& m, const State& s, DrawData& d) {
    if (m.device) planning::appendInactiveCatheter(m, s, *m.device, d);
  };
}

}  // namespace

void benchPracticeWindowFigures(const std::function<void(const std::string&, double)>& set, bool quick, bool json) {
  const fs::path casePath = findSourceFile(fs::path("scenes") / "cases" / "sphere-7mm-wide-neck.json");
  if (casePath.empty()) {
    std::fprintf(stderr, "bench: practice window figures skipped: scenes/cases/sphere-7mm-wide-neck.json not found\n");
    return;
  }
  Model model, alone;
  State state, aloneState;
  ui::RenderBenchOptions o;
  try {
    const planning::PracticeCase pc = planning::loadCase(casePath.string());
    if (!json) std::fprintf(stderr, "bench: placing four coils in the 7 mm sac at %g mm/s...\n", kPlacingSpeedMmS);
    double end = 0;
    const std::vector<TimedCommand> timeline = placingTimeline(pc, end);
    planning::SessionCoils coils(kPlaced[0]);
    for (size_t k = 1; k < std::size(kPlaced); ++k) coils.next.push_back({kPlaced[k], std::nullopt});
    coils.next.push_back({kFifth, std::nullopt});
    const planning::ScoreSheet sheet =
        planning::playSession(pc, coils, timeline, {}, end + 0.05, nullptr, {}, [&](const planning::PracticeSession& s) {
          model = s.model();
          state = s.state();
        });
    size_t detached = 0;
    for (const planning::CoilOutcome& c : sheet.coils) detached += c.detached ? 1 : 0;
    if (!sheet.ok || sheet.coils.size() != std::size(kPlaced) + 1 || detached != std::size(kPlaced))
      throw std::runtime_error("placing the four coils failed (" + std::to_string(detached) + " detached)" +
                               (sheet.error.empty() ? "" : ": " + sheet.error));
    // The baseline: the fifth coil alone in the sac.
    const planning::PracticeSession fifth(pc, kFifth);
    alone = fifth.model();
    aloneState = fifth.state();
    o.addDrawData = practiceDrawing(pc);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bench: practice window figures skipped: %s\n", e.what());
    return;
  }
  DeviceCommand push;
  push.kind = DeviceCommand::Kind::Push;
  push.rate = units::mmPerSToMPerS(kPushSpeedMmS);
  o.timeline = {{0.0, push}};
  o.frames = quick ? 10 : 30;
  if (!json) std::fprintf(stderr, "bench: drawing the practice window at 1280x720 off-screen...\n");
  // The baseline of the drawing: the same frames drawn as the renderer drew
  // them before issue 16 (every tube at full detail, everything rebuilt
  // and sent each frame).
  ui::RenderBenchOptions before = o;
  before.adjustSettings = [](render::RenderSettings& s) {
    s.tubeDetailBySize = false;
    s.keepGeometry = false;
  };
  ui::RenderBenchResult r, b, a;
  std::string error;
  if (!ui::benchRender(model, state, o, r, error) || !ui::benchRender(model, state, before, b, error) ||
      !ui::benchRender(alone, aloneState, o, a, error)) {
    std::fprintf(stderr, "bench: practice window figures skipped: %s\n", error.c_str());
    return;
  }
  const double frameSimulated = units::sToMs(r.stepsPerFrame * model.timeStep);
  const double realTime = frameSimulated / r.physicsMsPerFrame, aloneRealTime = frameSimulated / a.physicsMsPerFrame;
  set("practice4_physics_realtime", realTime);
  set("practice4_physics_realtime_alone", aloneRealTime);
  set("practice4_physics_realtime_cpu", frameSimulated / r.physicsCpuMsPerFrame);
  set("practice4_ms_3d", r.ms3d);
  set("practice4_ms_xray", r.msXRay);
  set("practice4_ms_biplane", r.msBiplane);
  set("practice4_ms_3d_before", b.ms3d);
  set("practice4_ms_xray_before", b.msXRay);
  set("practice4_ms_biplane_before", b.msBiplane);
  set("practice4_cpu_ms_3d", r.cpuMs3d);
  set("practice4_cpu_ms_xray", r.cpuMsXRay);
  set("practice4_cpu_ms_biplane", r.cpuMsBiplane);
  set("practice4_cpu_ms_3d_before", b.cpuMs3d);
  set("practice4_cpu_ms_xray_before", b.cpuMsXRay);
  set("practice4_cpu_ms_biplane_before", b.cpuMsBiplane);
  if (json) return;
  std::printf("practice window, 4 coils detached in the 7 mm sac, 5th pushing at 5 mm/s: physics x real time, drawing "
              "ms per frame (3D, X-ray) (%s):\n",
              r.gl.c_str());
  std::printf("  physics %.2fx real time (%.1f ms, %.1f ms of CPU, for a %d-step frame: %.2fx real time in CPU time); the "
              "5th coil alone in the sac %.1fx: the four placed coils make it %.0fx slower%s\n",
              realTime, r.physicsMsPerFrame, r.physicsCpuMsPerFrame, r.stepsPerFrame,
              frameSimulated / r.physicsCpuMsPerFrame, aloneRealTime, aloneRealTime / realTime,
              r.refusedSteps ? " - some steps were refused" : "");
  std::printf("  drawing at 1280x720, wall ms per frame: 3D %.1f, X-ray %.1f, biplane %.1f; drawn as before issue 16 (this "
              "run): %.1f, %.1f, %.1f (%.2fx, %.2fx, %.2fx)\n",
              r.ms3d, r.msXRay, r.msBiplane, b.ms3d, b.msXRay, b.msBiplane, b.ms3d / r.ms3d, b.msXRay / r.msXRay,
              b.msBiplane / r.msBiplane);
  std::printf("  CPU ms per frame, every thread: 3D %.1f, X-ray %.1f, biplane %.1f; before: %.1f, %.1f, %.1f (%.2fx, "
              "%.2fx, %.2fx)\n",
              r.cpuMs3d, r.cpuMsXRay, r.cpuMsBiplane, b.cpuMs3d, b.cpuMsXRay, b.cpuMsBiplane, b.cpuMs3d / r.cpuMs3d,
              b.cpuMsXRay / r.cpuMsXRay, b.cpuMsBiplane / r.cpuMsBiplane);
}

}  // namespace coilsim
