// Practice sessions: recorded inputs, score sheets, exact replay.
#include "planning/practice.h"

#include <cmath>

#include "io/json_reader.h"
#include "io/scene.h"
#include "io/timeline.h"
#include "io/units.h"
#include "physics/integrator.h"
#include "planning/contact_forces.h"
#include "planning/run_contacts.h"

namespace coilsim::planning {
namespace {

using nlohmann::ordered_json;
using Kind = DeviceCommand::Kind;

constexpr double kSampleInterval = 0.1;  // s between protrusion samples

// One command in the timeline file's words and units.
ordered_json commandJson(const TimedCommand& t) {
  ordered_json c;
  c["t_s"] = t.time;
  const DeviceCommand& d = t.command;
  auto linear = [&](const char* key) {
    ordered_json b;
    b["speed_mm_s"] = units::mToMm(d.rate);
    if (d.amount > 0) b["distance_mm"] = units::mToMm(d.amount);
    c[key] = b;
  };
  switch (d.kind) {
    case Kind::Push: linear("push"); break;
    case Kind::Pull: linear("pull"); break;
    case Kind::Retract: linear("retract"); break;
    case Kind::Twist: {
      ordered_json b;
      b["rate_deg_s"] = units::radToDeg(d.rate);
      if (d.amount > 0) b["angle_deg"] = units::radToDeg(d.amount);
      c["twist"] = b;
      break;
    }
    case Kind::Stop: c["stop"] = ordered_json::object(); break;
    case Kind::Detach: c["detach"] = ordered_json::object(); break;
  }
  return c;
}

bool fluoroscopic(const std::string& view) { return view == "xray" || view == "biplane"; }

}  // namespace

ordered_json scoreJson(const ScoreSheet& s) {
  ordered_json j;
  j["format"] = "coilsim-score/1";
  j["case"] = s.caseName;
  j["coil"] = s.coil;
  j["ok"] = s.ok;
  if (!s.ok) j["error"] = s.error;
  j["time_s"] = s.time;
  j["coil_length_placed_mm"] = units::mToMm(s.coilLengthPlaced);
  j["packing_density"] = s.packingDensity;
  j["neck_coverage"] = s.neckCoverage;
  j["occlusion_class"] = s.occlusion;
  j["protrusion_events"] = s.protrusionEvents;
  j["protruding_at_end"] = s.protrudingAtEnd;
  if (s.wallForcesAvailable) {
    j["max_wall_force_mN"] = s.maxWallForce * 1e3;  // N -> mN
    j["time_above_safety_s"] = s.timeAboveSafety;
  } else {
    j["max_wall_force_mN"] = nullptr;  // no contact forces in this build: unknown, not zero
    j["time_above_safety_s"] = nullptr;
  }
  j["max_tip_force_mN"] = s.maxTipForce * 1e3;
  j["repositionings"] = s.repositionings;
  j["fluoroscopy_time_s"] = s.fluoroscopyTime;
  j["detached"] = s.detached;
  j["detach_in_sac"] = s.detachInSac;
  j["goal_met"] = s.goalMet;
  return j;
}

PracticeSession::PracticeSession(const PracticeCase& pc, const std::string& coilName, const ContactForceSource& contacts)
    : case_(pc), contacts_(contacts ? contacts : ContactForceSource(wallContactForces)), coil_(coilName), sac_(pc.sac) {
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
  io::CompiledScene compiled;
  try {
    compiled = io::compileSceneWithDeployment(spec);
    addRunContacts(compiled.model, pc.sac);
    model_ = compileModel(compiled.model);
  } catch (const io::InputError&) {
    throw;
  } catch (const std::exception& e) {
    throw io::InputError(pc.file + ": /scene: " + e.what());
  }
  deployment_ = *compiled.deployment;
  state_ = makeState(model_);
  ds_ = initDeployment(deployment_, model_, state_, compiled.initialDeployed, compiled.initialTwist);
  setDrawnCatheterActive(deployment_, state_, false);
  sac_.neck.normal.normalize();
  sacVolume_ = volumeOnSide(*sac_.mesh, sac_.neck);
  neck_ = sampleNeck(sac_);
  score_.caseName = pc.name;
  score_.coil = coilName;
}

std::string PracticeSession::command(const DeviceCommand& c) {
  // Through the file's units and back, so the live session runs exactly the
  // numbers a replay of its recording reads.
  ordered_json doc;
  doc["format"] = io::kTimelineFormat;
  doc["commands"] = ordered_json::array({commandJson({time(), c})});
  const TimedCommand read = io::parseTimeline(nlohmann::json::parse(doc.dump()), "session").front();
  const std::string why = controller_.command(deployment_, ds_, read.command);
  if (!why.empty()) return why;
  recorded_.push_back(doc["commands"][0]);
  if (read.command.kind == Kind::Pull) ++score_.repositionings;
  return "";
}

std::string PracticeSession::replayCommand(const DeviceCommand& c) {
  const std::string why = controller_.command(deployment_, ds_, c);
  if (!why.empty()) return why;
  recorded_.push_back(commandJson({time(), c}));
  if (c.kind == Kind::Pull) ++score_.repositionings;
  return "";
}

void PracticeSession::setView(const std::string& view) {
  if (view == view_) return;
  view_ = view;
  views_.emplace_back(time(), view);
}

void PracticeSession::sample() {
  const SacMetrics m = measureSac(sac_, sacVolume_, neck_, coilLines(model_, state_, deployment_.chainRod, deployment_.tipNode));
  if (m.protruding && !protruding_) ++score_.protrusionEvents;
  protruding_ = m.protruding;
}

bool PracticeSession::step() {
  if (!score_.ok) return false;
  const double dt = model_.timeStep;
  // Counted in steps so the time is exactly steps x dt, as a reader would compute it.
  if (fluoroscopic(view_)) score_.fluoroscopyTime = double(++fluoroSteps_) * dt;
  const bool wasDetached = ds_.detached;
  const double deployedBefore = ds_.deployed, twistBefore = ds_.twist;
  controller_.advance(deployment_, model_, state_, ds_, dt);
  controller_.notes.clear();
  if (ds_.detached && !wasDetached) {
    score_.detached = true;
    const Vec3& tip = state_.rods[size_t(deployment_.chainRod)].x[size_t(deployment_.tipNode)];
    score_.detachInSac = sac_.neck.signedDistance(tip) >= 0 && insideSurface(sac_, tip);
  }
  const StepReport rep = coilsim::step(model_, state_);
  ++steps_;
  if (!rep.ok()) {
    score_.ok = false;
    score_.error = "step refused at t = " + std::to_string(time()) + " s: " + rep.message;
    return false;
  }
  // The force a hand feels, with the pusher at rest (FeltTipForce: the sliding tip beam spikes while pushing).
  if (!ds_.detached && felt_.add(deployment_, state_, ds_.deployed == deployedBefore && ds_.twist == twistBefore, dt))
    score_.maxTipForce = std::max(score_.maxTipForce, felt_.felt);
  if (contacts_ && contacts_(model_, state_, forces_)) {
    score_.wallForcesAvailable = true;
    wall_.add(forces_, dt, case_.goal.maxWallForce);
    score_.maxWallForce = wall_.max;
    score_.timeAboveSafety = wall_.timeAbove;
  }
  const long every = std::max(1L, std::lround(kSampleInterval / dt));
  if (steps_ % every == 0) sample();
  return true;
}

ScoreSheet PracticeSession::finish() {
  ScoreSheet s = score_;
  s.time = time();
  s.coilLengthPlaced = ds_.deployed;
  const SacMetrics m = measureSac(sac_, sacVolume_, neck_, coilLines(model_, state_, deployment_.chainRod, deployment_.tipNode));
  s.packingDensity = m.packingDensity;
  s.neckCoverage = m.neckCoverage;
  s.occlusion = occlusionClass(m.packingDensity, m.neckCoverage);
  s.protrudingAtEnd = m.protruding;
  if (m.protruding && !protruding_) ++s.protrusionEvents;
  const Goal& g = case_.goal;
  s.goalMet = s.ok && s.packingDensity >= g.minPackingDensity && (!g.noProtrusion || s.protrusionEvents == 0) &&
              (!s.wallForcesAvailable || s.maxWallForce <= g.maxWallForce) && (!g.detachInSac || s.detachInSac);
  return s;
}

ordered_json PracticeSession::recording() const {
  ordered_json r;
  r["format"] = kSessionFormat;
  r["case"] = case_.file;
  r["coil"] = coil_;
  r["end_s"] = time();
  ordered_json timeline;
  timeline["format"] = io::kTimelineFormat;
  timeline["name"] = case_.name + " session";
  timeline["description"] = "Inputs of a practice session with " + coil_ + "; play with coilsim practice --replay.";
  timeline["commands"] = ordered_json::array();
  for (const ordered_json& c : recorded_) timeline["commands"].push_back(c);
  r["timeline"] = timeline;
  r["views"] = ordered_json::array();
  for (const auto& [t, v] : views_) r["views"].push_back(ordered_json{{"t_s", t}, {"view", v}});
  return r;
}

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
                       ordered_json* recordingOut, const ContactForceSource& contacts,
                       const std::function<void(const PracticeSession&)>& atEnd) {
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
  }
  if (recordingOut) *recordingOut = session.recording();
  if (atEnd) atEnd(session);
  return session.finish();
}

}  // namespace coilsim::planning
