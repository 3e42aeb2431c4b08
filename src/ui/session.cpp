#include "ui/session.h"

#include <cstdio>

#include "ui/node_colours.h"

namespace coilsim::ui {

Session::Session(const Model& model, const State& state, DrawDataHook hook)
    : model_(model), initial_(state), state_(state), hook_(std::move(hook)) {
  RealTimeConfig c;
  c.timeStep = model.timeStep;
  loop_ = RealTimeLoop(c);
  refreshDrawData();
}

void Session::setPlaying(bool playing) {
  if (playing && !playing_) {
    loop_.reset();
    halt_.reset();
  }
  playing_ = playing;
}

void Session::setTimeline(std::vector<TimedCommand> timeline) {
  timeline_ = std::move(timeline);
  restartDevice();
}

void Session::restartDevice() {
  timelineNext_ = 0;
  scriptNext_ = 0;
  deviceSteps_ = 0;
  deviceMessages_.clear();
}

void Session::carryOn(Continuation next) {
  if (!start_) start_ = Continuation{std::move(model_), initial_, hook_};
  model_ = std::move(next.model);
  state_ = std::move(next.state);
  hook_ = std::move(next.draw);
  // A refused step of the model before is no reason to stop this one.
  halt_.reset();
  refreshDrawData();
}

void Session::replace(const Model& model, const State& state, DrawDataHook hook) {
  start_.reset();
  model_ = model;
  initial_ = state;
  state_ = state;
  hook_ = std::move(hook);
  timeline_.clear();
  timelineNext_ = scriptNext_ = 0;
  deviceSteps_ = 0;
  deviceMessages_.clear();
  RealTimeConfig c = loop_.config();
  c.timeStep = model.timeStep;
  loop_ = RealTimeLoop(c);
  playing_ = false;
  steps_ = 0;
  halt_.reset();
  refreshDrawData();
}

void Session::setObserver(std::shared_ptr<RunObserver> observer) {
  observer_ = std::move(observer);
  if (observer_) observer_->viewChanged(deviceTime(), view_);
}

void Session::setView(const std::string& view) {
  if (view == view_ || (xrayOnly_ && view == "3d")) return;
  view_ = view;
  if (observer_) observer_->viewChanged(deviceTime(), view_);
}

void Session::setScript(std::vector<ScriptedInput> script) {
  script_ = std::move(script);
  scriptNext_ = 0;
}

void Session::note(const std::string& message) {
  char t[48];
  std::snprintf(t, sizeof t, "t = %.3f s: ", state_.time);
  deviceMessages_.push_back(t + message);
  while (deviceMessages_.size() > 8) deviceMessages_.pop_front();
  if (observer_) observer_->noted(message);
}

namespace {

// What a window says for a scene without a device (physics' own refusal
// speaks of a run; the window's user chose a scene).
Failure noDeployment() {
  Failure f;
  f.kind = FailureKind::DeviceRefusal;
  f.text = "this scene has no deployment (no coil in a catheter to drive)";
  return f;
}

}  // namespace

std::optional<Failure> Session::command(const DeviceCommand& c) {
  if (!model_.device) {
    const Failure refused = noDeployment();
    note(describe(refused));
    return refused;
  }
  // The observer (a recorder) may round the command to what its file holds.
  const DeviceCommand applied = observer_ ? observer_->adjust(c) : c;
  std::optional<Failure> refused = coilsim::command(model_, state_, applied);
  if (refused) note(describe(*refused));
  else if (observer_) observer_->accepted(deviceTime(), c, applied);
  return refused;
}

std::optional<Failure> Session::wouldRefuse(const DeviceCommand& c) const {
  if (!model_.device) return noDeployment();
  State scratch = state_;
  return coilsim::command(model_, scratch, observer_ ? observer_->adjust(c) : c);
}

// What runTimeline does before each step, in the same order, so that a
// window run and a headless run of one timeline reach the same state.
void Session::giveInputs() {
  if (!model_.device) return;
  const std::vector<TimedCommand>& timeline = timeline_;
  const double dt = model_.timeStep;
  const double t = double(deviceSteps_) * dt;
  // Scripted user inputs, as if typed at their time (the same rule as timelines).
  while (scriptNext_ < script_.size() && script_[scriptNext_].time <= t + 1e-9 * dt) {
    const ScriptedInput& in = script_[scriptNext_++];
    if (in.command) command(*in.command);
    else setView(in.view);
  }
  while (timelineNext_ < timeline.size() && timeline[timelineNext_].time <= t + 1e-9 * dt) {
    if (const std::optional<Failure> refused = coilsim::command(model_, state_, timeline[timelineNext_].command))
      note("timeline /commands/" + std::to_string(timelineNext_) + ": " + describe(*refused));
    ++timelineNext_;
  }
}

bool Session::stepAndCheck() {
  // A refused step restores the poses but not the slid coil, exactly as in
  // runTimeline, which stops there too.
  giveInputs();
  if (observer_) observer_->beforeStep(state_);
  ++deviceSteps_;
  const StepReport r = coilsim::advance(model_, state_);
  for (const std::string& n : state_.device.notes) note(n);
  state_.device.notes.clear();
  if (observer_) observer_->afterStep(model_, state_, r);
  if (!r.ok()) {
    // step() restored the state; stepping again would fail the same way.
    halt_ = r.failure;
    playing_ = false;
    return false;
  }
  ++steps_;
  if (observer_)
    if (std::optional<Continuation> next = observer_->continuation(model_, state_)) carryOn(std::move(*next));
  return true;
}

StepReport Session::stepOnce() {
  const long before = steps_;
  stepAndCheck();
  refreshDrawData();
  StepReport r;
  if (steps_ == before) r.failure = halt_;
  return r;
}

long Session::stepMany(int count) {
  long refused = 0;
  for (int i = 0; i < count; ++i)
    if (!stepAndCheck()) ++refused;
  return refused;
}

void Session::reset() {
  if (start_) {
    model_ = std::move(start_->model);
    initial_ = std::move(start_->state);
    hook_ = std::move(start_->draw);
    start_.reset();
  }
  state_ = initial_;
  restartDevice();
  if (observer_) {
    observer_->restarted();
    observer_->viewChanged(0.0, view_);
  }
  halt_.reset();
  loop_.reset();
  steps_ = 0;
  refreshDrawData();
}

bool Session::reachedStopTime() const {
  return stopTime_ >= 0 && state_.time >= stopTime_ - 0.5 * model_.timeStep;
}

FrameAdvance Session::advance(double realDt, const std::function<double()>& now) {
  if (!playing_) return {};
  const FrameAdvance f = loop_.advance(realDt, [this] {
    if (reachedStopTime()) {
      playing_ = false;
      return false;  // ends the frame exactly at the stop time
    }
    return stepAndCheck();
  }, now);
  if (f.steps > 0 || f.refused) refreshDrawData();
  return f;
}

void Session::refreshDrawData() {
  // A state that fails the health check keeps the previous picture.
  if (checkHealth(model_, state_)) {
    stale_ = true;
    return;
  }
  stale_ = false;
  draw_.meshes.clear();
  draw_.points.clear();
  fillDrawData(model_, state_, draw_);
  if (hook_) hook_(model_, state_, draw_);
  // Arrows up to 3 mm: a coil loop is a few millimetres across.
  contacts_ = addContactMarkers(model_, state_, 3e-3, draw_);
  largestMoment_ = colourByMoment_ ? colourByBendingMoment(state_, momentScale_, draw_) : 0.0;
}

void Session::setMomentColouring(bool on, double scale) {
  if (on == colourByMoment_ && scale == momentScale_) return;
  colourByMoment_ = on;
  momentScale_ = scale;
  refreshDrawData();
}

}  // namespace coilsim::ui
