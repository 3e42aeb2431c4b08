#include "ui/help_overlay.h"

#include <imgui.h>

#include <algorithm>

#include "ui/layout_dump.h"

namespace coilsim::ui {
namespace {

constexpr HelpLine kRunWindow[] = {
    {"left drag (scene)", "orbit the camera (the C-arm in X-ray views)"},
    {"right or middle drag, Shift + left drag", "pan"},
    {"wheel, + / -", "zoom"},
    {"arrows, Shift + arrows", "orbit, pan"},
    {"F", "fit the scene into the view"},
    {"1  2  3", "3D, X-ray, biplane view"},
    {"Space", "play / pause the simulation"},
    {"N", "one step (paused)"},
    {"R", "reset the run to its start"},
    {"P / O held", "push / pull the coil at the panel's speed"},
    {"Q / E held", "twist left / right at the panel's rate"},
    {"Ctrl + wheel", "twist by the panel's step"},
    {"D", "detach: asks first (D or Enter confirms, Esc cancels); a refused detach says why at once"},
    {"F12", "screenshot (coilsim-N.png in the working directory)"},
    {"F1 or ?", "this help (Esc closes it)"},
    {"Esc", "close the confirmation, the help, then the window"},
    {"panel", "click a section header to open or close it; the wheel over the panel scrolls it"},
    {"gamepad", "triggers push / pull; right stick x twists, y zooms; left stick orbits (pans with LB); "
                "A play / pause, B reset, X fit, Y next view"},
};

constexpr HelpLine kValidateWindow[] = {
    {"left drag (scene)", "orbit the camera"},
    {"right or middle drag", "pan"},
    {"wheel", "zoom"},
    {"panel", "effect toggles, Fit and Stop; click a stage row to show that stage; the wheel scrolls the panel"},
    {"plots", "hover a point for its value"},
    {"F1 or ?", "this help (Esc closes it)"},
    {"Esc", "close the help, then the window (a running fit is stopped)"},
};

}  // namespace

std::span<const HelpLine> runWindowHelp() { return kRunWindow; }
std::span<const HelpLine> validateWindowHelp() { return kValidateWindow; }

void drawHelpOverlay(const char* title, std::span<const HelpLine> lines, float left, float right, float height,
                     LayoutDump* layout) {
  const float width = std::min(620.0f, std::max(200.0f, right - left - 40.0f));
  ImGui::SetNextWindowPos(ImVec2(0.5f * (left + right), 0.5f * height), ImGuiCond_Always, ImVec2(0.5f, 0.5f));
  ImGui::SetNextWindowSize(ImVec2(width, 0.0f), ImGuiCond_Always);
  ImGui::SetNextWindowBgAlpha(0.94f);
  ImGui::Begin(title, nullptr,
               ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse |
                   ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoSavedSettings);
  if (ImGui::BeginTable("keys", 2, ImGuiTableFlags_SizingStretchProp | ImGuiTableFlags_RowBg)) {
    ImGui::TableSetupColumn("press", ImGuiTableColumnFlags_WidthStretch, 0.38f);
    ImGui::TableSetupColumn("does", ImGuiTableColumnFlags_WidthStretch, 0.62f);
    for (const auto& [keys, what] : lines) {
      ImGui::TableNextRow();
      ImGui::TableNextColumn();
      ImGui::PushTextWrapPos(0.0f);
      ImGui::TextUnformatted(keys);
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(what);
      ImGui::PopTextWrapPos();
    }
    ImGui::EndTable();
  }
  if (layout) {
    const ImVec2 p = ImGui::GetWindowPos(), s = ImGui::GetWindowSize();
    layout->mark("help_overlay", p.x, p.y, p.x + s.x, p.y + s.y);
  }
  ImGui::End();
}

}  // namespace coilsim::ui
