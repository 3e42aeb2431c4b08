#pragma once
// The help overlay (F1 or ?): every key and mouse action of the window in
// use, drawn over the scene area, closed by F1, ? or Esc.
#include <span>
#include <utility>

namespace coilsim::ui {

class LayoutDump;

// One line of the overlay: what to press, what it does.
using HelpLine = std::pair<const char*, const char*>;

// The simulation window's keys (run and practice).
std::span<const HelpLine> runWindowHelp();
// The validation workbench's keys.
std::span<const HelpLine> validateWindowHelp();

// Draws the overlay centred in the scene area [left, right] x [0, height]
// (ImGui window units); marks its rectangle as "help_overlay" in `layout`.
void drawHelpOverlay(const char* title, std::span<const HelpLine> lines, float left, float right, float height,
                     LayoutDump* layout);

}  // namespace coilsim::ui
