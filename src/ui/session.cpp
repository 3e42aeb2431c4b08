#include "ui/session.h"

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
    haltMessage_.clear();
  }
  playing_ = playing;
}

bool Session::stepAndCheck() {
  const StepReport r = step(model_, state_);
  if (!r.ok()) {
    // step() restored the state; stepping again would fail the same way.
    haltMessage_ = "step refused at t = " + std::to_string(state_.time) + " s: " + r.message;
    playing_ = false;
    return false;
  }
  ++steps_;
  return true;
}

StepReport Session::stepOnce() {
  const long before = steps_;
  stepAndCheck();
  refreshDrawData();
  StepReport r;
  if (steps_ == before) {
    r.status = StepStatus::BlowUp;
    r.message = haltMessage_;
  }
  return r;
}

long Session::stepMany(int count) {
  long refused = 0;
  for (int i = 0; i < count; ++i)
    if (!stepAndCheck()) ++refused;
  return refused;
}

void Session::reset() {
  state_ = initial_;
  haltMessage_.clear();
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
  if (!checkHealth(model_, state_).empty()) {
    stale_ = true;
    return;
  }
  stale_ = false;
  draw_.meshes.clear();
  draw_.points.clear();
  fillDrawData(model_, state_, draw_);
  if (hook_) hook_(model_, state_, draw_);
}

}  // namespace coilsim::ui
