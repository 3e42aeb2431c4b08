// ---------------------------------------------------------------------------
// Deployment controls: push / pull at a speed (also P / O held), twist (Q / E
// held, Ctrl + wheel), detach with a confirmation, catheter retraction, stop;
// the controller's refusals and the limits reached, and the read-outs
// (deployed length, twist, catheter position). Every command goes through
// Session::command, the same controller API that timelines use.
// ---------------------------------------------------------------------------
#include <imgui.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "io/units.h"
#include "physics/rod_quantities.h"
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

void readOuts(const Session& session, PanelContext& ctx) {
  const Deployment& dep = *session.deployment();
  const DeviceState& ds = session.deploymentState();
  // Lengths in the rod quantities' declared unit (physics/rod_quantities.h), as scenes give them.
  const ParamSpec& length = rodq::kLength.spec;
  const std::string unit(length.unit);
  char overlay[64];
  std::snprintf(overlay, sizeof overlay, "%.1f of %.1f %s out", units::fromSI(length, ds.deployed),
                units::fromSI(length, dep.coilLength), unit.c_str());
  ImGui::ProgressBar(float(dep.coilLength > 0 ? ds.deployed / dep.coilLength : 0.0), ImVec2(-1.0f, 0.0f), overlay);
  if (ctx.layout) ctx.layout->markLastItem("deployed");
  ImGui::Text("twist %+.0f\xc2\xb0", units::radToDeg(ds.twist));
  if (ds.tipOffset != 0) {
    ImGui::SameLine();
    ImGui::Text("  catheter back %.1f %s", units::fromSI(length, ds.tipOffset), unit.c_str());
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
    ImGui::Text("wall load %.3f mN, largest %.3f mN (lasting 5 ms; %d contacts)", units::nToMn(c.wallLoad),
                units::nToMn(c.wallLoadMax), c.contacts);
  if (session.timelineSize() > 0)
    ImGui::TextDisabled("timeline: %zu of %zu commands started", session.timelineCursor(), session.timelineSize());
}

// A slider with its unit on the right, on one line (the compact layout).
void speedSlider(const char* id, const char* unit, double& value, double lo, double hi, const char* format,
                 ImGuiSliderFlags flags) {
  ImGui::SetNextItemWidth(-ImGui::CalcTextSize("catheter mm/s").x - ImGui::GetStyle().ItemInnerSpacing.x);
  ImGui::SliderScalar(id, ImGuiDataType_Double, &value, &lo, &hi, format, flags);
  ImGui::SameLine(0.0f, ImGui::GetStyle().ItemInnerSpacing.x);
  ImGui::TextDisabled("%s", unit);
}

void motionButtons(Session& session, PanelContext& ctx) {
  using K = DeviceCommand::Kind;
  DeviceControls& dc = ctx.device;
  auto mark = [&](const char* name) {
    if (ctx.layout) ctx.layout->markLastItem(name);
  };
  const Deployment& dep = *session.deployment();
  const double maxSpeedMmS = units::mToMm(dep.maxPushSpeed);
  const double maxTwistDegS = units::radToDeg(dep.maxTwistRate);
  speedSlider("##speed", "push mm/s", dc.pushSpeedMmS, 0.1, maxSpeedMmS, "%.2f", ImGuiSliderFlags_Logarithmic);
  mark("push_speed");
  const double speed = units::mmPerSToMPerS(dc.pushSpeedMmS);
  if (ImGui::Button("Push (P)")) session.command(make(K::Push, speed));
  mark("push");
  ImGui::SameLine();
  if (ImGui::Button("Pull (O)")) session.command(make(K::Pull, speed));
  mark("pull");
  ImGui::SameLine();
  if (ImGui::Button("Stop")) session.command(make(K::Stop, 0));
  mark("stop");

  speedSlider("##twist", "twist \xc2\xb0/s", dc.twistRateDegS, 5.0, maxTwistDegS, "%.0f", ImGuiSliderFlags_None);
  mark("twist_rate");
  const double rate = units::degPerSToRadPerS(dc.twistRateDegS);
  const double quarter = units::degToRad(90.0);
  if (ImGui::Button("Twist -90\xc2\xb0 (Q)")) session.command(make(K::Twist, -rate, quarter));
  mark("twist_minus");
  ImGui::SameLine();
  if (ImGui::Button("Twist +90\xc2\xb0 (E)")) session.command(make(K::Twist, rate, quarter));
  mark("twist_plus");

  speedSlider("##retract", "catheter mm/s", dc.retractSpeedMmS, 0.1, maxSpeedMmS, "%.2f",
              ImGuiSliderFlags_Logarithmic);
  mark("retract_speed");
  if (ImGui::Button("Retract catheter 2 mm"))
    session.command(make(K::Retract, units::mmPerSToMPerS(dc.retractSpeedMmS), units::mmToM(2.0)));
  mark("retract");
}

}  // namespace

bool requestDetach(Session& session, DeviceControls& dc) {
  if (const std::optional<Failure> refused = session.wouldRefuse(make(DeviceCommand::Kind::Detach, 0))) {
    session.noteRefusal(*refused);
    dc.confirmDetach = false;
    return false;
  }
  dc.confirmDetach = true;
  return true;
}

void confirmDetach(Session& session, DeviceControls& dc) {
  dc.confirmDetach = false;
  session.command(make(DeviceCommand::Kind::Detach, 0));
}

void drawDetachConfirmation(Session& session, PanelContext& ctx) {
  constexpr const char* kId = "Detach the coil?###detach";
  DeviceControls& dc = ctx.device;
  if (dc.confirmDetach && !ImGui::IsPopupOpen(kId)) ImGui::OpenPopup(kId);
  // Centred over the scene, away from the panel: where its buttons were,
  // there is only the scene when it closes.
  const ImGuiIO& io = ImGui::GetIO();
  const float scale = io.DisplayFramebufferScale.x > 0 ? io.DisplayFramebufferScale.x : 1.0f;
  const float left = float(ctx.sidebarWidth) / scale;
  ImGui::SetNextWindowPos(ImVec2(0.5f * (left + io.DisplaySize.x), 0.5f * io.DisplaySize.y), ImGuiCond_Always,
                          ImVec2(0.5f, 0.5f));
  if (!ImGui::BeginPopupModal(kId, nullptr, ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoMove)) return;
  if (!dc.confirmDetach) {
    ImGui::CloseCurrentPopup();  // answered by a key
  } else {
    ImGui::TextUnformatted("Detach the coil from the pusher?");
    ImGui::TextDisabled("It cannot be pushed, pulled or twisted after this (Reset starts again).");
    if (ImGui::Button("Detach (D or Enter)")) confirmDetach(session, dc);
    if (ctx.layout) ctx.layout->markLastItem("detach_confirm");
    ImGui::SameLine();
    if (ImGui::Button("Cancel (Esc)")) dc.confirmDetach = false;
    if (ctx.layout) ctx.layout->markLastItem("detach_cancel");
    if (!dc.confirmDetach) ImGui::CloseCurrentPopup();
  }
  ImGui::EndPopup();
}

void drawDeviceMessages(const Session& session) {
  if (session.deviceMessages().empty()) {
    ImGui::TextDisabled("none yet");
    return;
  }
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

void drawDeploymentControls(Session& session, PanelContext& ctx) {
  if (!session.hasDeployment()) {
    ImGui::PushTextWrapPos(0.0f);
    ImGui::TextDisabled("This scene has no \"deployment\" block: no coil in a catheter to push "
                        "(see docs/scene-format.md and scenes/default.json).");
    ImGui::PopTextWrapPos();
    return;
  }
  readOuts(session, ctx);
  // Nothing is greyed out: the controller says why a command cannot be done.
  motionButtons(session, ctx);
  ImGui::SameLine();
  if (ImGui::Button("Detach... (D)")) requestDetach(session, ctx.device);
  if (ctx.layout) ctx.layout->markLastItem("detach");
  // The newest message where it is seen (a refusal says why nothing moved);
  // all of them in the "Device messages" section below.
  if (!session.deviceMessages().empty()) {
    const std::string& last = session.deviceMessages().back();
    ImGui::PushTextWrapPos(0.0f);
    if (last.find("refused") != std::string::npos)
      ImGui::TextColored(kRefused, "%s", last.c_str());
    else
      ImGui::TextDisabled("%s", last.c_str());
    ImGui::PopTextWrapPos();
    if (ctx.layout) ctx.layout->markLastItem("last_message");
  }
}

}  // namespace coilsim::ui
