// `coilsim practice`: scripted, replayed or windowed (practice_window.cpp) sessions and their score sheets.
#include "app/practice_cmd.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>

#include "app/commands.h"
#include "app/format.h"
#include "app/graphics.h"
#include "app/practice_window.h"
#include "app/exit_codes.h"
#include "app/options.h"
#include "app/progress.h"
#include "app/stop_signal.h"
#include "io/json_reader.h"
#include "io/json_writer.h"
#include "io/timeline.h"
#include "planning/case_file.h"
#include "planning/practice.h"

namespace coilsim::app {
namespace {

int usage(const std::string& message) {
  std::fprintf(stderr,
               "coilsim practice: %s\n"
               "usage: coilsim practice CASE --coil NAME[+NAME...] --input TIMELINE [--view 3d|xray|biplane] [--views T:VIEW,...]\n"
               "                        [--duration S] [--record SESSION] [--screenshot PNG] [--size WxH] --out SCORE\n"
               "       coilsim practice CASE --replay SESSION [--screenshot PNG] [--size WxH] --out SCORE\n"
               "       coilsim practice CASE --window [--coil NAME[+NAME...]] [--view 3d|xray|biplane] [--record SESSION]\n"
               "                        [--out SCORE] [--input TIMELINE] [--views T:VIEW,...] [--duration S]\n"
               "                        [--screenshot PNG] [--size WxH]\n"
               "(docs/planning.md)\n",
               message.c_str());
  return kExitUsage;
}

// "0.5:xray,2:3d" -> view switches at their times, in time order.
bool parseViews(const std::string& text, std::vector<std::pair<double, std::string>>& out, std::string& why) {
  size_t at = 0;
  while (at <= text.size()) {
    const size_t comma = std::min(text.find(',', at), text.size());
    const std::string item = text.substr(at, comma - at);
    const size_t colon = item.find(':');
    double t = 0;
    const auto [end, ec] = colon == std::string::npos ? std::from_chars_result{nullptr, std::errc::invalid_argument}
                                                       : std::from_chars(item.data(), item.data() + colon, t);
    const std::string view = colon == std::string::npos ? "" : item.substr(colon + 1);
    if (ec != std::errc() || end != item.data() + colon || !(t >= 0) || !std::isfinite(t) ||
        (view != "3d" && view != "xray" && view != "biplane")) {
      why = "--views needs T:VIEW,... (seconds >= 0, view 3d, xray or biplane), got \"" + item + "\"";
      return false;
    }
    if (!out.empty() && t < out.back().first) {
      why = "--views must be in time order, got " + item + " after " + fmt("%g", out.back().first);
      return false;
    }
    out.emplace_back(t, view);
    at = comma + 1;
  }
  return true;
}

// "a+b+c" -> a, b, c (the coils of a session in order).
std::vector<std::string> coilNames(const std::string& text) {
  const planning::SessionCoils coils = planning::parseCoilSequence(text);
  std::vector<std::string> names{coils.first};
  for (const planning::NextCoil& c : coils.next) names.push_back(c.coil);
  return names;
}

}  // namespace

int runPractice(const std::vector<std::string>& args) {
  std::string casePath, coil, input, view = "3d", record, replay, out, screenshot;
  std::vector<std::pair<double, std::string>> views;
  bool window = false;
  double duration = 0;
  PictureSize size;
  for (size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    // An option's value is never the next option (`--out --duration` names no file).
    auto value = [&](std::string& v) {
      if (i + 1 >= args.size() || args[i + 1].rfind("--", 0) == 0) return false;
      v = args[++i];
      return !v.empty();
    };
    std::string v;
    if (a == "--coil") {
      if (!value(coil)) return usage("--coil needs a coil name of the case's set, or several joined by +");
      for (const std::string& name : coilNames(coil))
        if (name.empty()) return usage("--coil needs coil names joined by +, got \"" + coil + "\"");
    } else if (a == "--input") {
      if (!value(input)) return usage("--input needs a timeline file (coilsim-timeline/1)");
    } else if (a == "--window") {
      window = true;
    } else if (a == "--screenshot") {
      if (!value(screenshot)) return usage("--screenshot needs a PNG file name");
    } else if (a == "--view") {
      if (!value(view) || (view != "3d" && view != "xray" && view != "biplane"))
        return usage("--view needs 3d, xray or biplane, got \"" + view + "\"");
    } else if (a == "--views") {
      std::string why;
      if (!value(v)) return usage("--views needs T:VIEW,... e.g. 0.5:xray,2:3d");
      if (!parseViews(v, views, why)) return usage(why);
    } else if (a == "--duration") {
      const auto [end, ec] = value(v) ? std::from_chars(v.data(), v.data() + v.size(), duration)
                                      : std::from_chars_result{nullptr, std::errc::invalid_argument};
      // A session file holds at most an hour (what --replay reads back).
      if (ec != std::errc() || end != v.data() + v.size() || !(duration > 0) || !(duration <= 3600))
        return usage("--duration needs seconds in (0, 3600], got \"" + v + "\"");
    } else if (a == "--size") {
      std::string why;
      if (!value(v)) return usage("--size needs WIDTHxHEIGHT in pixels, e.g. 1920x1080");
      const auto wh = parseSize(*findOption(*findCommand("practice"), "--size"), v, why);
      if (!wh) return usage(why);
      size = {wh->first, wh->second};
    } else if (a == "--record") {
      if (!value(record)) return usage("--record needs a session file name");
    } else if (a == "--replay") {
      if (!value(replay)) return usage("--replay needs a session file (coilsim-session/1)");
    } else if (a == "--out") {
      if (!value(out)) return usage("--out needs a score file name");
    } else if (!a.empty() && a[0] == '-') {
      return usage("unknown option \"" + a + "\"");
    } else if (casePath.empty()) {
      casePath = a;
    } else {
      return usage("practice takes one case file, got \"" + casePath + "\" and \"" + a + "\"");
    }
  }
  if (casePath.empty()) return usage("practice needs a case file, e.g. scenes/cases/sphere-7mm.json");
  if ((window || !screenshot.empty()) && !haveUi()) return usage("this build has no window or screenshots (no ui layer)");
  if (window) {
    if (!replay.empty()) return usage("--window practises by hand; --replay plays a session headless: drop one");
  } else if (out.empty()) {
    return usage("practice needs --out SCORE (or --window)");
  }
  if (!window && replay.empty() == input.empty()) return usage("give either --input TIMELINE (play) or --replay SESSION");
  if (!replay.empty() && (!coil.empty() || !record.empty() || duration > 0 || view != "3d" || !views.empty()))
    return usage("--replay takes the coil, views and duration from the session; drop --coil, --record, --view, --views, "
                 "--duration");
  // Known before the session, not after it: a session is not lost to a typo.
  for (const std::string& path : {record, out})
    if (!path.empty())
      if (const std::string why = io::whyNotWritable(path); !why.empty()) {
        std::fprintf(stderr, "coilsim practice: %s\n", why.c_str());
        return kExitUsage;
      }
  try {
    const planning::PracticeCase pc = planning::loadCase(casePath);
    if (window) {
      if (!coil.empty()) planning::checkCoils(pc, planning::parseCoilSequence(coil));
      // By hand (or scripted, --input and --views as if typed), recorded and scored on close.
      const std::vector<TimedCommand> script = input.empty() ? std::vector<TimedCommand>() : io::loadTimeline(input);
      auto outputs = std::make_shared<WindowOutputs>();
      outputs->record = record;
      outputs->out = out;
      return practiseInWindow(pc, coil, view, script, views, duration, screenshot, size, outputs);
    }
    // The last frame of a scripted session, in its last view, with the read-outs.
    std::string shotError;
    auto picture = [&](const planning::PracticeSession& s) {
      if (screenshot.empty()) return;
      if (!practicePicture(pc, s, screenshot, size, shotError)) std::fprintf(stderr, "coilsim practice: %s\n", shotError.c_str());
    };
    planning::ScoreSheet score;
    // Progress on a terminal; Ctrl-C ends the session after the current step, scored as it stands.
    std::optional<Progress> progress;
    auto keepGoing = [&](const planning::PracticeSession& s) {
      progress->update(s.state().time);
      return !stopRequested();
    };
    if (!replay.empty()) {
      const planning::SessionRecording s = planning::loadSession(replay);
      // A session recorded on another case replays other physics: refused, naming the session's field.
      namespace fs = std::filesystem;
      std::error_code ec;
      const bool sameCase = s.caseLabel == casePath || fs::equivalent(fs::path(s.caseLabel), fs::path(casePath), ec) ||
                            fs::path(s.caseLabel).filename() == fs::path(casePath).filename();
      if (!sameCase)
        throw io::InputError(replay + ": /case: the session was recorded on \"" + s.caseLabel + "\", not on " + casePath);
      auto known = [&](const std::string& name) {
        return std::any_of(pc.coils.begin(), pc.coils.end(), [&](const io::CoilSpec& c) { return c.name == name; });
      };
      if (!known(s.coil)) throw io::InputError(replay + ": /coil: the case " + casePath + " has no coil \"" + s.coil + "\"");
      for (size_t k = 0; k < s.nextCoils.size(); ++k)
        if (!known(s.nextCoils[k].coil))
          throw io::InputError(replay + ": /next_coils/" + std::to_string(k) + "/coil: the case " + casePath +
                               " has no coil \"" + s.nextCoils[k].coil + "\"");
      progress.emplace("practice " + casePath, s.end, "s simulated");
      score = planning::playSession(pc, planning::SessionCoils(s.coil, s.nextCoils), s.timeline, s.views, s.end, nullptr,
                                    {}, picture, keepGoing);
    } else {
      const planning::SessionCoils coils = planning::parseCoilSequence(coil.empty() ? pc.coils.front().name : coil);
      planning::checkCoils(pc, coils);
      const std::vector<TimedCommand> timeline = io::loadTimeline(input);
      // Without --duration: one second after the last command.
      if (duration == 0) duration = std::min(3600.0, (timeline.empty() ? 0.0 : timeline.back().time) + 1.0);
      if (view != "3d") views.insert(views.begin(), {0.0, view});
      nlohmann::ordered_json recording;
      progress.emplace("practice " + casePath, duration, "s simulated");
      score = planning::playSession(pc, coils, timeline, views, duration, &recording, {}, picture, keepGoing);
      if (!record.empty()) io::writeFileAtomic(record, io::formatJson(recording));
    }
    if (progress) progress->finish();
    const std::string text = io::formatJson(planning::scoreJson(score));
    io::writeFileAtomic(out, text);
    std::fputs(text.c_str(), stdout);
    for (const std::string& m : score.deviceMessages) std::fprintf(stderr, "coilsim practice: device: %s\n", m.c_str());
    if (!score.ok) std::fprintf(stderr, "coilsim practice: %s\n", score.error.c_str());
    if (stopRequested()) {
      std::fprintf(stderr, "coilsim practice: %s: the score sheet is of the session so far\n", stopReason());
      return stopExitCode();
    }
    return score.ok ? kExitOk : kExitFailure;
  } catch (const io::InputError& e) {
    std::fprintf(stderr, "coilsim practice: %s\n", e.what());
    return kExitUsage;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "coilsim practice: %s\n", e.what());
    return kExitFailure;
  }
}

}  // namespace coilsim::app
