#pragma once
// What the viewer simulates and shows, independent of GL: its own copy of
// the Model (so that effect switches can change it), the initial State (for
// reset), the current State, the real-time loop, and the draw data of the
// last healthy state. A refused step (blow-up) pauses the simulation and is
// reported, never drawn. GL-free, tested in tests/ui.
#include <deque>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "physics/deployment.h"
#include "physics/draw_data.h"
#include "physics/integrator.h"
#include "physics/model.h"
#include "physics/run.h"
#include "physics/state.h"
#include "ui/contact_overlay.h"
#include "ui/realtime.h"

namespace coilsim::ui {

// Adds what the core does not fill (vessel meshes, markers) to draw data.
using DrawDataHook = std::function<void(const Model&, const State&, DrawData&)>;

// One scripted user input (tests under Xvfb drive the window with a list of
// them): a device command or a view switch ("3d", "xray", "biplane"), given
// at the first step starting at or after `time`, through the same path as
// the panel, keys and gamepad (Session::command, Session::setView).
struct ScriptedInput {
  double time = 0;  // s
  std::optional<DeviceCommand> command;
  std::string view;  // used when there is no command
};

// A session going on with another model (practice: the next coil through
// the same catheter, the detached ones kept in the sac as rods), built by
// the app: the model, the state to go on from, and the draw hook.
struct Continuation {
  Model model;
  State state;
  DrawDataHook draw;
};

// What the app does with the inputs and steps of a window run (practice:
// record every input and keep the score). The ui calls it; the app
// implements it with the layers the ui must not know. Defaults do nothing.
class RunObserver {
 public:
  virtual ~RunObserver() = default;
  // A device command the user gives: the one to start instead (a recorder
  // rounds it to the numbers its file will hold).
  virtual DeviceCommand adjust(const DeviceCommand& given) { return given; }
  // The controller accepted `applied` (given as `given`) at session time `t`
  // (steps x dt: it acts from the next step on).
  virtual void accepted(double /*t*/, const DeviceCommand& /*given*/, const DeviceCommand& /*applied*/) {}
  // The user looks through `view` from session time `t` on (also once when attached).
  virtual void viewChanged(double /*t*/, const std::string& /*view*/) {}
  // A refused command or a device limit reached (the device messages' line).
  virtual void noted(const std::string& /*message*/) {}
  // Around every advance (the device moves, then the physics steps); the
  // report is the step's (a refused step holds its Failure).
  virtual void beforeStep(const State&) {}
  virtual void afterStep(const Model&, const State&, const StepReport&) {}
  // After every step taken: a model to go on with from the next step (a
  // scripted session's next coil once the running one has detached), or
  // nothing. The session's clock, inputs and observer stay.
  virtual std::optional<Continuation> continuation(const Model&, const State&) { return std::nullopt; }
  // The session went back to its start (Reset); the inputs so far no longer count.
  virtual void restarted() {}
  // The window closes on this model and state (runWindow calls it).
  virtual void closed(const Model&, const State&) {}
};

class Session {
 public:
  Session(const Model& model, const State& state, DrawDataHook hook = {});

  Model& model() { return model_; }
  const Model& model() const { return model_; }
  const State& state() const { return state_; }
  const State& initialState() const { return initial_; }

  bool playing() const { return playing_; }
  void setPlaying(bool playing);
  // One step now (used when paused). Returns the step's report (refused:
  // its Failure, as haltReason() holds it).
  StepReport stepOnce();
  // `count` steps without refreshing the draw data (benchmarks; call
  // refreshDrawData after). Returns how many were refused.
  long stepMany(int count);
  // Back to the initial state; effect switches stay as they are.
  void reset();
  // Advances by `realDt` seconds of real time when playing (see RealTimeLoop).
  FrameAdvance advance(double realDt, const std::function<double()>& now);

  // Stop playing (pause) once simulated time reaches `seconds` (scripted
  // runs); negative: never.
  void setStopTime(double seconds) { stopTime_ = seconds; }
  bool reachedStopTime() const;

  // The model's device (push, pull, twist, detach, retract), if it has one.
  bool hasDeployment() const { return model_.device.has_value(); }
  const Deployment* deployment() const { return model_.device ? &*model_.device : nullptr; }
  const DeviceState& deploymentState() const { return state_.device; }
  // Device commands played exactly as runTimeline plays them headless (a
  // command starts at the first step whose start time, step index * dt, is
  // at or after its time). Call before the first step.
  void setTimeline(std::vector<TimedCommand> timeline);
  // Starts a device command now (it acts from the next step on). Returns
  // nothing, or why it is refused (a DeviceRefusal; then nothing changes);
  // refusals also go to the message list (describe()). Without a deployment
  // every command is refused.
  std::optional<Failure> command(const DeviceCommand& command);
  // Why the device would refuse `command` now (nothing if it would take
  // it), asked of physics' command() on a copy of the state, which is
  // dropped: nothing changes and nothing is noted (a confirmation asks only
  // when the answer could be yes).
  std::optional<Failure> wouldRefuse(const DeviceCommand& command) const;
  // Notes a refusal found by wouldRefuse in the message list (and tells the
  // observer), as command() notes its own.
  void noteRefusal(const Failure& refusal) { note(describe(refusal)); }
  // Refusals and limits reached ("the coil is fully deployed"), newest last,
  // each with the simulated time; at most the last 8.
  const std::deque<std::string>& deviceMessages() const { return deviceMessages_; }
  // Timeline commands already started.
  size_t timelineCursor() const { return timelineNext_; }
  size_t timelineSize() const { return timeline_.size(); }

  // Replaces the model, state and draw hook (a coil or catheter chosen in
  // the panel): the session starts again from `state`, paused, with no
  // timeline. The observer and the view stay.
  void replace(const Model& model, const State& state, DrawDataHook hook);

  // Goes on with another model and state (Continuation) between two steps:
  // the session time, timeline, script, messages, observer, view and
  // playing stay; reset() still goes back to the session's start.
  void carryOn(Continuation next);

  // Who records the inputs and steps (may be null). It is told the current view at once.
  void setObserver(std::shared_ptr<RunObserver> observer);
  RunObserver* observer() const { return observer_.get(); }
  // The view the user looks through ("3d", "xray", "biplane"); a change is
  // passed to the observer with the session time.
  void setView(const std::string& view);
  const std::string& view() const { return view_; }
  // X-ray views only (practice as in the procedure): a switch to "3d" is ignored.
  void setXrayOnly(bool on) { xrayOnly_ = on; }
  // Scripted inputs, given in order at their times (restart with reset()).
  void setScript(std::vector<ScriptedInput> script);
  bool scriptDone() const { return scriptNext_ >= script_.size(); }
  // Session time: steps since the start (or reset) x dt, the clock of timelines and recordings.
  double deviceTime() const { return double(deviceSteps_) * model_.timeStep; }

  // Why stepping stopped (the refused step's Failure), nothing while healthy;
  // haltMessage() is its describe() line, empty while healthy.
  const std::optional<Failure>& haltReason() const { return halt_; }
  std::string haltMessage() const { return halt_ ? describe(*halt_) : std::string(); }
  const RealTimeLoop& loop() const { return loop_; }
  RealTimeLoop& loop() { return loop_; }
  long stepsTaken() const { return steps_; }

  // Draw data of the last state that passed checkHealth; refreshed by
  // advance/stepOnce/reset.
  const DrawData& drawData() const { return draw_; }
  // True when the current state failed the health check and an older
  // picture is shown.
  bool showingOlderState() const { return stale_; }
  void refreshDrawData();

  // Colours the rods by bending moment (node_colours.h): `scale` N m is
  // fully red, <= 0 the largest. Off: the role colours (or the hook's).
  void setMomentColouring(bool on, double scale);
  bool momentColouring() const { return colourByMoment_; }
  // The largest bending moment in the picture when colouring by it, N m.
  double largestMoment() const { return largestMoment_; }
  // Contacts at the last step (markers are in the draw data's points).
  const ContactSummary& contacts() const { return contacts_; }

 private:
  bool stepAndCheck();
  void giveInputs();
  void restartDevice();
  void note(const std::string& message);

  Model model_;
  State initial_;
  State state_;
  DrawDataHook hook_;
  // The session's first model and hook, while another carries it on (reset goes back to them).
  std::optional<Continuation> start_;
  RealTimeLoop loop_;
  DrawData draw_;
  bool playing_ = false;
  bool stale_ = false;
  long steps_ = 0;
  double stopTime_ = -1;
  std::optional<Failure> halt_;
  std::vector<TimedCommand> timeline_;
  size_t timelineNext_ = 0;
  long deviceSteps_ = 0;  // steps since the start, the timeline's clock
  std::deque<std::string> deviceMessages_;
  std::shared_ptr<RunObserver> observer_;
  std::string view_ = "3d";
  bool xrayOnly_ = false;
  std::vector<ScriptedInput> script_;
  size_t scriptNext_ = 0;
  bool colourByMoment_ = false;
  double momentScale_ = 0;
  double largestMoment_ = 0;
  ContactSummary contacts_;
};

}  // namespace coilsim::ui
