#pragma once
// Input timelines ("coilsim-timeline/1", docs/scene-format.md): timed device
// commands (push, pull, twist, stop, detach, retract) in mm, deg and s,
// parsed into the controller's TimedCommands in SI. Every error is an
// InputError naming the file, the JSON path and what was expected.
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "io/json_reader.h"
#include "physics/run.h"

namespace coilsim::io {

inline constexpr const char* kTimelineFormat = "coilsim-timeline/1";

// Reads the commands; times must be in [0, 3600] s and non-decreasing, at
// most 100000 commands, speeds in [0.001, 1000] mm/s, distances up to
// 10000 mm, twist rates up to 36000 deg/s and angles up to 360000 deg
// (docs/input-limits.md). Whether the device allows a command (push beyond
// the coil, pull after detach) is the controller's decision at run time,
// not the reader's.
std::vector<TimedCommand> parseTimeline(const nlohmann::json& document, const std::string& file);
// The same for a timeline inside another file (a session's "timeline"):
// errors name that file and the full JSON path (/timeline/commands/0/...).
std::vector<TimedCommand> parseTimeline(const JsonNode& timeline);

// readJsonFile + parseTimeline.
std::vector<TimedCommand> loadTimeline(const std::string& path);
// parseJson + parseTimeline, for timelines held in memory (tests).
std::vector<TimedCommand> timelineFromText(std::string_view text, const std::string& label);

// The command in the file's words and units, e.g. "push at 5 mm/s by 40 mm".
std::string describeCommand(const DeviceCommand& command);

}  // namespace coilsim::io
