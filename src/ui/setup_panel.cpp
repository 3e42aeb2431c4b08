// Coil and catheter choice: the panel's combos, and loading what the app builds.
#include <imgui.h>

#include <exception>
#include <string>

#include "physics/rod_quantities.h"
#include "ui/panel.h"
#include "ui/setup.h"

namespace coilsim::ui {
namespace {

const ImVec4 kFailed(1.0f, 0.45f, 0.35f, 1.0f);
const ImVec4 kLoaded(0.5f, 0.9f, 0.5f, 1.0f);

// A combo over `items`; returns the index picked this frame, or -1.
int combo(const char* id, const std::vector<std::string>& items, int current, const char* none) {
  int picked = -1;
  const char* preview = current >= 0 && current < int(items.size()) ? items[size_t(current)].c_str() : none;
  ImGui::SetNextItemWidth(-1.0f);
  if (ImGui::BeginCombo(id, preview)) {
    for (int i = 0; i < int(items.size()); ++i) {
      const bool selected = i == current;
      if (ImGui::Selectable(items[size_t(i)].c_str(), selected) && !selected) picked = i;
      if (selected) ImGui::SetItemDefaultFocus();
    }
    ImGui::EndCombo();
  } else if (ImGui::IsItemHovered()) {
    ImGui::SetTooltip("%s", preview);  // the panel is narrower than a coil's label
  }
  return picked;
}

void note(const std::string& text) {
  if (text.empty()) return;
  ImGui::PushTextWrapPos(0.0f);
  ImGui::TextDisabled("%s", text.c_str());
  ImGui::PopTextWrapPos();
}

// The rod quantities a coil's label gives, as their declarations
// (physics/rod_quantities.h) name, measure and explain them.
std::string coilQuantities() {
  std::string out;
  for (const rodq::Quantity* q : {&rodq::kLoopDiameter, &rodq::kLength}) {
    if (!out.empty()) out += "\n";
    out += std::string(q->spec.name) + " (" + std::string(q->spec.unit) + "): " + std::string(q->spec.description);
  }
  return out;
}

}  // namespace

bool followsNow(const SetupChoices& choices, const Session& session) {
  return choices.follow && session.hasDeployment() && session.deploymentState().detached;
}

bool applySetup(SetupChoices& choices, int coil, int catheter, Session& session, PanelContext& panel) {
  // After a detach a coil goes in after the others; before, it starts the session again.
  const bool follow = followsNow(choices, session) && catheter == choices.catheter;
  SceneSetup setup;
  try {
    setup = follow ? choices.follow(coil, session.model(), session.state()) : choices.build(coil, catheter);
  } catch (const std::exception& e) {
    // The running setup stays; the panel says why the choice did not load.
    panel.setupStatus = {e.what(), true};
    return false;
  }
  if (follow) {
    session.carryOn({std::move(setup.model), std::move(setup.state), std::move(setup.draw)});
  } else {
    session.replace(setup.model, setup.state, setup.draw);
    session.setObserver(setup.observer);
    panel.readouts = setup.readouts;
  }
  panel.device.confirmDetach = false;
  choices.coil = coil;
  choices.catheter = catheter;
  panel.setupStatus = {setup.loaded, false};
  return true;
}

void drawSetupSection(const SetupChoices& choices, const Session& session, PanelContext& ctx) {
  const bool follow = followsNow(choices, session);
  ImGui::TextDisabled(follow ? "next coil (shape, loop, length, stiffness)" : "coil (shape, loop, length, stiffness)");
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", coilQuantities().c_str());
  const int coil = combo("##coil", choices.coils, follow ? -1 : choices.coil, "choose the next coil");
  note(follow ? choices.followNote : choices.coilNote);
  ImGui::TextDisabled("catheter tip");
  ImGui::BeginDisabled(choices.catheterFixed);
  const int catheter = combo("##catheter", choices.catheters, choices.catheter, "the scene's catheter");
  ImGui::EndDisabled();
  note(choices.catheterNote);
  // Loaded after the frame (the session is being drawn now).
  if (coil >= 0 || catheter >= 0) {
    ctx.setupRequested = true;
    ctx.setupCoil = coil >= 0 ? coil : choices.coil;
    ctx.setupCatheter = catheter >= 0 ? catheter : choices.catheter;
  }
  if (!ctx.setupStatus.message.empty()) {
    ImGui::PushTextWrapPos(0.0f);
    ImGui::TextColored(ctx.setupStatus.failed ? kFailed : kLoaded, "%s%s", ctx.setupStatus.failed ? "not loaded: " : "",
                       ctx.setupStatus.message.c_str());
    ImGui::PopTextWrapPos();
  }
}

}  // namespace coilsim::ui
