// Practice sessions: recorded inputs, score sheets, exact replay.
#include "planning/practice.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "io/json_reader.h"
#include "io/scene.h"
#include "io/timeline.h"
#include "io/units.h"
#include "physics/deployment.h"
#include "physics/integrator.h"
#include "planning/contact_forces.h"
#include "planning/run_contacts.h"

using nlohmann::ordered_json;

namespace coilsim::planning {

namespace {

// Coils left in the sac stay awake (sleeping, physics/sleep.h, is off in
// practice): a plan of three coils with it gained nothing, the incoming
// coil waking the placed ones as fast as they fell asleep, and the window's
// bench did not show it paying either (docs/contact.md, "Sleeping coils").
// Switch it on here, with setSleeping(model, true), once it is shown to pay.

}  // namespace

PracticeCoilChain::PracticeCoilChain(const PracticeCase& pc, const std::string& first) : case_(&pc) { build(first, nullptr); }

void PracticeCoilChain::build(const std::string& coilName, const State* before) {
  const PracticeCase& pc = *case_;
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
  ModelDef def;
  Model model;
  try {
    def = io::compileScene(spec);
    // The deployment's rods first, then the placed coils': the device's rod
    // indices are those of a session of one coil.
    const Deployment d = addDeployment(*def.device, def);
    def.device.reset();
    firstPlaced_ = addPlacedRods(def, placed_);
    addRunContacts(def, pc.sac);
    model = compileModel(def);
    model.device = d;
  } catch (const io::InputError&) {
    throw;
  } catch (const std::exception& e) {
    throw io::InputError(pc.file + ": /scene: " + e.what());
  }
  State start = makeState(model);
  restorePlacedRods(start, firstPlaced_, placed_);
  setDrawnCatheterActive(*model.device, start, false);
  if (before) {
    // One session: its clock and records go on.
    start.time = before->time;
    start.stats = before->stats;
    start.blowups = before->blowups;
    start.substepped = before->substepped;
    start.warnings = before->warnings;
  }
  def_ = std::move(def);
  model_ = std::move(model);
  start_ = std::move(start);
  coils_.push_back(coilName);
}

std::string PracticeCoilChain::whyNot(const State& now, const std::string& next) const {
  if (!now.device.detached) return "the coil " + coil() + " has not been detached yet: detach it before the next coil";
  for (const io::CoilSpec& c : case_->coils)
    if (c.name == next) return "";
  return "the case has no coil \"" + next + "\"";
}

State PracticeCoilChain::next(const State& now, const std::string& next) {
  if (const std::string why = whyNot(now, next); !why.empty()) throw io::InputError(case_->file + ": " + why);
  const std::vector<PlacedCoil> kept = placed_;
  keepPlacedCoils(def_, now, firstPlaced_, model_.device->freeRod, coil(), placed_);
  try {
    build(next, &now);
  } catch (...) {
    placed_ = kept;
    throw;
  }
  return start_;
}

SessionCoils parseCoilSequence(const std::string& text) {
  SessionCoils coils(std::string{});
  size_t at = 0;
  for (bool first = true; at <= text.size(); first = false) {
    const size_t plus = std::min(text.find('+', at), text.size());
    std::string name = text.substr(at, plus - at);
    if (first) coils.first = std::move(name);
    else coils.next.push_back({std::move(name), std::nullopt});
    at = plus + 1;
  }
  return coils;
}

void checkCoils(const PracticeCase& pc, const SessionCoils& coils) {
  std::vector<std::string> names{coils.first};
  for (const NextCoil& c : coils.next) names.push_back(c.coil);
  std::string set;
  for (const io::CoilSpec& c : pc.coils) set += (set.empty() ? "" : ", ") + c.name;
  for (const std::string& n : names)
    if (std::none_of(pc.coils.begin(), pc.coils.end(), [&](const io::CoilSpec& c) { return c.name == n; }))
      throw io::InputError(pc.file + ": /coils: the case has no coil \"" + n + "\"; it has: " + set);
}

PracticeSession::PracticeSession(const PracticeCase& pc, const std::string& coilName, const WallForceCheck& contacts)
    : coils_(pc, coilName), state_(coils_.start()) {
  scorer_.emplace(pc, coilName, *model().device, model().timeStep, contacts);
}

std::string PracticeSession::nextCoil(const std::string& coilName) {
  if (const std::string why = coils_.whyNot(state_, coilName); !why.empty()) {
    note("next coil " + coilName + " refused: " + why);
    return why;
  }
  const State left = state_;
  state_ = coils_.next(left, coilName);
  scorer_->coilChanged(time(), coilName, *model().device, left);
  return "";
}

std::string PracticeSession::command(const DeviceCommand& c) {
  // The numbers a replay of the recording will read, so it replays exactly.
  const DeviceCommand read = asRecorded(c);
  const std::optional<Failure> refused = coilsim::command(model(), state_, read);
  if (!refused) scorer_->commandAccepted(time(), commandJson({time(), c}), read);
  else note(describe(*refused));
  return refused ? describe(*refused) : std::string();
}

std::string PracticeSession::replayCommand(const DeviceCommand& c) {
  const std::optional<Failure> refused = coilsim::command(model(), state_, c);
  if (!refused) scorer_->commandAccepted(time(), commandJson({time(), c}), c);
  else note(describe(*refused));
  return refused ? describe(*refused) : std::string();
}

void PracticeSession::setView(const std::string& view) { scorer_->viewChanged(time(), view); }

bool PracticeSession::step() {
  if (!scorer_->scoring()) return false;
  scorer_->beforeStep(state_);
  const StepReport rep = coilsim::advance(model(), state_);
  for (const std::string& n : state_.device.notes) note(n);
  state_.device.notes.clear();
  ++steps_;
  scorer_->afterStep(model(), state_, rep);
  return rep.ok();
}

void PracticeSession::note(const std::string& message) { scorer_->deviceMessage(message); }

ScoreSheet PracticeSession::finish() { return scorer_->finish(model(), state_); }

ordered_json PracticeSession::recording() const { return scorer_->recording(time()); }

SessionRecording parseSession(const nlohmann::json& document, const std::string& file) {
  const io::JsonNode root(document, file);
  if (!root.isObject()) root.expected("a session object {\"format\": \"coilsim-session/1\", ...}");
  root.allowKeys({"format", "case", "coil", "next_coils", "end_s", "timeline", "views"});
  root.child("format").oneOf({kSessionFormat});
  SessionRecording s;
  s.caseLabel = root.child("case").string();
  s.coil = root.child("coil").string();
  s.end = root.child("end_s").number(io::Bounds::closed(0, 3600, "s"));
  if (root.has("next_coils")) {
    double previous = 0;
    for (const io::JsonNode& c : root.child("next_coils").items(0, SIZE_MAX, "an array of {\"t_s\", \"coil\"}")) {
      c.allowKeys({"t_s", "coil"});
      const double t = c.child("t_s").number(io::Bounds::nonNegative());
      if (t < previous) c.child("t_s").fail("next coils are listed in time order");
      previous = t;
      s.nextCoils.push_back({c.child("coil").string(), t});
    }
  }
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

ScoreSheet playSession(const PracticeCase& pc, const SessionCoils& coils, const std::vector<TimedCommand>& timeline,
                       const std::vector<std::pair<double, std::string>>& views, double end,
                       ordered_json* recordingOut, const WallForceCheck& contacts,
                       const std::function<void(const PracticeSession&)>& atEnd,
                       const std::function<bool(const PracticeSession&)>& keepGoing) {
  PracticeSession session(pc, coils.first, contacts);
  const double dt = session.model().timeStep;
  const long steps = std::lround(end / dt);
  size_t nextCommand = 0, nextView = 0, nextCoil = 0;
  for (long s = 0; s < steps; ++s) {
    const double t = double(s) * dt;
    // The next coil first: it goes in between two steps, before their inputs
    // (the window changes coils there too). The same rule as runTimeline
    // for a time: at the first step starting at or after it.
    while (nextCoil < coils.next.size()) {
      const NextCoil& c = coils.next[nextCoil];
      if (c.time ? *c.time > t + 1e-9 * dt : !session.deploymentState().detached) break;
      session.nextCoil(c.coil);
      ++nextCoil;
    }
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
