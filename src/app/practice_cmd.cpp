// `coilsim practice`: scripted or replayed practice sessions and their score sheets.
#include "app/practice_cmd.h"

#include <charconv>
#include <cmath>
#include <cstdio>

#include <algorithm>
#include <memory>
#include <optional>

#include "app/format.h"
#include "app/run_scene.h"
#include "io/json_reader.h"
#include "io/json_writer.h"
#include "io/timeline.h"
#include "planning/case_file.h"
#include "planning/live_readouts.h"
#include "planning/practice.h"
#include "planning/run_contacts.h"
#ifdef COILSIM_HAVE_UI
#include "app/window_setup.h"
#include "ui/viewer.h"
#endif

namespace coilsim::app {
namespace {

int usage(const std::string& message) {
  std::fprintf(stderr,
               "coilsim practice: %s\n"
               "usage: coilsim practice CASE --coil NAME --input TIMELINE [--view 3d|xray|biplane] [--views T:VIEW,...]\n"
               "                        [--duration S] [--record SESSION] [--screenshot PNG] --out SCORE\n"
               "       coilsim practice CASE --replay SESSION [--screenshot PNG] --out SCORE\n"
               "       coilsim practice CASE --window [--coil NAME] [--view 3d|xray|biplane] [--record SESSION]\n"
               "                        [--out SCORE] [--input TIMELINE] [--views T:VIEW,...] [--duration S]\n"
               "                        [--screenshot PNG]\n"
               "(docs/planning.md)\n",
               message.c_str());
  return kExitUsage;
}

// "0.5:xray,2:3d" -> view switches at their times, in time order.
bool parseViews(const std::string& text, std::vector<std::pair<double, std::string>>& out, std::string& why) {
  size_t at = 0;
  while (at <= text.size()) {
    const size_t comma = std::min(text.find(',', at), text.size());
    const std::string item = text.substr(at, comma - at);
    const size_t colon = item.find(':');
    double t = 0;
    const auto [end, ec] = colon == std::string::npos ? std::from_chars_result{nullptr, std::errc::invalid_argument}
                                                       : std::from_chars(item.data(), item.data() + colon, t);
    const std::string view = colon == std::string::npos ? "" : item.substr(colon + 1);
    if (ec != std::errc() || end != item.data() + colon || !(t >= 0) || !std::isfinite(t) ||
        (view != "3d" && view != "xray" && view != "biplane")) {
      why = "--views needs T:VIEW,... (seconds >= 0, view 3d, xray or biplane), got \"" + item + "\"";
      return false;
    }
    if (!out.empty() && t < out.back().first) {
      why = "--views must be in time order, got " + item + " after " + fmt("%g", out.back().first);
      return false;
    }
    out.emplace_back(t, view);
    at = comma + 1;
  }
  return true;
}

#ifdef COILSIM_HAVE_UI
// The window (or an off-screen picture) of a practice session's model and
// state, with the live read-outs: packing, protrusion and wall-force warnings.
ui::ViewerOptions practiceViewer(const planning::PracticeCase& pc, const planning::PracticeSession& session,
                                 const std::string& view) {
  ui::ViewerOptions v;
  v.scenePath = pc.name + " - " + session.runningScore().coil;
  v.view = view;
  const Deployment dep = session.deployment();
  v.addDrawData = [dep](const Model& m, const State& s, DrawData& d) { planning::appendInactiveCatheter(m, s, dep, d); };
  v.readouts = liveReadouts(pc.sac, dep, pc.goal.maxWallForce, "Practice: " + pc.name);
  v.deployment = ui::DeploymentSetup{dep, session.deploymentState(), {}};
  return v;
}

// Where a window session's recording and score sheet go when it closes.
struct WindowOutputs {
  std::string record, out;
  int exitCode = kExitOk;
};

// Records every input of a window session and keeps its score from the
// window's own steps (planning::SessionScorer, the hooks PracticeSession
// calls); writes the session and the score sheet when the window closes.
class WindowScorer : public ui::RunObserver {
 public:
  WindowScorer(const planning::PracticeCase& pc, const std::string& coil, const Deployment& dep, double dt,
               std::shared_ptr<WindowOutputs> outputs)
      : pc_(pc), coil_(coil), dep_(dep), dt_(dt), outputs_(std::move(outputs)) {
    restarted();
  }
  DeviceCommand adjust(const DeviceCommand& given) override { return planning::asRecorded(given); }
  void accepted(double t, const DeviceCommand& given, const DeviceCommand& applied) override {
    scorer_->commandAccepted(t, planning::commandJson({t, given}), applied);
  }
  void viewChanged(double t, const std::string& view) override { scorer_->viewChanged(t, view); }
  void beforeDevice(const DeploymentState& ds) override { scorer_->beforeDevice(ds); }
  void afterDevice(const State& s, const DeploymentState& ds) override { scorer_->afterDevice(s, ds); }
  void afterStep(const Model& m, const State& s, const DeploymentState& ds, bool ok, const std::string& why) override {
    scorer_->afterStep(m, s, ds, ok, why);
  }
  // Reset: a new session from the start.
  void restarted() override { scorer_.emplace(pc_, coil_, dep_, dt_); }
  // The session so far, for the panel.
  std::vector<ui::Readout> lines() const {
    const planning::ScoreSheet& s = scorer_->running();
    return {{"session time", fmt("%.1f s", scorer_->time()), false},
            {"fluoroscopy time", fmt("%.1f s", s.fluoroscopyTime), false},
            // What the score sheet will say: loads lasting 5 steps (the lines above show every step's).
            {"largest lasting wall load", s.wallForcesAvailable ? fmt("%.2f mN", 1e3 * s.maxWallForce) : "n/a",
             s.wallForcesAvailable && s.maxWallForce > pc_.goal.maxWallForce},
            {"repositionings", std::to_string(s.repositionings), false},
            {"recording", outputs_->record.empty() ? std::string("off (--record SESSION)") : outputs_->record, false}};
  }
  void closed(const Model& m, const State& s, const DeploymentState& ds) override {
    const planning::ScoreSheet score = scorer_->finish(m, s, ds);
    if (!outputs_->record.empty()) io::writeFileAtomic(outputs_->record, io::formatJson(scorer_->recording(scorer_->time())));
    const std::string text = io::formatJson(planning::scoreJson(score));
    if (!outputs_->out.empty()) io::writeFileAtomic(outputs_->out, text);
    std::fputs(text.c_str(), stdout);
    if (!score.ok) {
      std::fprintf(stderr, "coilsim practice: %s\n", score.error.c_str());
      outputs_->exitCode = kExitFailure;
    }
  }

 private:
  const planning::PracticeCase& pc_;
  std::string coil_;
  Deployment dep_;
  double dt_;
  std::shared_ptr<WindowOutputs> outputs_;
  std::optional<planning::SessionScorer> scorer_;
};

// The window's setup for one coil of the case: model, deployment, read-outs, scorer.
ui::SceneSetup practiceSetup(const planning::PracticeCase& pc, const std::string& coil, std::shared_ptr<WindowOutputs> outputs) {
  const planning::PracticeSession session(pc, coil);
  ui::SceneSetup s;
  s.model = session.model();
  s.state = session.state();
  ui::ViewerOptions v = practiceViewer(pc, session, "3d");
  s.deployment = v.deployment;
  s.draw = v.addDrawData;
  const auto scorer = std::make_shared<WindowScorer>(pc, coil, session.deployment(), session.model().timeStep, outputs);
  s.observer = scorer;
  // The live read-outs, then the session's own figures.
  s.readouts.title = v.readouts.title;
  s.readouts.compute = [live = v.readouts.compute, scorer](const Model& m, const State& st) {
    std::vector<ui::Readout> out = live(m, st);
    for (ui::Readout& r : scorer->lines()) out.push_back(std::move(r));
    return out;
  };
  s.loaded = "loaded " + coil + "; the session starts again";
  return s;
}

// By hand in the window: the case's coils in the panel, the case's catheter,
// every input recorded and scored (scripted inputs, --input and --views, go
// through the same path as the keys).
int practiseInWindow(const planning::PracticeCase& pc, std::string coil, const std::string& view,
                     const std::vector<TimedCommand>& script, const std::vector<std::pair<double, std::string>>& views,
                     double duration, const std::string& screenshot, std::shared_ptr<WindowOutputs> outputs) {
  if (coil.empty()) coil = pc.coils.front().name;
  const ui::SceneSetup first = practiceSetup(pc, coil, outputs);
  ui::ViewerOptions v;
  v.scenePath = pc.name;
  v.view = view;
  v.deployment = first.deployment;
  v.addDrawData = first.draw;
  v.readouts = first.readouts;
  v.observer = first.observer;
  // X-ray views only, as in the procedure, when the session starts in one.
  v.xrayOnly = planning::fluoroscopic(view);
  v.effectsLocked = "The case fixes the physics (a recording must replay it).";
  ui::SetupChoices choices;
  for (size_t i = 0; i < pc.coils.size(); ++i) {
    choices.coils.push_back(coilLabel(pc.coils[i]));
    if (pc.coils[i].name == coil) choices.coil = int(i);
  }
  choices.catheters = {"the case's catheter"};
  choices.catheter = 0;
  choices.catheterFixed = true;
  choices.coilNote = "the case's coil set; choosing one starts the session again";
  choices.catheterNote = "the case fixes the catheter position and tip";
  choices.build = [&pc, outputs](int c, int) { return practiceSetup(pc, pc.coils.at(size_t(c)).name, outputs); };
  v.setup = choices;
  for (const TimedCommand& c : script) v.script.push_back({c.time, c.command, ""});
  for (const auto& [t, name] : views) v.script.push_back({t, std::nullopt, name});
  std::stable_sort(v.script.begin(), v.script.end(), [](const auto& a, const auto& b) { return a.time < b.time; });
  if (duration > 0) v.runSeconds = duration;
  v.windowScreenshotPath = screenshot;
  Model model = first.model;
  State state = first.state;
  const int code = ui::runWindow(model, state, v);
  return code != kExitOk ? code : outputs->exitCode;
}
#endif

}  // namespace

int runPractice(const std::vector<std::string>& args) {
  std::string casePath, coil, input, view = "3d", record, replay, out, screenshot;
  std::vector<std::pair<double, std::string>> views;
  bool window = false;
  double duration = 0;
  for (size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    auto value = [&](std::string& v) {
      if (i + 1 >= args.size()) return false;
      v = args[++i];
      return !v.empty();
    };
    std::string v;
    if (a == "--coil") {
      if (!value(coil)) return usage("--coil needs a coil name of the case's set");
    } else if (a == "--input") {
      if (!value(input)) return usage("--input needs a timeline file (coilsim-timeline/1)");
    } else if (a == "--window") {
      window = true;
    } else if (a == "--screenshot") {
      if (!value(screenshot)) return usage("--screenshot needs a PNG file name");
    } else if (a == "--view") {
      if (!value(view) || (view != "3d" && view != "xray" && view != "biplane"))
        return usage("--view needs 3d, xray or biplane, got \"" + view + "\"");
    } else if (a == "--views") {
      std::string why;
      if (!value(v)) return usage("--views needs T:VIEW,... e.g. 0.5:xray,2:3d");
      if (!parseViews(v, views, why)) return usage(why);
    } else if (a == "--duration") {
      const auto [end, ec] = value(v) ? std::from_chars(v.data(), v.data() + v.size(), duration)
                                      : std::from_chars_result{nullptr, std::errc::invalid_argument};
      if (ec != std::errc() || end != v.data() + v.size() || !(duration > 0) || !std::isfinite(duration))
        return usage("--duration needs seconds > 0, got \"" + v + "\"");
    } else if (a == "--record") {
      if (!value(record)) return usage("--record needs a session file name");
    } else if (a == "--replay") {
      if (!value(replay)) return usage("--replay needs a session file (coilsim-session/1)");
    } else if (a == "--out") {
      if (!value(out)) return usage("--out needs a score file name");
    } else if (!a.empty() && a[0] == '-') {
      return usage("unknown option \"" + a + "\"");
    } else if (casePath.empty()) {
      casePath = a;
    } else {
      return usage("practice takes one case file, got \"" + casePath + "\" and \"" + a + "\"");
    }
  }
  if (casePath.empty()) return usage("practice needs a case file, e.g. scenes/cases/sphere-7mm.json");
#ifndef COILSIM_HAVE_UI
  if (window || !screenshot.empty()) return usage("this build has no window or screenshots (no ui layer)");
#endif
  if (window) {
    if (!replay.empty()) return usage("--window practises by hand; --replay plays a session headless: drop one");
  } else if (out.empty()) {
    return usage("practice needs --out SCORE (or --window)");
  }
  if (!window && replay.empty() == input.empty()) return usage("give either --input TIMELINE (play) or --replay SESSION");
  if (!replay.empty() && (!coil.empty() || !record.empty() || duration > 0 || view != "3d" || !views.empty()))
    return usage("--replay takes the coil, views and duration from the session; drop --coil, --record, --view, --views, "
                 "--duration");
  try {
    const planning::PracticeCase pc = planning::loadCase(casePath);
#ifdef COILSIM_HAVE_UI
    if (window) {
      // By hand (or scripted, --input and --views as if typed), recorded and scored on close.
      const std::vector<TimedCommand> script = input.empty() ? std::vector<TimedCommand>() : io::loadTimeline(input);
      auto outputs = std::make_shared<WindowOutputs>();
      outputs->record = record;
      outputs->out = out;
      return practiseInWindow(pc, coil, view, script, views, duration, screenshot, outputs);
    }
    // The last frame of a scripted session, in its last view, with the read-outs.
    std::string shotError;
    auto picture = [&](const planning::PracticeSession& s) {
      if (screenshot.empty()) return;
      ui::ViewerOptions v = practiceViewer(pc, s, s.view());
      v.deployment = ui::DeploymentSetup{s.deployment(), s.deploymentState(), {}};
      v.screenshotPath = screenshot;
      if (!ui::renderOffscreen(s.model(), s.state(), v, shotError)) std::fprintf(stderr, "coilsim practice: %s\n", shotError.c_str());
    };
#else
    const std::function<void(const planning::PracticeSession&)> picture;
#endif
    planning::ScoreSheet score;
    if (!replay.empty()) {
      const planning::SessionRecording s = planning::loadSession(replay);
      score = planning::playSession(pc, s.coil, s.timeline, s.views, s.end, nullptr, {}, picture);
    } else {
      if (coil.empty()) coil = pc.coils.front().name;
      const std::vector<TimedCommand> timeline = io::loadTimeline(input);
      // Without --duration: one second after the last command.
      if (duration == 0) duration = (timeline.empty() ? 0.0 : timeline.back().time) + 1.0;
      if (view != "3d") views.insert(views.begin(), {0.0, view});
      nlohmann::ordered_json recording;
      score = planning::playSession(pc, coil, timeline, views, duration, &recording, {}, picture);
      if (!record.empty()) io::writeFileAtomic(record, io::formatJson(recording));
    }
    const std::string text = io::formatJson(planning::scoreJson(score));
    io::writeFileAtomic(out, text);
    std::fputs(text.c_str(), stdout);
    if (!score.ok) std::fprintf(stderr, "coilsim practice: %s\n", score.error.c_str());
    return score.ok ? kExitOk : kExitFailure;
  } catch (const io::InputError& e) {
    std::fprintf(stderr, "coilsim practice: %s\n", e.what());
    return kExitUsage;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "coilsim practice: %s\n", e.what());
    return kExitFailure;
  }
}

}  // namespace coilsim::app
