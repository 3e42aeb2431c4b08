#include "ui/scene_legend.h"

#include <imgui.h>

#include <algorithm>
#include <string>

#include "ui/layout_dump.h"

namespace coilsim::ui {
namespace {

ImU32 grey(float g) { return ImGui::ColorConvertFloat4ToU32(ImVec4(g, g, g, 1.0f)); }

// The grey of an entry's matter in this X-ray view; < 0 when it has none.
float xrayGrey(LegendMatter m, const render::XRayGreys& x) {
  switch (m) {
    case LegendMatter::Coil: return x.coil;
    case LegendMatter::Catheter: return x.catheter;
    case LegendMatter::Wire: return x.wire;
    case LegendMatter::Vessel:
    case LegendMatter::VesselOutline: return x.vessel;
    case LegendMatter::None: break;
  }
  return -1;
}

}  // namespace

void drawSceneLegend(const std::vector<LegendEntry>& entries, float left, float bottom,
                     const render::XRayGreys* xray, LayoutDump* layout) {
  if (entries.empty()) return;
  ImDrawList* d = ImGui::GetForegroundDrawList();
  const float line = ImGui::GetTextLineHeight() + 2, swatch = ImGui::GetTextLineHeight() - 2, pad = 6;
  float width = 0;
  for (const LegendEntry& e : entries) width = std::max(width, ImGui::CalcTextSize(e.text.c_str()).x);
  width += swatch + 3 * pad;
  const float height = line * float(entries.size()) + 2 * pad;
  const ImVec2 a(left + 10, bottom - 10 - height), b(a.x + width, bottom - 10);
  d->AddRectFilled(a, b, IM_COL32(20, 22, 28, 200), 4.0f);
  float y = a.y + pad;
  for (size_t i = 0; i < entries.size(); ++i) {
    const LegendEntry& e = entries[i];
    const float x = a.x + pad;
    const ImVec2 s0(x, y + 2), s1(x + swatch, y + 2 + swatch);
    const float g = xray ? xrayGrey(e.matter, *xray) : -1.0f;
    if (g >= 0) {
      // The grey on a frame of the picture's background: a coil's near
      // black would vanish on the legend's dark box, and the picture shows
      // it against that background.
      const ImVec2 i0(s0.x + 2, s0.y + 2), i1(s1.x - 2, s1.y - 2);
      d->AddRectFilled(s0, s1, grey(xray->background));
      d->AddRectFilled(i0, i1, grey(g));
      if (e.matter == LegendMatter::VesselOutline && xray->vesselEdge >= 0)
        d->AddRectFilled(ImVec2(i0.x, 0.5f * (i0.y + i1.y) - 1), ImVec2(i1.x, 0.5f * (i0.y + i1.y) + 1),
                         grey(xray->vesselEdge));
      if (layout) layout->mark(("legend_grey_" + std::to_string(i)).c_str(), i0.x, i0.y, i1.x, i1.y);
    } else if (e.colour.w() > 0 && !(xray && e.matter != LegendMatter::None)) {
      // The swatch opaque: a translucent wall's colour alone is hard to read.
      const ImU32 c = ImGui::ColorConvertFloat4ToU32(ImVec4(e.colour.x(), e.colour.y(), e.colour.z(), 1.0f));
      d->AddRectFilled(s0, s1, c, 2.0f);
    }
    if (layout) layout->mark(("legend_swatch_" + std::to_string(i)).c_str(), s0.x, s0.y, s1.x, s1.y);
    d->AddText(ImVec2(x + swatch + pad, y), IM_COL32(235, 235, 235, 255), e.text.c_str());
    y += line;
  }
}

}  // namespace coilsim::ui
