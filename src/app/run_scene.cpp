#include "app/run_scene.h"
#include "app/commands.h"
#include "app/format.h"
#include "app/graphics.h"
#include "app/progress.h"
#include "app/stop_signal.h"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>

#include "io/result.h"
#include "io/scene.h"
#include "io/timeline.h"
#include "io/units.h"
#include "physics/run.h"
#include "physics/deployment.h"
#include "physics/integrator.h"
#include "physics/model.h"
#include "physics/state.h"
#include "planning/case_file.h"
#include "planning/live_readouts.h"


namespace coilsim::app {
namespace {

using Clock = std::chrono::steady_clock;

int usageError(const std::string& message) {
  std::fprintf(stderr, "coilsim: %s\n", message.c_str());
  return kExitUsage;
}

// "(x, y, z) mm" of a point given in metres.
std::string mm(const Vec3& x) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "(%.4g, %.4g, %.4g) mm", units::mToMm(x.x()), units::mToMm(x.y()),
                units::mToMm(x.z()));
  return buf;
}

std::string tips(const Model& model, const State& state) {
  std::string s;
  for (size_t k = 0; k < model.rods.size() && k < 3; ++k)
    s += std::string(k ? ", " : "; ") + "last node of \"" + model.rods[k].name + "\" at " + mm(state.rods[k].x.back());
  if (model.rods.size() > 3) s += ", ...";
  return s;
}

struct Outcome {
  bool ok = true;
  bool stopped = false;  // by SIGINT or SIGTERM, after a whole step
  std::string summary;  // one line, without the scene name
  std::optional<Failure> failure;  // why it failed (not ok, not stopped)
};

std::string stepSummary(const Model& model, const State& state, long done, long steps, double seconds) {
  const StepStats& st = state.stats;
  const double meanUs = st.steps ? units::sToUs(st.totalStepSeconds / double(st.steps)) : 0.0;
  const Energy e = computeEnergy(model, state);
  return "dynamic, " + std::to_string(done) + " of " + std::to_string(steps) + " steps of " +
         fmt("%.4g", units::sToMs(model.timeStep)) + " ms to t = " + fmt("%.6g", state.time) + " s in " + fmt("%.3g", seconds) +
         " s (step mean " + fmt("%.3g", meanUs) + " us, max " + fmt("%.3g", units::sToUs(st.maxStepSeconds)) +
         " us); energy " + fmt("%.4g", e.total()) + " J (kinetic " + fmt("%.3g", e.kinetic) + " J)";
}

// The record of a run stopped by a signal: still a valid result of the state reached.
Outcome stopped(io::RunRecord& record, const State& state, std::string line) {
  record.status = "stopped";
  record.error = std::string(stopReason()) + " at t = " + fmt("%.6g", state.time) + " s, after a whole step";
  return {false, true, std::move(line), {}};
}

Outcome simulateDynamic(const Model& model, State& state, long steps, io::RunRecord& record, const std::string& label) {
  Progress progress("run " + label, double(steps) * model.timeStep, "s simulated");
  StepReport report;
  long done = 0;
  while (done < steps && !stopRequested()) {
    report = advance(model, state);
    if (!report.ok()) break;
    ++done;
    progress.update(state.time);
  }
  progress.finish();
  const std::string line = stepSummary(model, state, done, steps, progress.seconds()) + tips(model, state);
  if (report.ok() && done < steps) return stopped(record, state, line);
  if (report.ok()) return {true, false, line, {}};
  record.status = "step_refused";
  // The step's number says where in a run without a device timeline.
  record.error = "step " + std::to_string(done + 1) + " refused at t = " + fmt("%.6g", report.failure->time) +
                 " s: " + report.failure->message();
  return {false, false, line, report.failure};
}

// runTimeline reports a refused command as "t = <its time> s: refused: why";
// this names the command too: "/commands/3 (push at 50 mm/s by 40 mm) at
// t = 2 s: refused: why". An entry it cannot match stays as it is.
std::string nameCommand(const std::string& entry, const std::vector<TimedCommand>& timeline, size_t& cursor) {
  for (size_t i = cursor; i < timeline.size(); ++i) {
    const std::string prefix = "t = " + std::to_string(timeline[i].time) + " s: ";
    if (entry.rfind(prefix, 0) != 0) continue;
    cursor = i + 1;
    return "/commands/" + std::to_string(i) + " (" + io::describeCommand(timeline[i].command) + ") at t = " +
           fmt("%g", timeline[i].time) + " s: " + entry.substr(prefix.size());
  }
  return entry;
}

// The scene's deployment driven by the timeline (possibly empty) for `steps`
// steps. Refused commands are printed and become warnings, not failures; a
// refused step fails the run.
Outcome simulateDeployment(const Model& model, State& state, const std::vector<TimedCommand>& timeline, const std::string& timelineFile, long steps,
                           io::RunRecord& record, const std::string& label) {
  const double duration = double(steps) * model.timeStep;
  // runTimeline starts a command at the first step that begins at or after its time.
  const double lastStart = double(steps - 1) * model.timeStep;
  for (size_t i = 0; i < timeline.size(); ++i)
    if (timeline[i].time > lastStart + 1e-9 * model.timeStep) {
      const std::string w = timelineFile + ": /commands/" + std::to_string(i) + "/t_s: " +
                            fmt("%g", timeline[i].time) + " s is not before the end of the run (" +
                            fmt("%g", duration) + " s): not run";
      std::fprintf(stderr, "coilsim: warning: %s\n", w.c_str());
      record.warnings.push_back(w);
    }
  Progress progress("run " + label, duration, "s simulated");
  TimelineRun run = runTimeline(model, state, timeline, duration, [&] {
    progress.update(state.time, fmt("coil %.4g mm out", units::mToMm(state.device.deployed)));
    return !stopRequested();
  });
  progress.finish();
  const double seconds = progress.seconds();
  // The log holds refused commands and limits reached on the way.
  const std::string source = timelineFile.empty() ? std::string("deployment") : timelineFile;
  size_t cursor = 0;  // refusals come in timeline order
  for (std::string entry : run.log) {
    const bool refused = entry.find("refused") != std::string::npos;
    if (refused) entry = nameCommand(entry, timeline, cursor);
    std::fprintf(stderr, "coilsim: %s: %s\n", source.c_str(), entry.c_str());
    if (refused) record.warnings.push_back(source + ": " + entry);
  }
  const Deployment& dep = *model.device;
  const DeviceState& ds = state.device;
  record.deployment = ds;
  record.catheterTip = catheterTip(model, state);
  const std::string tipLine = dep.flexible() ? fmt(", catheter tip at %.3g deg", units::radToDeg(record.catheterTip->angle)) +
                                                   fmt(", kickback %.4g mm", units::mToMm(record.catheterTip->kickback))
                                             : std::string();
  std::string line = stepSummary(model, state, run.steps, steps, seconds) + "; coil " +
                     fmt("%.6g", units::mToMm(ds.deployed)) + " of " + fmt("%.6g", units::mToMm(dep.coilLength)) +
                     " mm out, twist " + fmt("%.6g", units::radToDeg(ds.twist)) + " deg" +
                     (ds.detached ? ", detached" : "") +
                     (ds.tipOffset != 0 ? ", catheter retracted " + fmt("%.6g", units::mToMm(ds.tipOffset)) + " mm"
                                        : std::string()) +
                     tipLine + "; state " + io::stateHash(state);
  if (run.stopped) return stopped(record, state, line);
  if (run.ok()) return {true, false, line, {}};
  record.status = "step_refused";
  record.error = describe(*run.failure);
  return {false, false, line, run.failure};
}

Outcome simulateStatic(const Model& model, State& state, const io::SceneSpec& spec, io::RunRecord& record) {
  const auto start = Clock::now();
  const StaticReport rep = solveStatic(model, state, io::staticOptions(spec));
  record.statics = rep;
  const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
  const Energy e = computeEnergy(model, state);
  const std::string line = std::string("static, ") + (rep.converged() ? "converged" : "NOT converged") + " after " +
                           std::to_string(rep.increments) + " load increments and " + std::to_string(rep.iterations) +
                           " Newton iterations in " + fmt("%.3g", seconds) + " s; elastic energy " +
                           fmt("%.4g", e.elastic) + " J" + tips(model, state);
  if (rep.converged()) return {true, false, line, {}};
  record.status = "not_converged";
  record.error = describe(*rep.failure);
  return {false, false, line, rep.failure};
}

// The clinical read-outs of a deployment into a phantom's sac (the lines the
// window's panel shows, computed by the same planning::LiveReadouts): printed
// and kept for result.json. Nothing when no obstacle is a phantom with a sac.
void readSac(const io::SceneSpec& spec, const Model& model, const State& state, io::RunRecord& record) {
  if (!model.device) return;
  std::string note;
  const std::optional<planning::Sac> sac = planning::sceneSac(spec, note);
  if (!sac) return;
  planning::LiveReadouts live(*sac, *model.device, planning::Goal{}.maxWallForce);
  live.interval = 0;
  std::printf("read-outs (%s):\n", note.c_str());
  for (const planning::LiveLine& l : live.lines(model, state))
    std::printf("  %s%s: %s\n", l.warning ? "! " : "", l.label.c_str(), l.value.c_str());
  const planning::SacMetrics& m = live.metrics();
  io::ClinicalReadouts r;
  r.packingDensity = m.packingDensity;
  r.coilLengthInSac = m.coilLengthInSac;
  r.coilVolume = m.coilVolume;
  r.sacVolume = m.sacVolume;
  r.neckCoverage = m.neckCoverage;
  r.protruding = m.protruding;
  r.protrudingLength = m.protrudingLength;
  r.wallLoadAvailable = live.wallLoadAvailable();
  r.wallLoad = live.wallLoadNow();
  r.largestWallLoad = live.wallLoadMax();
  r.wallLoadWindow = kWallLoadWindow;
  record.readouts = r;
}

// Writes --out; false (after saying why) if it cannot.
bool writeOut(const RunOptions& o, const Model& model, const State& state, const io::RunRecord& record) {
  if (o.out.empty()) return true;
  try {
    io::writeResult(o.out, model, state, record);
    return true;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "coilsim: cannot write the result: %s\n", e.what());
    return false;
  }
}


int run(const RunOptions& o) {
  const io::SceneSpec spec = io::loadScene(o.scene);  // throws InputError
  if (spec.solve == io::SolveMode::Static && (o.durationS || o.steps))
    return usageError(o.scene + ": --duration and --steps apply to dynamic scenes; this scene has \"solve\": \"static\"");
  Model model;
  try {
    model = compileModel(io::compileScene(spec));
  } catch (const PhysicsError& e) {
    std::fprintf(stderr, "coilsim: %s: %s\n", o.scene.c_str(), describe(e.failure()).c_str());
    return exitCodeOf(e.failure());
  } catch (const io::InputError&) {
    throw;
  } catch (const std::exception& e) {
    return usageError(o.scene + ": " + e.what());
  }
  // A timeline drives a deployment: without one there is nothing to push.
  std::vector<TimedCommand> timeline;
  if (!o.input.empty()) {
    if (!model.device)
      return usageError(o.input + ": a timeline drives a coil deployment, but " + o.scene +
                        " has no \"deployment\" block (docs/scene-format.md)");
    timeline = io::loadTimeline(o.input);  // throws InputError
  }
  State state = makeState(model);
  io::RunRecord record;
  record.scene = o.scene;
  record.sceneName = spec.name;
  record.solve = spec.solve;
  record.warnings = spec.warnings;
  for (const std::string& w : spec.warnings) std::fprintf(stderr, "coilsim: warning: %s\n", w.c_str());

  const bool window = !o.headless && haveDisplay();
  if (window) {
    if (!haveUi())
      return usageError("this coilsim was built without the ui layer, so it cannot open a window; run with --headless "
                        "(or build with the graphics packages, see scripts/bootstrap)");
    if (spec.solve == io::SolveMode::Static) {
      Outcome r = simulateStatic(model, state, spec, record);
      std::printf("%s: %s\n", o.scene.c_str(), r.summary.c_str());
      if (!r.ok) std::fprintf(stderr, "coilsim: %s: %s\n", o.scene.c_str(), record.error.c_str());
    }
    const int code = runSceneWindow(model, state, spec, o, timeline);
    if (model.device) {
      record.deployment = state.device;
      record.catheterTip = catheterTip(model, state);
    }
    // The run as the window closed, read out as the headless run reads its end.
    readSac(spec, model, state, record);
    std::fflush(stdout);
    return writeOut(o, model, state, record) ? code : kExitUsage;
  }

  if (!o.headless && !haveDisplay())
    std::fprintf(stderr, "coilsim: no display (DISPLAY and WAYLAND_DISPLAY unset): running off-screen\n");
  Outcome r;
  if (spec.solve == io::SolveMode::Static) {
    r = simulateStatic(model, state, spec, record);
  } else {
    const double seconds = o.durationS ? *o.durationS : spec.durationS;
    const long steps = o.steps ? *o.steps : io::stepCount(seconds, model.timeStep);
    if (!o.steps && seconds / model.timeStep > double(kMaxRunSteps))
      return usageError(o.scene + ": " + (o.durationS ? "--duration " : "duration_s ") + fmt("%g", seconds) + " s in steps of " + fmt("%g", model.timeStep) +
                        " s is more than " + std::to_string(kMaxRunSteps) + " steps: refused before it starts");
    if (model.device)
      r = simulateDeployment(model, state, timeline, o.input, steps, record, o.scene);
    else
      r = simulateDynamic(model, state, steps, record, o.scene);
  }
  std::printf("%s: %s\n", o.scene.c_str(), r.summary.c_str());
  readSac(spec, model, state, record);
  std::fflush(stdout);
  if (!r.ok) std::fprintf(stderr, "coilsim: %s: %s\n", o.scene.c_str(), record.error.c_str());
  if (!writeOut(o, model, state, record)) return kExitUsage;
  if (r.stopped || stopRequested()) return stopExitCode();  // a static solve is not interrupted: it ends first
  if (!o.screenshot.empty()) {
    std::string error;
    if (!sceneScreenshot(model, state, spec, o, error)) {
      std::fprintf(stderr, "coilsim: screenshot %s failed: %s\n", o.screenshot.c_str(), error.c_str());
      return kExitFailure;
    }
  }
  if (r.failure) return exitCodeOf(*r.failure);
  return r.ok ? kExitOk : kExitFailure;
}

}  // namespace

bool haveDisplay() {
  for (const char* name : {"DISPLAY", "WAYLAND_DISPLAY"})
    if (const char* v = std::getenv(name); v && *v) return true;
  return false;
}

int runScene(const RunOptions& o) {
  // Asked for pictures from a binary that cannot make any: say so before simulating.
  if (!haveUi() && !o.screenshot.empty())
    return usageError("this coilsim was built without the ui layer: --screenshot is not available");
  if (!haveUi() && (o.view || o.width))
    return usageError("this coilsim was built without the ui layer: --view and --size have nothing to draw");
  try {
    return run(o);
  } catch (const io::InputError& e) {
    return usageError(e.what());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "coilsim: %s: internal error: %s\n", o.scene.c_str(), e.what());
    return kExitFailure;
  }
}

}  // namespace coilsim::app
