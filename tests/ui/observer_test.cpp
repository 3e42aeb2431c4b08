// What the window tells the app (ui::RunObserver): every input with the
// session time it acts from, view switches, the steps around which a
// practice score is kept; scripted inputs given as the timeline rule says
// (the first step starting at or after their time); a setup chosen in the
// panel replaces the run, a failed one keeps it; X-ray-only views.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "physics/effect.h"
#include "ui/panel.h"
#include "ui/session.h"
#include "ui/setup.h"
#include "ui/views.h"
#include "support/helix_deployment.h"

namespace coilsim::ui {
namespace {

// A platinum helix of `lengthMm` in a rigid catheter at the origin along +x, 2 mm out.
using Scene = test::HelixDeployment;

Scene makeScene(double lengthMm = 40.0) { return test::makeHelixDeployment(lengthMm); }

DeviceCommand push(double speed, double distance = 0) {
  DeviceCommand c;
  c.kind = DeviceCommand::Kind::Push;
  c.rate = speed;
  c.amount = distance;
  return c;
}

// Logs what the session reports; halves every command's speed (as a recorder may change it).
struct Log : RunObserver {
  std::vector<std::pair<double, double>> commands;  // (t, applied speed) of accepted commands
  std::vector<std::pair<double, std::string>> views;
  long before = 0, after = 0, fluoroSteps = 0, restarts = 0;
  std::string view = "3d";
  DeviceCommand adjust(const DeviceCommand& c) override {
    DeviceCommand a = c;
    a.rate *= 0.5;
    return a;
  }
  void accepted(double t, const DeviceCommand&, const DeviceCommand& applied) override {
    commands.emplace_back(t, applied.rate);
  }
  void viewChanged(double t, const std::string& v) override {
    views.emplace_back(t, v);
    view = v;
  }
  void beforeStep(const State&) override {
    ++before;
    if (view != "3d") ++fluoroSteps;
  }
  void afterStep(const Model&, const State&, const StepReport&) override { ++after; }
  void restarted() override { *this = Log(); restarts = 1; }
};

TEST(RunObserver, ScriptedInputsActAtTheFirstStepStartingAtOrAfterTheirTime) {
  const Scene sc = makeScene();
  Session session(sc.model, sc.start);
  auto log = std::make_shared<Log>();
  session.setObserver(log);
  // 10 mm/s asked, 5 mm/s applied (the observer halves it), from 0.1005 s: the step starting at 0.101 s.
  std::vector<ScriptedInput> script;
  script.push_back({0.05, std::nullopt, "xray"});
  script.push_back({0.1005, push(0.010), ""});
  script.push_back({0.3, std::nullopt, "3d"});
  session.setScript(script);
  session.stepMany(400);

  ASSERT_EQ(log->views.size(), 3u);  // "3d" when attached, then the two switches
  EXPECT_EQ(log->views[0], std::make_pair(0.0, std::string("3d")));
  EXPECT_NEAR(log->views[1].first, 0.05, 1e-12);
  EXPECT_NEAR(log->views[2].first, 0.3, 1e-12);
  ASSERT_EQ(log->commands.size(), 1u);
  EXPECT_NEAR(log->commands[0].first, 0.101, 1e-12);
  EXPECT_DOUBLE_EQ(log->commands[0].second, 0.005);
  EXPECT_EQ(log->before, 400);
  EXPECT_EQ(log->after, 400);
  // X-ray from 0.05 s to 0.3 s: 250 steps.
  EXPECT_EQ(log->fluoroSteps, 250);
  // Pushed at the applied 5 mm/s for the 299 steps from 0.101 s to 0.4 s.
  EXPECT_NEAR(session.deploymentState().deployed, 2e-3 + 0.005 * 0.299, 1e-9);
  EXPECT_NEAR(session.deviceTime(), 0.4, 1e-12);
  EXPECT_TRUE(session.scriptDone());
}

TEST(RunObserver, ResetStartsTheInputsAgain) {
  const Scene sc = makeScene();
  Session session(sc.model, sc.start);
  auto log = std::make_shared<Log>();
  session.setObserver(log);
  session.setView("biplane");
  session.setScript({{0.01, push(0.010), ""}});
  session.stepMany(50);
  ASSERT_EQ(log->commands.size(), 1u);
  session.reset();
  // The observer starts a new session, told the view that is on.
  EXPECT_EQ(log->restarts, 1);
  ASSERT_EQ(log->views.size(), 1u);
  EXPECT_EQ(log->views[0], std::make_pair(0.0, std::string("biplane")));
  EXPECT_TRUE(log->commands.empty());
  session.stepMany(20);
  EXPECT_EQ(log->commands.size(), 1u);  // the script played again from its start
  EXPECT_EQ(log->fluoroSteps, 20);
}

TEST(SetupChoice, ALoadedSetupReplacesTheRunAFailedOneKeepsIt) {
  const Scene first = makeScene(40.0);
  Session session(first.model, first.start);
  session.setPlaying(true);
  session.stepMany(10);
  SetupChoices choices;
  choices.coils = {"short 20 mm", "too long"};
  choices.build = [](int coil, int) {
    if (coil == 1) throw std::runtime_error("the coil is longer than the catheter allows");
    const Scene s = makeScene(20.0);
    SceneSetup setup;
    setup.model = s.model;
    setup.state = s.start;
    setup.readouts.compute = [](const Model&, const State&) { return std::vector<Readout>{{"a", "b", false}}; };
    setup.loaded = "loaded the short coil";
    return setup;
  };
  PanelContext panel;

  EXPECT_FALSE(applySetup(choices, 1, -1, session, panel));
  EXPECT_TRUE(panel.setupStatus.failed);
  EXPECT_NE(panel.setupStatus.message.find("longer than the catheter"), std::string::npos);
  EXPECT_DOUBLE_EQ(session.deployment()->coilLength, 0.040);  // still the running coil
  EXPECT_EQ(session.stepsTaken(), 10);
  EXPECT_EQ(choices.coil, -1);
  EXPECT_FALSE(panel.readouts);

  ASSERT_TRUE(applySetup(choices, 0, -1, session, panel));
  EXPECT_FALSE(panel.setupStatus.failed);
  EXPECT_EQ(panel.setupStatus.message, "loaded the short coil");
  EXPECT_DOUBLE_EQ(session.deployment()->coilLength, 0.020);
  EXPECT_EQ(session.state().rods[0].x.size(), makeScene(20.0).start.rods[0].x.size());
  EXPECT_EQ(session.stepsTaken(), 0);  // from the start, paused
  EXPECT_FALSE(session.playing());
  EXPECT_EQ(session.state().time, 0.0);
  EXPECT_EQ(choices.coil, 0);
  EXPECT_TRUE(panel.readouts);
  // It runs: pushed 4 mm at 10 mm/s.
  session.command(push(0.010, 0.004));
  session.stepMany(500);
  EXPECT_NEAR(session.deploymentState().deployed, 6e-3, 1e-9);
}

TEST(RunObserver, XrayOnlySessionIgnoresAScripted3dView) {
  const Scene sc = makeScene();
  Session session(sc.model, sc.start);
  session.setView("biplane");
  session.setXrayOnly(true);
  auto log = std::make_shared<Log>();
  session.setObserver(log);
  session.setScript({{0.05, std::nullopt, "3d"}, {0.1, std::nullopt, "xray"}});
  session.stepMany(200);
  EXPECT_EQ(session.view(), "xray");
  // Every step in an X-ray view: the switch to 3D never happened.
  EXPECT_EQ(log->fluoroSteps, 200);
  ASSERT_EQ(log->views.size(), 2u);
  EXPECT_EQ(log->views[1], std::make_pair(0.1, std::string("xray")));
}

TEST(Views, XrayOnlyRefusesThe3dView) {
  Views views(render::ViewMode::Biplane);
  views.setXrayOnly(true);
  views.setMode(render::ViewMode::Shaded);
  EXPECT_EQ(views.mode(), render::ViewMode::Biplane);
  views.setMode(render::ViewMode::XRay);
  EXPECT_EQ(views.mode(), render::ViewMode::XRay);
  views.setXrayOnly(false);
  views.setMode(render::ViewMode::Shaded);
  EXPECT_EQ(views.mode(), render::ViewMode::Shaded);
}

}  // namespace
}  // namespace coilsim::ui
