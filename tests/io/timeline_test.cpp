// Input timelines: every command kind in SI, and every kind of bad input
// named by its file and JSON path.
#include "io/timeline.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>

#include "io/expect_error.h"

namespace coilsim::io {
namespace {

using Kind = DeviceCommand::Kind;

constexpr const char* kTimeline = R"({
  "format": "coilsim-timeline/1",
  "description": "every command once",
  "commands": [
    {"t_s": 0.0, "push": {"speed_mm_s": 5, "distance_mm": 40}},
    {"t_s": 9, "twist": {"rate_deg_s": -90, "angle_deg": 90}},
    {"t_s": 10, "stop": {}},
    {"t_s": 12, "pull": {"speed_mm_s": 2}},
    {"t_s": 12, "push": {"speed_mm_s": 2}},
    {"t_s": 20, "detach": {}},
    {"t_s": 21, "retract": {"speed_mm_s": 5, "distance_mm": 10}}
  ]
})";

nlohmann::json base() { return nlohmann::json::parse(kTimeline); }

std::string errorWith(const std::string& pointer, const nlohmann::json& value, bool remove = false) {
  nlohmann::json doc = base();
  const nlohmann::json::json_pointer p(pointer);
  if (remove) doc.at(p.parent_pointer()).erase(p.back());
  else doc[p] = value;
  return errorOf([&] { (void)timelineFromText(doc.dump(2), "tl.json"); });
}

TEST(Timeline, ReadsEveryCommandInSi) {
  const std::vector<TimedCommand> t = timelineFromText(kTimeline, "tl.json");
  ASSERT_EQ(t.size(), 7u);
  EXPECT_EQ(t[0].command.kind, Kind::Push);
  EXPECT_DOUBLE_EQ(t[0].time, 0.0);
  EXPECT_DOUBLE_EQ(t[0].command.rate, 5e-3);
  EXPECT_DOUBLE_EQ(t[0].command.amount, 40e-3);
  EXPECT_EQ(t[1].command.kind, Kind::Twist);
  EXPECT_NEAR(t[1].command.rate, -M_PI / 2, 1e-15);
  EXPECT_NEAR(t[1].command.amount, M_PI / 2, 1e-15);
  EXPECT_EQ(t[2].command.kind, Kind::Stop);
  EXPECT_EQ(t[3].command.kind, Kind::Pull);
  EXPECT_DOUBLE_EQ(t[3].command.amount, 0.0);  // no distance: until stopped or a limit
  EXPECT_DOUBLE_EQ(t[4].time, 12.0);           // equal times keep file order
  EXPECT_EQ(t[5].command.kind, Kind::Detach);
  EXPECT_EQ(t[6].command.kind, Kind::Retract);
  EXPECT_DOUBLE_EQ(t[6].command.amount, 10e-3);
  EXPECT_EQ(describeCommand(t[0].command), "push at 5 mm/s by 40 mm");
  EXPECT_EQ(describeCommand(t[1].command), "twist at -90 deg/s by 90 deg");
  EXPECT_EQ(describeCommand(t[3].command), "pull at 2 mm/s");
}

TEST(Timeline, EmptyCommandListIsAllowed) {
  EXPECT_TRUE(timelineFromText(R"({"format": "coilsim-timeline/1", "commands": []})", "tl.json").empty());
}

TEST(TimelineErrors, FileLevelProblemsNameTheFile) {
  EXPECT_CONTAINS(errorOf([] { (void)timelineFromText("{\"format\": ", "tl.json"); }), "tl.json: line 1, column");
  EXPECT_CONTAINS(errorOf([] { (void)timelineFromText("[]", "tl.json"); }),
                  "tl.json: /: expected a JSON object (a coilsim timeline), got an empty array");
  EXPECT_CONTAINS(errorWith("/format", "coilsim-timeline/2"),
                  "tl.json: /format: expected \"coilsim-timeline/1\", got \"coilsim-timeline/2\"");
  EXPECT_CONTAINS(errorWith("/commands", nullptr, true), "tl.json: /commands: missing; expected an array of commands");
  EXPECT_CONTAINS(errorWith("/command", nlohmann::json::array()), "tl.json: /command: unknown key (did you mean \"commands\"?)");
  const std::string missing = (std::filesystem::path(testing::TempDir()) / "no-such-timeline.json").string();
  EXPECT_CONTAINS(errorOf([&] { (void)loadTimeline(missing); }), missing + ": cannot open the file");
}

TEST(TimelineErrors, CommandProblemsNameTheirPath) {
  EXPECT_CONTAINS(errorWith("/commands/1/t_s", -1), "tl.json: /commands/1/t_s: expected a finite number >= 0, got -1");
  EXPECT_CONTAINS(errorWith("/commands/1/t_s", nullptr, true), "/commands/1/t_s: missing");
  EXPECT_CONTAINS(errorWith("/commands/2/t_s", 5),
                  "tl.json: /commands/2/t_s: expected a time >= the previous command's (9 s): commands are listed in "
                  "time order, got 5 s");
  EXPECT_CONTAINS(errorWith("/commands/0/push/speed_mm_s", 0), "/commands/0/push/speed_mm_s: expected a finite number > 0, got 0");
  EXPECT_CONTAINS(errorWith("/commands/0/push/speed_mm_s", nullptr, true), "/commands/0/push/speed_mm_s: missing");
  EXPECT_CONTAINS(errorWith("/commands/0/push/distance_mm", -4), "/commands/0/push/distance_mm: expected a finite number > 0");
  EXPECT_CONTAINS(errorWith("/commands/0/push/speed", 5), "/commands/0/push/speed: unknown key (did you mean \"speed_mm_s\"?)");
  EXPECT_CONTAINS(errorWith("/commands/1/twist/rate_deg_s", 0),
                  "/commands/1/twist/rate_deg_s: expected a finite non-zero number (deg/s; negative turns left-handed), got 0");
  EXPECT_CONTAINS(errorWith("/commands/1/twist/angle_deg", 0), "/commands/1/twist/angle_deg: expected a finite number > 0");
  EXPECT_CONTAINS(errorWith("/commands/2/stop", {{"now", true}}), "/commands/2/stop/now: unknown key; allowed here: none");
  EXPECT_CONTAINS(errorWith("/commands/5/detach", 1), "/commands/5/detach: expected an object, got 1");
  EXPECT_CONTAINS(errorWith("/commands/0/jump", nlohmann::json::object()), "/commands/0/jump: unknown key; allowed here: t_s, push");
  EXPECT_CONTAINS(errorWith("/commands/0/pull", {{"speed_mm_s", 1}}),
                  "tl.json: /commands/0: a command has exactly one of push, pull, twist, stop, detach, retract; got "
                  "\"push\" and \"pull\"");
  EXPECT_CONTAINS(errorWith("/commands/0/push", nullptr, true),
                  "/commands/0: a command needs one of push, pull, twist, stop, detach, retract");
  EXPECT_CONTAINS(errorWith("/commands/3", 7), "/commands/3: expected a command object");
  // Beyond the range of a double: caught while parsing, with the path.
  EXPECT_CONTAINS(errorOf([] {
                    (void)timelineFromText(R"({"format": "coilsim-timeline/1", "commands": [{"t_s": 1e400, "stop": {}}]})",
                                           "tl.json");
                  }),
                  "/commands/0/t_s: expected a finite number, got 1e400");
}

// The timelines shipped in timelines/ all read.
TEST(Timeline, ShippedTimelinesLoad) {
  int count = 0;
  for (const auto& entry : std::filesystem::directory_iterator(std::string(COILSIM_SOURCE_DIR) + "/timelines")) {
    if (entry.path().extension() != ".json") continue;
    SCOPED_TRACE(entry.path().string());
    EXPECT_FALSE(loadTimeline(entry.path().string()).empty());
    ++count;
  }
  EXPECT_GE(count, 1);
}

}  // namespace
}  // namespace coilsim::io
