// ---------------------------------------------------------------------------
// Deployment controls: push / pull (speed slider, hold-to-push key), twist,
// detach (with confirmation), retract catheter. They belong to the
// deployment issue; this file is where they go, so that adding them touches
// neither the panel layout nor the window loop.
// ---------------------------------------------------------------------------
#include <imgui.h>

#include "ui/panel.h"

namespace coilsim::ui {

void drawDeploymentControls(Session&) {
  ImGui::PushTextWrapPos(0.0f);
  ImGui::TextDisabled("Push, pull, twist, detach and catheter retraction arrive with the deployment issue.");
  ImGui::PopTextWrapPos();
  ImGui::BeginDisabled();
  ImGui::Button("Push");
  ImGui::SameLine();
  ImGui::Button("Pull");
  ImGui::SameLine();
  ImGui::Button("Twist");
  ImGui::SameLine();
  ImGui::Button("Detach...");
  ImGui::EndDisabled();
}

}  // namespace coilsim::ui
