#pragma once
// Live read-outs the caller computes from the model and state the window
// shows (planning: packing density, protrusion, wall force), drawn as one
// panel section, warnings highlighted. The ui layer knows nothing of what
// they mean: the app supplies the hook (coilsim practice).
#include <functional>
#include <string>
#include <vector>

#include "physics/model.h"
#include "physics/state.h"

namespace coilsim::ui {

struct Readout {
  std::string label, value;
  bool warning = false;  // drawn highlighted, with "!" in front
};

struct ReadoutHook {
  std::string title = "Read-outs";  // the panel section's header
  std::function<std::vector<Readout>(const Model&, const State&)> compute;
  explicit operator bool() const { return bool(compute); }
};

// Draws the section's lines (inside an open ImGui window).
void drawReadouts(const std::vector<Readout>& readouts);

}  // namespace coilsim::ui
