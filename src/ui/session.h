#pragma once
// What the viewer simulates and shows, independent of GL: its own copy of
// the Model (so that effect switches can change it), the initial State (for
// reset), the current State, the real-time loop, and the draw data of the
// last healthy state. A refused step (blow-up) pauses the simulation and is
// reported, never drawn. GL-free, tested in tests/ui.
#include <functional>
#include <string>

#include "physics/draw_data.h"
#include "physics/integrator.h"
#include "physics/model.h"
#include "physics/state.h"
#include "ui/realtime.h"

namespace coilsim::ui {

// Adds what the core does not fill (vessel meshes, markers) to draw data.
using DrawDataHook = std::function<void(const Model&, const State&, DrawData&)>;

class Session {
 public:
  Session(const Model& model, const State& state, DrawDataHook hook = {});

  Model& model() { return model_; }
  const Model& model() const { return model_; }
  const State& state() const { return state_; }
  const State& initialState() const { return initial_; }

  bool playing() const { return playing_; }
  void setPlaying(bool playing);
  // One step now (used when paused). Returns the step's report.
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

  // Why stepping stopped (a refused step), empty while healthy.
  const std::string& haltMessage() const { return haltMessage_; }
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

 private:
  bool stepAndCheck();

  Model model_;
  State initial_;
  State state_;
  DrawDataHook hook_;
  RealTimeLoop loop_;
  DrawData draw_;
  bool playing_ = false;
  bool stale_ = false;
  long steps_ = 0;
  double stopTime_ = -1;
  std::string haltMessage_;
};

}  // namespace coilsim::ui
