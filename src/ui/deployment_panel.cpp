// ---------------------------------------------------------------------------
// Deployment controls: push / pull at a speed (also P / O held), twist (Q / E
// held, Ctrl + wheel), detach with a confirmation, catheter retraction, stop,
// reset; the controller's refusals and the limits reached, and the read-outs
// (deployed length, twist, catheter position). Every command goes through
// Session::command, the same controller API that timelines use.
// ---------------------------------------------------------------------------
#include <imgui.h>

#include <cmath>
#include <cstdio>

#include "io/units.h"
#include "ui/panel.h"

namespace coilsim::ui {
namespace {

const ImVec4 kRefused(1.0f, 0.45f, 0.35f, 1.0f);

DeviceCommand make(DeviceCommand::Kind kind, double rate, double amount = 0) {
  DeviceCommand c;
  c.kind = kind;
  c.rate = rate;
  c.amount = amount;
  return c;
}

void readOuts(const Session& session) {
  const Deployment& dep = *session.deployment();
  const DeviceState& ds = session.deploymentState();
  char overlay[64];
  std::snprintf(overlay, sizeof overlay, "%.1f of %.1f mm out", units::mToMm(ds.deployed), units::mToMm(dep.coilLength));
  ImGui::ProgressBar(float(dep.coilLength > 0 ? ds.deployed / dep.coilLength : 0.0), ImVec2(-1.0f, 0.0f), overlay);
  ImGui::Text("twist %+.0f\xc2\xb0", units::radToDeg(ds.twist));
  if (ds.tipOffset != 0) {
    ImGui::SameLine();
    ImGui::Text("  catheter back %.1f mm", units::mToMm(ds.tipOffset));
  }
  if (ds.detached) {
    ImGui::SameLine();
    ImGui::TextColored(ImVec4(0.5f, 0.9f, 0.5f, 1.0f), "  detached");
  }
  if (ds.motion.moving()) {
    ImGui::SameLine();
    ImGui::TextDisabled("  moving");
  }
  const ContactSummary& c = session.contacts();
  if (!c.available)
    ImGui::TextDisabled("wall load: this build has no contact forces");
  else
    ImGui::Text("wall load %.3f mN, largest %.3f mN (lasting 5 ms; %d contacts)", 1e3 * c.wallLoad,
                1e3 * c.wallLoadMax, c.contacts);
  if (session.timelineSize() > 0)
    ImGui::TextDisabled("timeline: %zu of %zu commands started", session.timelineCursor(), session.timelineSize());
}

void motionButtons(Session& session, DeviceControls& dc) {
  using K = DeviceCommand::Kind;
  const Deployment& dep = *session.deployment();
  const double maxSpeedMmS = units::mToMm(dep.maxPushSpeed);
  const double maxTwistDegS = units::radToDeg(dep.maxTwistRate);
  ImGui::TextDisabled("push / pull speed [mm/s]");
  ImGui::SetNextItemWidth(-1.0f);
  const double lo = 0.1;
  ImGui::SliderScalar("##speed", ImGuiDataType_Double, &dc.pushSpeedMmS, &lo, &maxSpeedMmS, "%.2f",
                      ImGuiSliderFlags_Logarithmic);
  const double speed = units::mmPerSToMPerS(dc.pushSpeedMmS);
  if (ImGui::Button("Push (P)")) session.command(make(K::Push, speed));
  ImGui::SameLine();
  if (ImGui::Button("Pull (O)")) session.command(make(K::Pull, speed));
  ImGui::SameLine();
  if (ImGui::Button("Stop")) session.command(make(K::Stop, 0));

  ImGui::TextDisabled("twist rate [\xc2\xb0/s]");
  ImGui::SetNextItemWidth(-1.0f);
  const double tlo = 5.0;
  ImGui::SliderScalar("##twist", ImGuiDataType_Double, &dc.twistRateDegS, &tlo, &maxTwistDegS, "%.0f");
  const double rate = units::degPerSToRadPerS(dc.twistRateDegS);
  const double quarter = units::degToRad(90.0);
  if (ImGui::Button("Twist -90\xc2\xb0 (Q)")) session.command(make(K::Twist, -rate, quarter));
  ImGui::SameLine();
  if (ImGui::Button("Twist +90\xc2\xb0 (E)")) session.command(make(K::Twist, rate, quarter));

  ImGui::TextDisabled("catheter retraction [mm/s]");
  ImGui::SetNextItemWidth(-1.0f);
  ImGui::SliderScalar("##retract", ImGuiDataType_Double, &dc.retractSpeedMmS, &lo, &maxSpeedMmS, "%.2f",
                      ImGuiSliderFlags_Logarithmic);
  if (ImGui::Button("Retract catheter 2 mm"))
    session.command(make(K::Retract, units::mmPerSToMPerS(dc.retractSpeedMmS), units::mmToM(2.0)));
}

// Detaching cannot be undone (except by Reset): ask first.
void detachButton(Session& session, DeviceControls& dc) {
  if (!dc.confirmDetach) {
    if (ImGui::Button("Detach... (D)")) dc.confirmDetach = true;
    return;
  }
  ImGui::TextColored(kRefused, "Detach the coil from the pusher?");
  if (ImGui::Button("Yes, detach")) {
    session.command(make(DeviceCommand::Kind::Detach, 0));
    dc.confirmDetach = false;
  }
  ImGui::SameLine();
  if (ImGui::Button("Cancel")) dc.confirmDetach = false;
}

void messages(const Session& session) {
  if (session.deviceMessages().empty()) return;
  ImGui::PushTextWrapPos(0.0f);
  // Newest first: the one that matters is the last thing that happened.
  const auto& list = session.deviceMessages();
  for (auto it = list.rbegin(); it != list.rend(); ++it) {
    if (it->find("refused") != std::string::npos)
      ImGui::TextColored(kRefused, "%s", it->c_str());
    else
      ImGui::TextDisabled("%s", it->c_str());
  }
  ImGui::PopTextWrapPos();
}

}  // namespace

void drawDeploymentControls(Session& session, PanelContext& ctx) {
  if (!session.hasDeployment()) {
    ImGui::PushTextWrapPos(0.0f);
    ImGui::TextDisabled("This scene has no \"deployment\" block: no coil in a catheter to push "
                        "(see docs/scene-format.md and scenes/default.json).");
    ImGui::PopTextWrapPos();
    return;
  }
  readOuts(session);
  // Nothing is greyed out: the controller says why a command cannot be done.
  motionButtons(session, ctx.device);
  ImGui::SameLine();
  detachButton(session, ctx.device);
  if (ImGui::Button("Reset deployment (R)")) session.reset();
  if (!session.playing()) {
    ImGui::SameLine();
    ImGui::TextDisabled("paused: Space plays");
  }
  messages(session);
}

}  // namespace coilsim::ui
