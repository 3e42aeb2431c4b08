// The read-out section of the panel.
#include "ui/readouts.h"

#include <imgui.h>

namespace coilsim::ui {

void drawReadouts(const std::vector<Readout>& readouts) {
  // Wrapped: a warning cut at the panel's edge would lose its number.
  ImGui::PushTextWrapPos(0.0f);
  for (const Readout& r : readouts) {
    if (r.warning) {
      ImGui::TextColored(ImVec4(1.0f, 0.45f, 0.2f, 1.0f), "! %s: %s", r.label.c_str(), r.value.c_str());
    } else {
      ImGui::Text("  %s: %s", r.label.c_str(), r.value.c_str());
    }
  }
  ImGui::PopTextWrapPos();
}

}  // namespace coilsim::ui
