#pragma once
// Input timelines ("coilsim-timeline/1", docs/scene-format.md): timed device
// commands (push, pull, twist, stop, detach, retract) in mm, deg and s,
// parsed into the controller's TimedCommands in SI. Every error is an
// InputError naming the file, the JSON path and what was expected.
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "physics/run.h"

namespace coilsim::io {

inline constexpr const char* kTimelineFormat = "coilsim-timeline/1";

// Reads the commands; times must be >= 0 and non-decreasing. Whether the
// device allows a command (push beyond the coil, pull after detach) is the
// controller's decision at run time, not the reader's.
std::vector<TimedCommand> parseTimeline(const nlohmann::json& document, const std::string& file);

// readJsonFile + parseTimeline.
std::vector<TimedCommand> loadTimeline(const std::string& path);
// parseJson + parseTimeline, for timelines held in memory (tests).
std::vector<TimedCommand> timelineFromText(std::string_view text, const std::string& label);

// The command in the file's words and units, e.g. "push at 5 mm/s by 40 mm".
std::string describeCommand(const DeviceCommand& command);

}  // namespace coilsim::io
