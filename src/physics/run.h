#pragma once
// One function advances a run: advance(model, state). Every front end (the
// window, headless runs and timelines, practice, planning's operator,
// validation's dynamic stages, the benches) calls it; it moves the device by
// the motions commanded (when the model has a device), then takes one
// physics step (physics/integrator.h). Commands are inputs: command() checks
// one against what the real device allows and sets it on the State, to act
// from the next advance().
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "physics/device.h"
#include "physics/failure.h"
#include "physics/integrator.h"
#include "physics/model.h"
#include "physics/state.h"

namespace coilsim {

// Starts the command on the run's device; returns nothing, or why it was
// refused (a DeviceRefusal; then nothing changes). A model without a device
// refuses every command.
std::optional<Failure> command(const Model& model, State& state, const DeviceCommand& c);

// Moves the device by model.timeStep (pushes, twists, retraction, a pending
// detach; limits reached are added to state.device.notes), then steps the
// physics. The report is the step's; a refused step leaves the device moved
// and the rods as they were.
StepReport advance(const Model& model, State& state);

// The two halves of advance(), for benchmarks that time the physics step
// alone: moveDevice(model, state) then step(model, state) is advance().
// moveDevice does nothing without a device.
void moveDevice(const Model& model, State& state);

// Runs a timeline: commands are applied at the first step whose start time
// (step index * dt) is at or after their time, so a replay is bit-for-bit.
// Stops after `duration` s. Refused commands ("t = 2.000000 s: refused: why")
// and the device's notes are reported in `log`; a refused step ends the run
// and is its `failure`.
// `keepGoing`, when given, is asked after each step (a front end's progress
// and Ctrl-C); false ends the run there with `stopped` set.
struct TimelineRun {
  std::vector<std::string> log;
  long steps = 0;
  std::optional<Failure> failure;  // the refused step that ended the run
  bool stopped = false;
  bool ok() const { return !failure; }
};
TimelineRun runTimeline(const Model& model, State& state, const std::vector<TimedCommand>& timeline, double duration,
                        const std::function<bool()>& keepGoing = {});

}  // namespace coilsim
