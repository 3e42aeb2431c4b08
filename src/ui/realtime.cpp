#include "ui/realtime.h"

#include <algorithm>
#include <chrono>

namespace coilsim::ui {

double wallSeconds() {
  using clock = std::chrono::steady_clock;
  static const clock::time_point start = clock::now();
  return std::chrono::duration<double>(clock::now() - start).count();
}

RealTimeLoop::RealTimeLoop(const RealTimeConfig& config) : config_(config) {}

void RealTimeLoop::reset() {
  accumulator_ = 0;
  factor_ = 1;
  sinceDrop_ = 1e9;
}

FrameAdvance RealTimeLoop::advance(double realDt, const std::function<bool()>& step,
                                   const std::function<double()>& now) {
  FrameAdvance f;
  const double h = config_.timeStep;
  if (!(h > 0)) return f;
  realDt = std::clamp(realDt, 0.0, config_.maxFrameTime);
  accumulator_ += realDt * config_.timeScale;
  const double start = now();
  // At least one step per frame whenever one is due, so that simulated time
  // always moves on; further steps only while the budget lasts.
  // The tolerance keeps round-off in the accumulator from losing a step.
  while (accumulator_ >= h * (1.0 - 1e-9)) {
    if (f.steps > 0 && now() - start > config_.frameBudget) {
      f.droppedTime = true;
      accumulator_ = 0;
      break;
    }
    if (!step()) {
      f.refused = true;
      accumulator_ = 0;
      break;
    }
    accumulator_ = std::max(accumulator_ - h, 0.0);
    ++f.steps;
  }
  sinceDrop_ = f.droppedTime ? 0.0 : sinceDrop_ + realDt;
  // Exponential average over about half a second of real time.
  if (realDt > 0) factor_ += (f.steps * h / realDt - factor_) * std::min(1.0, realDt / 0.5);
  return f;
}

}  // namespace coilsim::ui
