// Practice sessions: recorded inputs, score sheets, exact replay.
#include "planning/practice.h"

#include <cmath>
#include <cstdio>

#include "io/json_reader.h"
#include "io/scene.h"
#include "io/timeline.h"
#include "io/units.h"
#include "physics/integrator.h"
#include "planning/contact_forces.h"
#include "planning/run_contacts.h"

using nlohmann::ordered_json;

namespace coilsim::planning {

PracticeSession::PracticeSession(const PracticeCase& pc, const std::string& coilName, const WallForceCheck& contacts) {
  const io::CoilSpec* coil = nullptr;
  std::string names;
  for (const io::CoilSpec& c : pc.coils) {
    if (c.name == coilName) coil = &c;
    names += (names.empty() ? "" : ", ") + c.name;
  }
  if (!coil) throw io::InputError(pc.file + ": /coils: the case has no coil \"" + coilName + "\"; it has: " + names);
  io::SceneSpec spec = pc.scene;
  io::applyCoil(*coil, pc.spacingMm, *spec.deployment);
  spec.deployment->initialDeployedMm = std::min(spec.deployment->initialDeployedMm, 0.5 * coil->lengthMm);
  try {
    ModelDef def = io::compileScene(spec);
    addRunContacts(def, pc.sac);
    model_ = compileModel(def);
  } catch (const io::InputError&) {
    throw;
  } catch (const std::exception& e) {
    throw io::InputError(pc.file + ": /scene: " + e.what());
  }
  state_ = makeState(model_);
  setDrawnCatheterActive(*model_.device, state_, false);
  scorer_.emplace(pc, coilName, *model_.device, model_.timeStep, contacts);
}

std::string PracticeSession::command(const DeviceCommand& c) {
  // The numbers a replay of the recording will read, so it replays exactly.
  const DeviceCommand read = asRecorded(c);
  const std::optional<Failure> refused = coilsim::command(model_, state_, read);
  if (!refused) scorer_->commandAccepted(time(), commandJson({time(), c}), read);
  else note(describe(*refused));
  return refused ? describe(*refused) : std::string();
}

std::string PracticeSession::replayCommand(const DeviceCommand& c) {
  const std::optional<Failure> refused = coilsim::command(model_, state_, c);
  if (!refused) scorer_->commandAccepted(time(), commandJson({time(), c}), c);
  else note(describe(*refused));
  return refused ? describe(*refused) : std::string();
}

void PracticeSession::setView(const std::string& view) { scorer_->viewChanged(time(), view); }

bool PracticeSession::step() {
  if (!scorer_->scoring()) return false;
  scorer_->beforeStep(state_);
  const StepReport rep = coilsim::advance(model_, state_);
  for (const std::string& n : state_.device.notes) note(n);
  state_.device.notes.clear();
  ++steps_;
  scorer_->afterStep(model_, state_, rep);
  return rep.ok();
}

void PracticeSession::note(const std::string& message) { scorer_->deviceMessage(message); }

ScoreSheet PracticeSession::finish() { return scorer_->finish(model_, state_); }

ordered_json PracticeSession::recording() const { return scorer_->recording(time()); }

SessionRecording parseSession(const nlohmann::json& document, const std::string& file) {
  const io::JsonNode root(document, file);
  if (!root.isObject()) root.expected("a session object {\"format\": \"coilsim-session/1\", ...}");
  root.allowKeys({"format", "case", "coil", "end_s", "timeline", "views"});
  root.child("format").oneOf({kSessionFormat});
  SessionRecording s;
  s.caseLabel = root.child("case").string();
  s.coil = root.child("coil").string();
  s.end = root.child("end_s").number(io::Bounds::closed(0, 3600, "s"));
  const io::JsonNode tl = root.child("timeline");
  if (!tl.isObject()) tl.expected("a coilsim-timeline/1 object");
  s.timeline = io::parseTimeline(tl.value(), file + " (/timeline)");
  double last = 0;
  for (const io::JsonNode& v : root.child("views").items(0, SIZE_MAX, "an array of {\"t_s\", \"view\"}")) {
    v.allowKeys({"t_s", "view"});
    const double t = v.child("t_s").number(io::Bounds::nonNegative());
    if (t < last) v.child("t_s").fail("views are listed in time order");
    last = t;
    s.views.emplace_back(t, v.child("view").oneOf({"3d", "xray", "biplane"}));
  }
  return s;
}

SessionRecording loadSession(const std::string& path) { return parseSession(io::readJsonFile(path), path); }

ScoreSheet playSession(const PracticeCase& pc, const std::string& coil, const std::vector<TimedCommand>& timeline,
                       const std::vector<std::pair<double, std::string>>& views, double end,
                       ordered_json* recordingOut, const WallForceCheck& contacts,
                       const std::function<void(const PracticeSession&)>& atEnd,
                       const std::function<bool(const PracticeSession&)>& keepGoing) {
  PracticeSession session(pc, coil, contacts);
  const double dt = session.model().timeStep;
  const long steps = std::lround(end / dt);
  size_t nextCommand = 0, nextView = 0;
  for (long s = 0; s < steps; ++s) {
    const double t = double(s) * dt;
    // The same rule as runTimeline: an input acts at the first step starting at or after its time.
    while (nextView < views.size() && views[nextView].first <= t + 1e-9 * dt) session.setView(views[nextView++].second);
    // Recording: the live path (through the file's units), so the recording
    // replays exactly; replaying: the commands exactly as read.
    while (nextCommand < timeline.size() && timeline[nextCommand].time <= t + 1e-9 * dt) {
      const DeviceCommand& c = timeline[nextCommand++].command;
      if (recordingOut) session.command(c);
      else session.replayCommand(c);
    }
    if (!session.step()) break;
    if (keepGoing && !keepGoing(session)) break;
  }
  if (recordingOut) *recordingOut = session.recording();
  if (atEnd) atEnd(session);
  return session.finish();
}

}  // namespace coilsim::planning
