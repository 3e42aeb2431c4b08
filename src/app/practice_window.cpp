// The practice window: recorded and scored from the window's own steps.
#include "app/practice_window.h"

#include <algorithm>
#include <cstdio>
#include <memory>
#include <optional>

#include "app/format.h"
#include "app/exit_codes.h"
#include "app/sac_drawing.h"
#include "app/window_setup.h"
#include "io/json_writer.h"
#include "planning/run_contacts.h"
#include "planning/session_scorer.h"
#include "ui/viewer.h"

namespace coilsim::app {
namespace {

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
  void noted(const std::string& message) override { scorer_->deviceMessage(message); }
  void beforeStep(const State& s) override { scorer_->beforeStep(s); }
  void afterStep(const Model& m, const State& s, const StepReport& report) override {
    scorer_->afterStep(m, s, report);
  }
  // Reset: a new session from the start.
  void restarted() override { scorer_.emplace(pc_, coil_, dep_, dt_); }
  // The session so far, for the panel.
  std::vector<ui::Readout> lines() const {
    const planning::ScoreSheet& s = scorer_->running();
    return {{"session time", fmt("%.1f s", scorer_->time()), false},
            {"fluoroscopy time", fmt("%.1f s", s.fluoroscopyTime), false},
            {"repositionings", std::to_string(s.repositionings), false},
            {"recording", outputs_->record.empty() ? std::string("off (--record SESSION)") : outputs_->record, false}};
  }
  void closed(const Model& m, const State& s) override {
    const planning::ScoreSheet score = scorer_->finish(m, s);
    const std::string text = io::formatJson(planning::scoreJson(score));
    // Each file on its own, and the sheet printed whatever happens to them:
    // a disk that filled up during the session must not take the score with it.
    const std::pair<std::string, std::string> files[] = {
        {outputs_->record, outputs_->record.empty() ? "" : io::formatJson(scorer_->recording(scorer_->time()))},
        {outputs_->out, text}};
    for (const auto& [path, body] : files) {
      if (path.empty()) continue;
      try {
        io::writeFileAtomic(path, body);
      } catch (const std::exception& e) {
        std::fprintf(stderr, "coilsim practice: %s\n", e.what());
        outputs_->exitCode = kExitFailure;
      }
    }
    std::fputs(text.c_str(), stdout);
    for (const std::string& m : score.deviceMessages) std::fprintf(stderr, "coilsim practice: device: %s\n", m.c_str());
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

// The window (or an off-screen picture) of a practice session's model and
// state, with the live read-outs: packing, protrusion and wall-force warnings.
ui::ViewerOptions practiceViewer(const planning::PracticeCase& pc, const planning::PracticeSession& session,
                                 const std::string& view) {
  ui::ViewerOptions v;
  v.scenePath = pc.name + " - " + session.runningScore().coil;
  v.view = view;
  const Deployment dep = session.deployment();
  const DrawMesh neck = neckDisc(pc.sac);
  v.addDrawData = [dep, neck](const Model& m, const State& s, DrawData& d) {
    planning::appendInactiveCatheter(m, s, dep, d);
    if (!neck.triangles.empty()) d.meshes.push_back(neck);
  };
  v.legend = sacLegend(pc.sac);
  v.readouts = liveReadouts(pc.sac, dep, pc.goal.maxWallForce, "Practice: " + pc.name);
  return v;
}

// The window's setup for one coil of the case: model, deployment, read-outs, scorer.
ui::SceneSetup practiceSetup(const planning::PracticeCase& pc, const std::string& coil, std::shared_ptr<WindowOutputs> outputs) {
  const planning::PracticeSession session(pc, coil);
  ui::SceneSetup s;
  s.model = session.model();
  s.state = session.state();
  ui::ViewerOptions v = practiceViewer(pc, session, "3d");
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

}  // namespace

bool practicePicture(const planning::PracticeCase& pc, const planning::PracticeSession& session,
                     const std::string& path, PictureSize size, std::string& error) {
  ui::ViewerOptions v = practiceViewer(pc, session, session.view());
  v.screenshotPath = path;
  v.width = size.width, v.height = size.height;
  return ui::renderOffscreen(session.model(), session.state(), v, error);
}

// By hand in the window: the case's coils in the panel, the case's catheter,
// every input recorded and scored (scripted inputs, --input and --views, go
// through the same path as the keys).
int practiseInWindow(const planning::PracticeCase& pc, std::string coil, const std::string& view,
                     const std::vector<TimedCommand>& script, const std::vector<std::pair<double, std::string>>& views,
                     double duration, const std::string& screenshot, PictureSize size,
                     std::shared_ptr<WindowOutputs> outputs) {
  if (coil.empty()) coil = pc.coils.front().name;
  const ui::SceneSetup first = practiceSetup(pc, coil, outputs);
  ui::ViewerOptions v;
  v.scenePath = pc.name;
  v.view = view;
  v.width = size.width, v.height = size.height;
  v.addDrawData = first.draw;
  v.legend = sacLegend(pc.sac);
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

}  // namespace coilsim::app
