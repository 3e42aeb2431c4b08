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
// It also holds the session's coils (planning::PracticeCoilChain): the next
// coil of a scripted sequence goes in once the running one has detached,
// exactly where a headless session of the same inputs changes coils.
class WindowScorer : public ui::RunObserver {
 public:
  WindowScorer(const planning::PracticeCase& pc, const planning::SessionCoils& coils, ui::DrawDataHook draw,
               std::shared_ptr<WindowOutputs> outputs)
      : pc_(pc), coils_(coils), draw_(std::move(draw)), outputs_(std::move(outputs)) {
    restarted();
  }
  const planning::PracticeCoilChain& sequence() const { return *sequence_; }

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
  std::optional<ui::Continuation> continuation(const Model&, const State& s) override {
    if (queued_ >= coils_.next.size() || !s.device.detached) return std::nullopt;
    const std::string next = coils_.next[queued_++].coil;
    if (const std::string why = sequence_->whyNot(s, next); !why.empty()) {
      scorer_->deviceMessage("next coil " + next + " refused: " + why);
      return std::nullopt;
    }
    return follow(next, s);
  }
  // The next coil after the running one, as `state` left it (the panel's choice after a detach).
  ui::Continuation follow(const std::string& coil, const State& state) {
    State start = sequence_->next(state, coil);
    scorer_->coilChanged(scorer_->time(), coil, *sequence_->model().device, state);
    return {sequence_->model(), std::move(start), draw_};
  }
  // Reset: a new session from the start, with the first coil.
  void restarted() override {
    sequence_.emplace(pc_, coils_.first);
    queued_ = 0;
    scorer_.emplace(pc_, coils_.first, *sequence_->model().device, sequence_->model().timeStep);
  }
  // The session so far, for the panel.
  std::vector<ui::Readout> lines() const {
    const planning::ScoreSheet& s = scorer_->running();
    std::vector<ui::Readout> out{{"session time", fmt("%.1f s", scorer_->time()), false},
                                 {"fluoroscopy time", fmt("%.1f s", s.fluoroscopyTime), false},
                                 {"repositionings", std::to_string(s.repositionings), false}};
    if (sequence_->placed() > 0)
      out.push_back({"coils", std::to_string(sequence_->placed()) + " detached in the sac, " + sequence_->coil() + " going in",
                     false});
    out.push_back(
        {"recording", outputs_->record.empty() ? std::string("off (--record SESSION)") : outputs_->record, false});
    return out;
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
  planning::SessionCoils coils_;
  size_t queued_ = 0;  // next coils of coils_ gone in (or refused)
  ui::DrawDataHook draw_;
  std::shared_ptr<WindowOutputs> outputs_;
  std::optional<planning::PracticeCoilChain> sequence_;
  std::optional<planning::SessionScorer> scorer_;
};

// What every coil's picture adds to the core's: the rigid catheter (only
// drawn) and the neck plane.
ui::DrawDataHook practiceDrawing(const planning::PracticeCase& pc) {
  const DrawMesh neck = neckDisc(pc.sac);
  return [neck](const Model& m, const State& s, DrawData& d) {
    if (m.device) planning::appendInactiveCatheter(m, s, *m.device, d);
    if (!neck.triangles.empty()) d.meshes.push_back(neck);
  };
}

// The window (or an off-screen picture) of a practice session's model and
// state, with the live read-outs: packing, protrusion and wall-force warnings.
ui::ViewerOptions practiceViewer(const planning::PracticeCase& pc, const Model& model, const std::string& coil,
                                 const std::string& view) {
  ui::ViewerOptions v;
  v.scenePath = pc.name + " - " + coil;
  v.view = view;
  v.addDrawData = practiceDrawing(pc);
  v.legend = sacLegend(pc.sac);
  v.readouts = liveReadouts(pc.sac, *model.device, pc.goal.maxWallForce, "Practice: " + pc.name);
  return v;
}

// The window's setup for a session of the case's coils: model, deployment, read-outs, scorer.
ui::SceneSetup practiceSetup(const planning::PracticeCase& pc, const planning::SessionCoils& coils,
                             std::shared_ptr<WindowOutputs> outputs, std::shared_ptr<WindowScorer>* scorerOut = nullptr) {
  const ui::DrawDataHook draw = practiceDrawing(pc);
  const auto scorer = std::make_shared<WindowScorer>(pc, coils, draw, outputs);
  const planning::PracticeCoilChain& seq = scorer->sequence();
  ui::SceneSetup s;
  s.model = seq.model();
  s.state = seq.start();
  s.draw = draw;
  ui::ViewerOptions v = practiceViewer(pc, seq.model(), coils.first, "3d");
  s.observer = scorer;
  // The live read-outs, then the session's own figures.
  s.readouts.title = v.readouts.title;
  s.readouts.compute = [live = v.readouts.compute, scorer](const Model& m, const State& st) {
    std::vector<ui::Readout> out = live(m, st);
    for (ui::Readout& r : scorer->lines()) out.push_back(std::move(r));
    return out;
  };
  s.loaded = "loaded " + coils.first + "; the session starts again";
  if (scorerOut) *scorerOut = scorer;
  return s;
}

}  // namespace

bool practicePicture(const planning::PracticeCase& pc, const planning::PracticeSession& session,
                     const std::string& path, PictureSize size, std::string& error) {
  ui::ViewerOptions v = practiceViewer(pc, session.model(), session.runningScore().coil, session.view());
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
  const planning::SessionCoils coils = planning::parseCoilSequence(coil);
  // The scorer of the running session: the panel's next coil goes in through it.
  auto running = std::make_shared<std::shared_ptr<WindowScorer>>();
  const ui::SceneSetup first = practiceSetup(pc, coils, outputs, running.get());
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
    if (pc.coils[i].name == coils.first) choices.coil = int(i);
  }
  choices.catheters = {"the case's catheter"};
  choices.catheter = 0;
  choices.catheterFixed = true;
  choices.coilNote = "the case's coil set; choosing one starts the session again";
  choices.followNote = "the coil is detached: the one chosen goes in next through the same catheter, the detached "
                       "ones stay in the sac (Reset starts the session again)";
  choices.catheterNote = "the case fixes the catheter position and tip";
  choices.build = [&pc, outputs, running](int c, int) {
    return practiceSetup(pc, planning::SessionCoils(pc.coils.at(size_t(c)).name), outputs, running.get());
  };
  choices.follow = [&pc, running](int c, const Model&, const State& now) {
    ui::Continuation next = (*running)->follow(pc.coils.at(size_t(c)).name, now);
    ui::SceneSetup s;
    s.model = std::move(next.model);
    s.state = std::move(next.state);
    s.draw = std::move(next.draw);
    s.loaded = "loaded " + pc.coils.at(size_t(c)).name + " after " + std::to_string((*running)->sequence().placed()) +
               " detached coil(s)";
    return s;
  };
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
