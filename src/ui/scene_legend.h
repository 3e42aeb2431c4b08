#pragma once
// A legend in the scene area's lower left corner: what each colour of the
// picture is (coil, catheter, sac wall, neck plane), drawn in the window and
// in off-screen pictures, with or without the panel.
#include <string>
#include <vector>

#include "physics/draw_data.h"

namespace coilsim::ui {

struct LegendEntry {
  Colour colour = Colour(1, 1, 1, 1);  // alpha 0: a line of text without a swatch
  std::string text;
};

// Draws the entries in a box at (left, bottom) of the scene area, ImGui window units.
void drawSceneLegend(const std::vector<LegendEntry>& entries, float left, float bottom);

}  // namespace coilsim::ui
