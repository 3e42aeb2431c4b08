// Timeline file -> TimedCommands in SI; units convert only through units.h.
#include "io/timeline.h"

#include <cmath>
#include <cstdint>
#include <cstdio>

#include "io/json_reader.h"
#include "io/units.h"

namespace coilsim::io {
namespace {

using Kind = DeviceCommand::Kind;

constexpr std::string_view kKinds[] = {"push", "pull", "twist", "stop", "detach", "retract"};

std::string fmt(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

// What a timeline may ask (docs/input-limits.md). Far beyond any device (a
// hand pushes at a few mm/s); whether the device allows a command within
// them is the controller's decision at run time. Beyond them a value is a
// unit error, and 1e308 mm would overflow once converted.
constexpr double kMaxTimeS = 3600;           // a command at most an hour in
constexpr double kMinSpeedMmS = 0.001;       // push, pull, retract: 1 um/s (slower never arrives)
constexpr double kMaxSpeedMmS = 1000;
constexpr double kMaxDistanceMm = 10'000;    // 10 m
constexpr double kMaxTwistRateDegS = 36'000; // 100 turns per second
constexpr double kMaxTwistAngleDeg = 360'000;
constexpr size_t kMaxCommands = 100'000;

// A number within `bounds` (the message the format has always given), then
// within the limits above, which get their own message naming the limit.
double limited(const JsonNode& n, const Bounds& bounds, double lowest, double highest, std::string_view unit) {
  const double v = n.number(bounds);
  if (std::abs(v) < lowest || std::abs(v) > highest)
    n.fail("expected a magnitude in [" + fmt(lowest) + ", " + fmt(highest) + "] " + std::string(unit) + ", got " + fmt(v) +
           " (the timeline limits, docs/input-limits.md)");
  return v;
}

// push, pull, retract: {"speed_mm_s" > 0, "distance_mm" > 0 (optional: until stopped or a limit)}.
DeviceCommand readLinear(const JsonNode& n, Kind kind) {
  n.allowKeys({"speed_mm_s", "distance_mm"});
  DeviceCommand c;
  c.kind = kind;
  c.rate = units::mmPerSToMPerS(limited(n.child("speed_mm_s"), Bounds::positive(), kMinSpeedMmS, kMaxSpeedMmS, "mm/s"));
  if (auto d = n.optional("distance_mm"))
    c.amount = units::mmToM(limited(*d, Bounds::positive(), 0, kMaxDistanceMm, "mm"));
  return c;
}

// twist: {"rate_deg_s" != 0 (its sign turns right- or left-handed about the
// exit direction), "angle_deg" > 0 (optional: until stopped)}.
DeviceCommand readTwist(const JsonNode& n) {
  n.allowKeys({"rate_deg_s", "angle_deg"});
  DeviceCommand c;
  c.kind = Kind::Twist;
  const JsonNode rate = n.child("rate_deg_s");
  const double r = rate.number(Bounds::any());
  if (r == 0) rate.expected("a finite non-zero number (deg/s; negative turns left-handed)");
  limited(rate, Bounds::any(), 0, kMaxTwistRateDegS, "deg/s");
  c.rate = units::degPerSToRadPerS(r);
  if (auto a = n.optional("angle_deg"))
    c.amount = units::degToRad(limited(*a, Bounds::positive(), 0, kMaxTwistAngleDeg, "deg"));
  return c;
}

TimedCommand readCommand(const JsonNode& n) {
  if (!n.isObject()) n.expected("a command object {\"t_s\": ..., \"push\" | \"pull\" | ...: {...}}");
  std::vector<std::string_view> allowed{"t_s"};
  allowed.insert(allowed.end(), std::begin(kKinds), std::end(kKinds));
  n.allowKeys(allowed);
  TimedCommand t;
  t.time = limited(n.child("t_s"), Bounds::nonNegative(), 0, kMaxTimeS, "s");
  std::string_view kind;
  for (std::string_view k : kKinds) {
    if (!n.has(k)) continue;
    if (!kind.empty())
      n.fail("a command has exactly one of push, pull, twist, stop, detach, retract; got \"" + std::string(kind) +
             "\" and \"" + std::string(k) + "\"");
    kind = k;
  }
  if (kind.empty()) n.fail("a command needs one of push, pull, twist, stop, detach, retract");
  const JsonNode body = n.child(kind);
  if (!body.isObject()) body.expected("an object");
  if (kind == "push") t.command = readLinear(body, Kind::Push);
  else if (kind == "pull") t.command = readLinear(body, Kind::Pull);
  else if (kind == "retract") t.command = readLinear(body, Kind::Retract);
  else if (kind == "twist") t.command = readTwist(body);
  else {
    body.allowKeys(std::span<const std::string_view>());
    t.command.kind = kind == "stop" ? Kind::Stop : Kind::Detach;
  }
  return t;
}

}  // namespace

std::vector<TimedCommand> parseTimeline(const nlohmann::json& document, const std::string& file) {
  return parseTimeline(JsonNode(document, file));
}

std::vector<TimedCommand> parseTimeline(const JsonNode& root) {
  if (!root.isObject()) root.expected("a JSON object (a coilsim timeline)");
  root.allowKeys({"format", "name", "description", "commands"});
  root.child("format").oneOf({kTimelineFormat});
  if (auto n = root.optional("name")) (void)n->string();
  if (auto d = root.optional("description")) (void)d->string(true);
  std::vector<TimedCommand> out;
  const std::vector<JsonNode> commands = root.child("commands").items(0, SIZE_MAX, "an array of commands");
  if (commands.size() > kMaxCommands)
    root.child("commands").fail("holds " + std::to_string(commands.size()) + " commands, more than the limit of " +
                                std::to_string(kMaxCommands) + " (docs/input-limits.md)");
  for (const JsonNode& item : commands) {
    out.push_back(readCommand(item));
    // Commands run in file order; a time going back would silently reorder them.
    if (out.size() > 1 && out.back().time < out[out.size() - 2].time)
      item.child("t_s").fail("expected a time >= the previous command's (" + fmt(out[out.size() - 2].time) +
                             " s): commands are listed in time order, got " + fmt(out.back().time) + " s");
  }
  return out;
}

std::vector<TimedCommand> loadTimeline(const std::string& path) { return parseTimeline(readJsonFile(path), path); }

std::vector<TimedCommand> timelineFromText(std::string_view text, const std::string& label) {
  return parseTimeline(parseJson(text, label), label);
}

std::string describeCommand(const DeviceCommand& c) {
  const auto linear = [&](const char* verb) {
    std::string s = std::string(verb) + " at " + fmt(units::mToMm(c.rate)) + " mm/s";
    if (c.amount > 0) s += " by " + fmt(units::mToMm(c.amount)) + " mm";
    return s;
  };
  switch (c.kind) {
    case Kind::Push: return linear("push");
    case Kind::Pull: return linear("pull");
    case Kind::Retract: return linear("retract");
    case Kind::Twist: {
      std::string s = "twist at " + fmt(units::radToDeg(c.rate)) + " deg/s";
      if (c.amount > 0) s += " by " + fmt(units::radToDeg(c.amount)) + " deg";
      return s;
    }
    case Kind::Stop: return "stop";
    case Kind::Detach: return "detach";
  }
  return "?";
}

}  // namespace coilsim::io
