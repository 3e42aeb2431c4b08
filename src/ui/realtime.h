#pragma once
// The real-time loop's clock: physics at a fixed time step with an
// accumulator, decoupled from the frame rate. When stepping cannot keep up
// within a per-frame budget of wall time, the unsimulated time is dropped
// (simulated time slows down and behind() says so) instead of piling up,
// so the window never freezes. GL-free, tested in tests/ui.
#include <functional>

namespace coilsim::ui {

// Seconds of wall time since the first call (steady clock): the frame loops' clock.
double wallSeconds();

struct RealTimeConfig {
  double timeStep = 1e-3;       // s, model.timeStep
  double timeScale = 1.0;       // simulated seconds per real second wanted
  double frameBudget = 0.030;   // s of wall time for physics per frame
  double maxFrameTime = 0.1;    // s: longer frame gaps (window dragged, debugger) count as this
};

struct FrameAdvance {
  int steps = 0;            // steps taken this frame
  bool droppedTime = false; // the budget ran out: simulated time fell behind real time
  bool refused = false;     // the step function refused a step (or asked to stop)
};

class RealTimeLoop {
 public:
  explicit RealTimeLoop(const RealTimeConfig& config = {});

  // Takes as many fixed steps as `realDt` seconds of real time ask for.
  // `step` returns false when a step is refused (the loop then stops for
  // this frame and drops the accumulated time); `now` is a wall clock in
  // seconds, used for the budget (injected so that tests control it).
  FrameAdvance advance(double realDt, const std::function<bool()>& step, const std::function<double()>& now);

  // Forgets accumulated time and the statistics (after a reset or a pause).
  void reset();

  // Simulated seconds per real second, averaged over about half a second (1 when
  // keeping up with timeScale 1; below 1 when physics is behind).
  double realTimeFactor() const { return factor_; }
  // True while time has been dropped within the last half second.
  bool behind() const { return sinceDrop_ < 0.5; }
  const RealTimeConfig& config() const { return config_; }
  void setTimeScale(double scale) { config_.timeScale = scale; }

 private:
  RealTimeConfig config_;
  double accumulator_ = 0;
  double factor_ = 1;
  double sinceDrop_ = 1e9;
};

}  // namespace coilsim::ui
