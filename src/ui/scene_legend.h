#pragma once
// A legend in the scene area's lower left corner: what each colour of the
// picture is (coil, catheter, sac wall, neck plane), drawn in the window and
// in off-screen pictures, with or without the panel. In the X-ray views,
// where everything is grey, an entry that names its matter shows the grey
// the renderer draws that matter in (render/xray_look.h).
#include <string>
#include <vector>

#include "physics/draw_data.h"
#include "render/xray_look.h"

namespace coilsim::ui {

class LayoutDump;

// What an entry is in an X-ray view. None keeps the entry's colour.
enum class LegendMatter { None, Coil, Catheter, Wire, Vessel, VesselOutline };

struct LegendEntry {
  Colour colour = Colour(1, 1, 1, 1);  // alpha 0: a line of text without a swatch
  std::string text;
  LegendMatter matter = LegendMatter::None;
};

// Draws the entries in a box at (left, bottom) of the scene area, ImGui
// window units. With `xray` (an X-ray view), entries that name a matter the
// scene holds get its grey; a vessel outline is the vessel's grey crossed by
// its outline's, each on a frame of the picture's background grey. Each
// swatch goes to `layout` as legend_swatch_<entry>, a grey's inside as
// legend_grey_<entry>.
void drawSceneLegend(const std::vector<LegendEntry>& entries, float left, float bottom,
                     const render::XRayGreys* xray = nullptr, LayoutDump* layout = nullptr);

}  // namespace coilsim::ui
