#include "ui/scene_legend.h"

#include <imgui.h>

#include <algorithm>

namespace coilsim::ui {

void drawSceneLegend(const std::vector<LegendEntry>& entries, float left, float bottom) {
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
  for (const LegendEntry& e : entries) {
    const float x = a.x + pad;
    if (e.colour.w() > 0) {
      // The swatch opaque: a translucent wall's colour alone is hard to read.
      const ImU32 c = ImGui::ColorConvertFloat4ToU32(ImVec4(e.colour.x(), e.colour.y(), e.colour.z(), 1.0f));
      d->AddRectFilled(ImVec2(x, y + 2), ImVec2(x + swatch, y + 2 + swatch), c, 2.0f);
    }
    d->AddText(ImVec2(x + swatch + pad, y), IM_COL32(235, 235, 235, 255), e.text.c_str());
    y += line;
  }
}

}  // namespace coilsim::ui
