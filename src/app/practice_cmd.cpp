// `coilsim practice`: scripted or replayed practice sessions and their score sheets.
#include "app/practice_cmd.h"

#include <charconv>
#include <cmath>
#include <cstdio>

#include "app/run_scene.h"
#include "io/json_reader.h"
#include "io/json_writer.h"
#include "io/timeline.h"
#include "planning/case_file.h"
#include "planning/live_readouts.h"
#include "planning/practice.h"
#include "planning/run_contacts.h"
#ifdef COILSIM_HAVE_UI
#include "ui/viewer.h"
#endif

namespace coilsim::app {
namespace {

int usage(const std::string& message) {
  std::fprintf(stderr,
               "coilsim practice: %s\n"
               "usage: coilsim practice CASE --coil NAME --input TIMELINE [--view 3d|xray|biplane] [--duration S]\n"
               "                        [--record SESSION] [--screenshot PNG] --out SCORE\n"
               "       coilsim practice CASE --replay SESSION [--screenshot PNG] --out SCORE\n"
               "       coilsim practice CASE --window [--coil NAME] [--view 3d|xray|biplane]\n"
               "(docs/planning.md)\n",
               message.c_str());
  return kExitUsage;
}

#ifdef COILSIM_HAVE_UI
// The window (or an off-screen picture) of a practice session's model and
// state, with the live read-outs: packing, protrusion and wall-force warnings.
ui::ViewerOptions practiceViewer(const planning::PracticeCase& pc, const planning::PracticeSession& session,
                                 const std::string& view) {
  ui::ViewerOptions v;
  v.scenePath = pc.name + " - " + session.runningScore().coil;
  v.view = view;
  const Deployment dep = session.deployment();
  v.addDrawData = [dep](const Model& m, const State& s, DrawData& d) { planning::appendInactiveCatheter(m, s, dep, d); };
  auto live = std::make_shared<planning::LiveReadouts>(pc, dep);
  v.readouts.title = "Practice: " + pc.name;
  v.readouts.compute = [live](const Model& m, const State& s) {
    std::vector<ui::Readout> out;
    for (const planning::LiveLine& l : live->lines(m, s)) out.push_back({l.label, l.value, l.warning});
    return out;
  };
  return v;
}
#endif

}  // namespace

int runPractice(const std::vector<std::string>& args) {
  std::string casePath, coil, input, view = "3d", record, replay, out, screenshot;
  bool window = false;
  double duration = 0;
  for (size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    auto value = [&](std::string& v) {
      if (i + 1 >= args.size()) return false;
      v = args[++i];
      return !v.empty();
    };
    std::string v;
    if (a == "--coil") {
      if (!value(coil)) return usage("--coil needs a coil name of the case's set");
    } else if (a == "--input") {
      if (!value(input)) return usage("--input needs a timeline file (coilsim-timeline/1)");
    } else if (a == "--window") {
      window = true;
    } else if (a == "--screenshot") {
      if (!value(screenshot)) return usage("--screenshot needs a PNG file name");
    } else if (a == "--view") {
      if (!value(view) || (view != "3d" && view != "xray" && view != "biplane"))
        return usage("--view needs 3d, xray or biplane, got \"" + view + "\"");
    } else if (a == "--duration") {
      const auto [end, ec] = value(v) ? std::from_chars(v.data(), v.data() + v.size(), duration)
                                      : std::from_chars_result{nullptr, std::errc::invalid_argument};
      if (ec != std::errc() || end != v.data() + v.size() || !(duration > 0) || !std::isfinite(duration))
        return usage("--duration needs seconds > 0, got \"" + v + "\"");
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
#ifndef COILSIM_HAVE_UI
  if (window || !screenshot.empty()) return usage("this build has no window or screenshots (no ui layer)");
#endif
  if (window) {
    if (!input.empty() || !replay.empty() || !record.empty() || !out.empty() || !screenshot.empty())
      return usage("--window practises by hand: drop --input, --replay, --record, --out and --screenshot");
  } else if (out.empty()) {
    return usage("practice needs --out SCORE (or --window)");
  }
  if (!window && replay.empty() == input.empty()) return usage("give either --input TIMELINE (play) or --replay SESSION");
  if (!replay.empty() && (!coil.empty() || !record.empty() || duration > 0 || view != "3d"))
    return usage("--replay takes the coil, views and duration from the session; drop --coil, --record, --view, --duration");
  try {
    const planning::PracticeCase pc = planning::loadCase(casePath);
#ifdef COILSIM_HAVE_UI
    if (window) {
      // By hand in the window, with the live read-outs. The window steps its own copy of the
      // model with its own device controls: no score sheet here (scripted sessions give one).
      const planning::PracticeSession session(pc, coil.empty() ? pc.coils.front().name : coil);
      Model model = session.model();
      State state = session.state();
      ui::ViewerOptions v = practiceViewer(pc, session, view);
      v.deployment = ui::DeploymentSetup{session.deployment(), session.deploymentState(), {}};
      return ui::runWindow(model, state, v);
    }
    // The last frame of a scripted session, in its last view, with the read-outs.
    std::string shotError;
    auto picture = [&](const planning::PracticeSession& s) {
      if (screenshot.empty()) return;
      ui::ViewerOptions v = practiceViewer(pc, s, s.view());
      v.deployment = ui::DeploymentSetup{s.deployment(), s.deploymentState(), {}};
      v.screenshotPath = screenshot;
      if (!ui::renderOffscreen(s.model(), s.state(), v, shotError)) std::fprintf(stderr, "coilsim practice: %s\n", shotError.c_str());
    };
#else
    const std::function<void(const planning::PracticeSession&)> picture;
#endif
    planning::ScoreSheet score;
    if (!replay.empty()) {
      const planning::SessionRecording s = planning::loadSession(replay);
      score = planning::playSession(pc, s.coil, s.timeline, s.views, s.end, nullptr, {}, picture);
    } else {
      if (coil.empty()) coil = pc.coils.front().name;
      const std::vector<TimedCommand> timeline = io::loadTimeline(input);
      // Without --duration: one second after the last command.
      if (duration == 0) duration = (timeline.empty() ? 0.0 : timeline.back().time) + 1.0;
      std::vector<std::pair<double, std::string>> views;
      if (view != "3d") views.emplace_back(0.0, view);
      nlohmann::ordered_json recording;
      score = planning::playSession(pc, coil, timeline, views, duration, &recording, {}, picture);
      if (!record.empty()) io::writeFileAtomic(record, io::formatJson(recording));
    }
    const std::string text = io::formatJson(planning::scoreJson(score));
    io::writeFileAtomic(out, text);
    std::fputs(text.c_str(), stdout);
    if (!score.ok) std::fprintf(stderr, "coilsim practice: %s\n", score.error.c_str());
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
