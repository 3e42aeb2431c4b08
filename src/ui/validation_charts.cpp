#include "ui/validation_charts.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace coilsim::ui {
namespace {

const ImU32 kAxis = IM_COL32(200, 200, 200, 255);
const ImU32 kGrid = IM_COL32(90, 90, 90, 120);
const ImU32 kCurve = IM_COL32(255, 190, 80, 255);
const ImU32 kLevel = IM_COL32(150, 200, 255, 200);

std::string tickText(float v, float step) {
  char t[32];
  const int decimals = step >= 1 ? 0 : std::min(6, int(std::ceil(-std::log10(step) - 1e-6)));
  std::snprintf(t, sizeof t, "%.*f", decimals, std::abs(v) < 1e-6f * step ? 0.0 : double(v));
  return t;
}

}  // namespace

float niceTickStep(float range, int n) {
  const double raw = std::max(double(range), 1e-12) / std::max(1, n);
  const double p = std::pow(10.0, std::floor(std::log10(raw)));
  for (double m : {1.0, 2.0, 5.0, 10.0})
    if (m * p >= raw * (1 - 1e-9)) return float(m * p);
  return float(10 * p);
}

void drawLineChart(const char* id, const std::vector<float>& x, const std::vector<float>& y, const ChartAxes& a,
                   const std::string& title, float level, float height) {
  ImGui::PushID(id);
  const float line = ImGui::GetTextLineHeight();
  const ImVec2 origin = ImGui::GetCursorScreenPos();
  const float width = ImGui::GetContentRegionAvail().x;
  // Room for the y tick values at the left and the x tick values and label below.
  const float left = origin.x + ImGui::CalcTextSize("0.0000").x + 8, right = origin.x + width - 6;
  const float top = origin.y + 2, bottom = origin.y + height - 2 * line - 4;
  ImGui::InvisibleButton("##chart", ImVec2(width, height));
  const bool hovered = ImGui::IsItemHovered();
  ImDrawList* d = ImGui::GetWindowDrawList();
  const float xr = a.xMax > a.xMin ? a.xMax - a.xMin : 1, yr = a.yMax > a.yMin ? a.yMax - a.yMin : 1;
  auto px = [&](float v) { return left + (v - a.xMin) / xr * (right - left); };
  auto py = [&](float v) { return bottom - (v - a.yMin) / yr * (bottom - top); };
  float sx = niceTickStep(xr, std::max(2, int((right - left) / 70)));
  if (a.integerX) sx = std::max(sx, 1.0f);
  const float sy = niceTickStep(yr, 3);
  for (float v = std::ceil(a.xMin / sx) * sx; v <= a.xMax + 1e-4f * sx; v += sx) {
    d->AddLine(ImVec2(px(v), top), ImVec2(px(v), bottom), kGrid);
    d->AddLine(ImVec2(px(v), bottom), ImVec2(px(v), bottom + 4), kAxis);
    const std::string t = tickText(v, sx);
    d->AddText(ImVec2(px(v) - 0.5f * ImGui::CalcTextSize(t.c_str()).x, bottom + 4), kAxis, t.c_str());
  }
  for (float v = std::ceil(a.yMin / sy) * sy; v <= a.yMax + 1e-4f * sy; v += sy) {
    d->AddLine(ImVec2(left, py(v)), ImVec2(right, py(v)), kGrid);
    d->AddLine(ImVec2(left - 4, py(v)), ImVec2(left, py(v)), kAxis);
    const std::string t = tickText(v, sy);
    d->AddText(ImVec2(left - 6 - ImGui::CalcTextSize(t.c_str()).x, py(v) - 0.5f * line), kAxis, t.c_str());
  }
  d->AddRect(ImVec2(left, top), ImVec2(right, bottom), kAxis);
  if (level > 0 && level <= a.yMax)
    for (float v = left; v < right; v += 10) d->AddLine(ImVec2(v, py(level)), ImVec2(std::min(v + 6, right), py(level)), kLevel);
  d->PushClipRect(ImVec2(left, top), ImVec2(right, bottom), true);
  for (size_t i = 1; i < std::min(x.size(), y.size()); ++i)
    d->AddLine(ImVec2(px(x[i - 1]), py(y[i - 1])), ImVec2(px(x[i]), py(y[i])), kCurve, 1.5f);
  d->PopClipRect();
  d->AddText(ImVec2(left + 4, top + 1), IM_COL32(255, 255, 255, 230), title.c_str());
  const float xl = ImGui::CalcTextSize(a.xLabel.c_str()).x;
  d->AddText(ImVec2(0.5f * (left + right - xl), bottom + line + 4), kAxis, a.xLabel.c_str());
  // The y axis's label goes in the tooltip and the title's unit: ImGui draws no rotated text.
  if (hovered && !x.empty()) {
    const float mx = a.xMin + (ImGui::GetIO().MousePos.x - left) / (right - left) * xr;
    size_t k = 0;
    for (size_t i = 1; i < x.size(); ++i)
      if (std::abs(x[i] - mx) < std::abs(x[k] - mx)) k = i;
    if (k < y.size())
      ImGui::SetTooltip("%s %.4g\n%s %.4g", a.xLabel.c_str(), double(x[k]), a.yLabel.c_str(), double(y[k]));
  }
  ImGui::PopID();
}

void drawErrorColourScale(const ErrorColourScale& s) {
  if (s.colours.empty()) return;
  ImGui::TextWrapped("%s", s.legend.c_str());
  const ImVec2 o = ImGui::GetCursorScreenPos();
  const float width = ImGui::GetContentRegionAvail().x - 20, barH = 12, line = ImGui::GetTextLineHeight();
  ImGui::Dummy(ImVec2(width, barH + line + 4));
  ImDrawList* d = ImGui::GetWindowDrawList();
  const size_t n = s.colours.size();
  for (size_t i = 0; i < n; ++i) {
    const Colour& c = s.colours[i];
    const float x0 = o.x + width * float(i) / float(n), x1 = o.x + width * float(i + 1) / float(n);
    d->AddRectFilled(ImVec2(x0, o.y), ImVec2(x1 + 0.5f, o.y + barH), ImGui::ColorConvertFloat4ToU32(ImVec4(c.x(), c.y(), c.z(), 1)));
  }
  for (const auto& [pos, label] : s.ticks) {
    const float x = o.x + width * std::clamp(pos, 0.0f, 1.0f);
    d->AddLine(ImVec2(x, o.y + barH), ImVec2(x, o.y + barH + 3), kAxis);
    const float w = ImGui::CalcTextSize(label.c_str()).x;
    d->AddText(ImVec2(std::clamp(x - 0.5f * w, o.x, o.x + width + 20 - w), o.y + barH + 3), kAxis, label.c_str());
  }
}

}  // namespace coilsim::ui
