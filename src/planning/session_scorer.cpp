// The score sheet and recording of a practice session, step by step.
#include "planning/session_scorer.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "io/timeline.h"
#include "io/units.h"

namespace coilsim::planning {
namespace {

using nlohmann::ordered_json;
using Kind = DeviceCommand::Kind;

constexpr double kSampleInterval = 0.1;  // s between protrusion samples

}  // namespace

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

DeviceCommand asRecorded(const DeviceCommand& c) {
  // Through the text a file holds, as loadSession will read it.
  ordered_json doc;
  doc["format"] = io::kTimelineFormat;
  doc["commands"] = ordered_json::array({commandJson({0.0, c})});
  return io::parseTimeline(nlohmann::json::parse(doc.dump()), "session").front().command;
}

bool fluoroscopic(const std::string& view) { return view == "xray" || view == "biplane"; }

ordered_json scoreJson(const ScoreSheet& s) {
  ordered_json j;
  j["format"] = "coilsim-score/1";
  j["case"] = s.caseName;
  j["coil"] = s.coil;
  j["ok"] = s.ok;
  if (!s.ok) j["error"] = s.error;
  j["time_s"] = s.time;
  j["coil_length_placed_mm"] = units::mToMm(s.coilLengthPlaced);
  j["packing_percent"] = 100 * s.packingDensity;
  j["neck_coverage_percent"] = 100 * s.neckCoverage;
  j["occlusion_class"] = s.occlusion;
  j["protrusion_events"] = s.protrusionEvents;
  j["protruding_at_end"] = s.protrudingAtEnd;
  j["wall_load_window_ms"] = units::sToMs(kWallLoadWindow);
  if (s.wallForcesAvailable) {
    j["largest_wall_load_mN"] = units::nToMn(s.maxWallForce);
    j["time_above_safety_s"] = s.timeAboveSafety;
    j["max_wall_penetration_um"] = units::mToUm(s.maxWallPenetration);
    j["max_wall_penetration_of_radius"] = s.maxWallPenetrationOfRadius;
  } else {
    j["largest_wall_load_mN"] = nullptr;  // no wall contact in this run: unknown, not zero
    j["time_above_safety_s"] = nullptr;
    j["max_wall_penetration_um"] = nullptr;
    j["max_wall_penetration_of_radius"] = nullptr;
  }
  j["max_tip_force_mN"] = units::nToMn(s.maxTipForce);
  j["repositionings"] = s.repositionings;
  j["fluoroscopy_time_s"] = s.fluoroscopyTime;
  j["detached"] = s.detached;
  j["detach_in_sac"] = s.detachInSac;
  if (s.coils.size() > 1) {
    ordered_json coils = ordered_json::array();
    for (const CoilOutcome& c : s.coils)
      coils.push_back({{"coil", c.coil},
                       {"from_s", c.from},
                       {"length_placed_mm", units::mToMm(c.lengthPlaced)},
                       {"detached", c.detached},
                       {"detach_in_sac", c.detachInSac}});
    j["coils"] = coils;
  }
  ordered_json goal;
  goal["min_packing_percent"] = 100 * s.goal.minPackingDensity;
  goal["no_protrusion"] = s.goal.noProtrusion;
  goal["max_wall_load_mN"] = units::nToMn(s.goal.maxWallForce);
  goal["detach_in_sac"] = s.goal.detachInSac;
  j["goal"] = goal;
  j["goal_met"] = s.goalMet;
  j["goal_missed"] = s.goalMissed;
  j["device_messages"] = s.deviceMessages;
  return j;
}

SessionScorer::SessionScorer(const PracticeCase& pc, const std::string& coil, const Deployment& dep, double dt,
                             const WallForceCheck& contacts)
    : case_(pc),
      contacts_(contacts ? contacts : WallForceCheck(hasWallForces)),
      coil_(coil),
      dep_(dep),
      dt_(dt),
      sac_(pc.sac) {
  sac_.neck.normal.normalize();
  sacVolume_ = sacVolume(sac_);
  neck_ = sampleNeck(sac_);
  score_.caseName = pc.name;
  score_.coil = coil;
}

void SessionScorer::commandAccepted(double, const ordered_json& recorded, const DeviceCommand& applied) {
  recorded_.push_back(recorded);
  if (applied.kind == Kind::Pull) ++score_.repositionings;
}

void SessionScorer::viewChanged(double t, const std::string& view) {
  if (view == view_) return;
  view_ = view;
  views_.emplace_back(t, view);
}

void SessionScorer::coilChanged(double t, const std::string& coil, const Deployment& dep, const State& left) {
  left_.push_back({coil_, coilFrom_, left.device.deployed, coilDetached_, coilInSac_});
  coil_ = coil;
  coilFrom_ = t;
  coilDetached_ = coilInSac_ = false;
  dep_ = dep;
  felt_ = FeltTipForce();
  wasDetached_ = false;
  score_.coil += " + " + coil;
  recordedCoils_.emplace_back(t, coil);
}

void SessionScorer::deviceMessage(const std::string& message) {
  char t[40];
  std::snprintf(t, sizeof t, "t = %.3f s: ", time());
  score_.deviceMessages.push_back(t + message);
}

void SessionScorer::beforeStep(const State& state) {
  if (!score_.ok) return;
  const DeviceState& ds = state.device;
  ++steps_;
  // Counted in steps so the time is exactly steps x dt, as a reader would compute it.
  if (fluoroscopic(view_)) score_.fluoroscopyTime = double(++fluoroSteps_) * dt_;
  wasDetached_ = ds.detached;
  deployedBefore_ = ds.deployed;
  twistBefore_ = ds.twist;
}


SacMetrics SessionScorer::measure(const Model& model, const State& state) const {
  return measureSac(sac_, sacVolume_, neck_, coilLines(model, state, dep_.chainRod, dep_.tipNode));
}

void SessionScorer::afterStep(const Model& model, const State& state, const StepReport& report) {
  if (!score_.ok) return;
  const DeviceState& ds = state.device;
  if (ds.detached && !wasDetached_) {
    coilDetached_ = true;
    const Vec3& tip = ds.releasedAt;
    coilInSac_ = inSac(sac_, tip) && !measure(model, state).protruding;
  }
  if (!report.ok()) {
    score_.ok = false;
    score_.error = "step refused at t = " + std::to_string(time()) + " s: " + report.message();
    return;
  }
  // The force a hand feels, with the pusher at rest (FeltTipForce: the sliding tip beam spikes while pushing).
  if (!ds.detached && felt_.add(dep_, state, ds.deployed == deployedBefore_ && ds.twist == twistBefore_, dt_))
    score_.maxTipForce = std::max(score_.maxTipForce, felt_.felt);
  if (contacts_ && contacts_(model, state)) {
    score_.wallForcesAvailable = true;
    wall_.add(state, dt_, case_.goal.maxWallForce);
    score_.maxWallForce = wall_.max;
    score_.timeAboveSafety = wall_.timeAbove;
  }
  const long every = std::max(1L, std::lround(kSampleInterval / dt_));
  if (steps_ % every == 0) {
    const SacMetrics m = measure(model, state);
    if (m.protruding && !protruding_) ++score_.protrusionEvents;
    protruding_ = m.protruding;
  }
}

ScoreSheet SessionScorer::finish(const Model& model, const State& state) const {
  ScoreSheet s = score_;
  s.time = time();
  s.coils = left_;
  s.coils.push_back({coil_, coilFrom_, state.device.deployed, coilDetached_, coilInSac_});
  s.detached = s.detachInSac = true;
  s.coilLengthPlaced = 0;
  for (const CoilOutcome& c : s.coils) {
    s.coilLengthPlaced += c.lengthPlaced;
    s.detached = s.detached && c.detached;
    s.detachInSac = s.detachInSac && c.detachInSac;
  }
  s.maxWallPenetration = state.stats.maxWallPenetration;
  s.maxWallPenetrationOfRadius = state.stats.maxWallPenetrationOfRadius;
  const SacMetrics m = measure(model, state);
  s.packingDensity = m.packingDensity;
  s.neckCoverage = m.neckCoverage;
  s.occlusion = occlusionClass(m.packingDensity, m.neckCoverage);
  s.protrudingAtEnd = m.protruding;
  if (m.protruding && !protruding_) ++s.protrusionEvents;
  const Goal& g = case_.goal;
  s.goal = g;
  char b[160];
  if (!s.ok) s.goalMissed.push_back("the session ended with a refused step");
  if (s.packingDensity < g.minPackingDensity) {
    std::snprintf(b, sizeof b, "packing %.1f %% is below %.0f %%", 100 * s.packingDensity, 100 * g.minPackingDensity);
    s.goalMissed.push_back(b);
  }
  if (g.noProtrusion && s.protrusionEvents > 0)
    s.goalMissed.push_back("the coil protruded through the neck " + std::to_string(s.protrusionEvents) + " time(s)" +
                           (s.protrudingAtEnd ? ", and does at the end" : ""));
  if (s.wallForcesAvailable && s.maxWallForce > g.maxWallForce) {
    std::snprintf(b, sizeof b, "the wall load reached %.1f mN (limit %.0f mN)", units::nToMn(s.maxWallForce),
                  units::nToMn(g.maxWallForce));
    s.goalMissed.push_back(b);
  }
  if (g.detachInSac && !s.detachInSac)
    s.goalMissed.push_back(s.detached ? "detached with the tip outside the sac or the coil through the neck"
                                      : "not detached");
  s.goalMet = s.goalMissed.empty();
  return s;
}

ordered_json SessionScorer::recording(double end) const {
  ordered_json r;
  r["format"] = kSessionFormat;
  r["case"] = case_.file;
  r["coil"] = left_.empty() ? coil_ : left_.front().coil;
  if (!recordedCoils_.empty()) {
    r["next_coils"] = ordered_json::array();
    for (const auto& [t, c] : recordedCoils_) r["next_coils"].push_back(ordered_json{{"t_s", t}, {"coil", c}});
  }
  r["end_s"] = end;
  ordered_json timeline;
  timeline["format"] = io::kTimelineFormat;
  timeline["name"] = case_.name + " session";
  timeline["description"] = "Inputs of a practice session with " + score_.coil + "; play with coilsim practice --replay.";
  timeline["commands"] = ordered_json::array();
  for (const ordered_json& c : recorded_) timeline["commands"].push_back(c);
  r["timeline"] = timeline;
  r["views"] = ordered_json::array();
  for (const auto& [t, v] : views_) r["views"].push_back(ordered_json{{"t_s", t}, {"view", v}});
  return r;
}

}  // namespace coilsim::planning
