#include "ui/panel.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "io/units.h"
#include "ui/help_overlay.h"
#include "physics/integrator.h"

namespace coilsim::ui {
namespace {

const ImVec4 kWarn(1.0f, 0.7f, 0.2f, 1.0f);
const ImVec4 kError(1.0f, 0.4f, 0.35f, 1.0f);

// Energies are tiny (a coil stores micro-joules): one readable unit for the
// whole table, picked from the largest value.
struct EnergyUnit {
  const char* name;
  double scale;
};

EnergyUnit energyUnit(double largest) {
  if (largest >= 1.0 || !std::isfinite(largest)) return {"J", 1.0};
  if (largest >= 1e-3) return {"mJ", 1e3};
  if (largest >= 1e-6) return {"\xc2\xb5J", 1e6};
  return {"nJ", 1e9};
}

// Play, step, reset and the time: always at the top of the panel.
void transportRow(Session& session, PanelContext& ctx) {
  if (session.playing()) {
    if (ImGui::Button("Pause (Space)")) session.setPlaying(false);
  } else {
    if (ImGui::Button("Play (Space)")) session.setPlaying(true);
  }
  if (ctx.layout) ctx.layout->markLastItem("play");
  ImGui::SameLine();
  ImGui::BeginDisabled(session.playing());
  if (ImGui::Button("Step (N)")) session.stepOnce();
  ImGui::EndDisabled();
  ImGui::SameLine();
  if (ImGui::Button("Reset (R)")) session.reset();
  if (ctx.layout) ctx.layout->markLastItem("reset");
  // The time beside them when it fits (a narrow panel puts it below).
  char time[32];
  std::snprintf(time, sizeof time, "t = %.3f s", session.state().time);
  ImGui::SameLine();
  if (ImGui::GetContentRegionAvail().x < ImGui::CalcTextSize(time).x) ImGui::NewLine();
  ImGui::TextUnformatted(time);
}

void simulationSection(Session& session, PanelContext& ctx) {
  const State& s = session.state();
  ImGui::Text("simulated time  %.4f s", s.time);
  const double meanStep = s.stats.steps ? s.stats.totalStepSeconds / double(s.stats.steps) : 0.0;
  ImGui::Text("time step       %.3g ms", units::sToMs(session.model().timeStep));
  ImGui::Text("step time       %.3f ms", units::sToMs(s.stats.lastStepSeconds));
  ImGui::Text("  mean / max    %.3f / %.3f ms", units::sToMs(meanStep), units::sToMs(s.stats.maxStepSeconds));
  if (ctx.interactive) {
    if (session.playing()) {
      ImGui::Text("real-time factor %.2fx", session.loop().realTimeFactor());
      if (session.loop().behind())
        ImGui::TextColored(kWarn, "Physics is slower than real time:\nsimulated time runs %.2fx real time.",
                           session.loop().realTimeFactor());
    } else {
      ImGui::TextDisabled("real-time factor (paused)");
    }
    if (ctx.frameSeconds > 0)
      ImGui::Text("frame %.1f ms (%.0f fps), drawing %.1f ms", units::sToMs(ctx.frameSeconds), 1.0 / ctx.frameSeconds,
                  units::sToMs(ctx.renderSeconds));
  } else {
    ImGui::TextDisabled("off-screen snapshot");
  }

  const Energy e = computeEnergy(session.model(), s);
  const EnergyUnit unit = energyUnit(std::max({std::abs(e.kinetic), std::abs(e.elastic), std::abs(e.potential)}));
  if (ImGui::BeginTable("energy", 2, ImGuiTableFlags_SizingFixedFit)) {
    auto row = [&](const char* name, double joules) {
      ImGui::TableNextRow();
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(name);
      ImGui::TableNextColumn();
      ImGui::Text("%10.4f %s", joules * unit.scale, unit.name);
    };
    row("kinetic energy", e.kinetic);
    row("elastic energy", e.elastic);
    row("potential energy", e.potential);
    row("total energy", e.total());
    ImGui::EndTable();
  }

  // Blow-ups are reported here and never drawn.
  if (!session.haltMessage().empty()) {
    ImGui::PushTextWrapPos(0.0f);
    ImGui::TextColored(kError, "Stopped: %s", session.haltMessage().c_str());
    ImGui::TextDisabled("Reset, or change the effects and press Play.");
    ImGui::PopTextWrapPos();
  }
  if (session.showingOlderState())
    ImGui::TextColored(kError, "The current state is unhealthy; showing the last good one.");
  if (s.blowups > 0) ImGui::TextColored(kError, "refused steps: %ld", s.blowups);
  if (!s.warnings.empty()) {
    ImGui::PushTextWrapPos(0.0f);
    for (const std::string& w : s.warnings) ImGui::TextColored(kWarn, "%s", w.c_str());
    ImGui::PopTextWrapPos();
  }
}

void viewSection(Views& views, PanelContext& ctx) {
  int mode = int(views.mode());
  ImGui::BeginDisabled(views.xrayOnly());
  bool changed = ImGui::RadioButton("3D (1)", &mode, int(render::ViewMode::Shaded));
  ImGui::EndDisabled();
  ImGui::SameLine();
  changed |= ImGui::RadioButton("X-ray (2)", &mode, int(render::ViewMode::XRay));
  ImGui::SameLine();
  changed |= ImGui::RadioButton("Biplane (3)", &mode, int(render::ViewMode::Biplane));
  if (changed) views.setMode(render::ViewMode(mode));
  if (views.xrayOnly()) ImGui::TextDisabled("X-ray views only, as in the procedure");
  if (ImGui::Button("Fit to scene (F)")) ctx.fitRequested = true;
  if (views.mode() != render::ViewMode::Shaded) {
    ImGui::Text("C-arm rotation %+.0f\xc2\xb0, angulation %+.0f\xc2\xb0", views.rotationDeg(), views.angulationDeg());
  }
}

void overlaySection(Session& session, PanelContext& ctx) {
  Overlays& o = ctx.overlays;
  ImGui::Checkbox("colour by bending moment", &o.colourByMoment);
  if (o.colourByMoment) {
    ImGui::Indent();
    ImGui::TextDisabled("red at [N mm] (0: the largest)");
    ImGui::SetNextItemWidth(-1.0f);
    const double lo = 0, hi = 10;
    ImGui::SliderScalar("##moment", ImGuiDataType_Double, &o.momentScaleNmm, &lo, &hi, "%.3f");
    ImGui::Text("largest %.4f N mm", units::nmToNmm(session.largestMoment()));
    ImGui::Unindent();
  }
  session.setMomentColouring(o.colourByMoment, units::nmmToNm(o.momentScaleNmm));
  ImGui::Checkbox("contact points and forces (3D)", &o.contacts);
}

void effectsSection(Session& session, const PanelContext& ctx) {
  Model& m = session.model();
  if (m.effects.empty()) ImGui::TextDisabled("no effects in this scene");
  if (!ctx.effectsLocked.empty()) {
    ImGui::PushTextWrapPos(0.0f);
    ImGui::TextDisabled("%s", ctx.effectsLocked.c_str());
    ImGui::PopTextWrapPos();
  }
  ImGui::BeginDisabled(!ctx.effectsLocked.empty());
  for (size_t i = 0; i < m.effects.size(); ++i) {
    EffectUse& use = m.effects[i];
    if (!use.effect) continue;
    ImGui::PushID(int(i));
    const std::string name(use.name());
    ImGui::Checkbox(name.c_str(), &use.enabled);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%.*s", int(use.effect->description().size()),
                                                  use.effect->description().data());
    // Parameters are declared once (name, unit, bounds) and edited in their edge unit.
    const auto params = use.effect->params();
    for (size_t k = 0; k < params.size() && k < use.values.size(); ++k) {
      const ParamSpec& p = params[k];
      double edge = use.values[k] / p.toSI;
      ImGui::PushID(int(k));
      ImGui::Indent();
      ImGui::TextDisabled("%.*s [%.*s]", int(p.name.size()), p.name.data(), int(p.unit.size()), p.unit.data());
      ImGui::SetNextItemWidth(-1.0f);
      ImGui::BeginDisabled(!use.enabled);
      if (ImGui::SliderScalar("##value", ImGuiDataType_Double, &edge, &p.min, &p.max, "%.4g"))
        use.values[k] = edge * p.toSI;
      ImGui::EndDisabled();
      if (ImGui::IsItemHovered())
        ImGui::SetTooltip("%.*s", int(p.description.size()), p.description.data());
      ImGui::Unindent();
      ImGui::PopID();
    }
    ImGui::PopID();
  }
  ImGui::EndDisabled();
}

}  // namespace

void drawPanel(Session& session, Views& views, PanelContext& ctx) {
  const ImGuiIO& io = ImGui::GetIO();
  ImGui::SetNextWindowPos(ImVec2(0, 0), ImGuiCond_Always);
  // sidebarWidth is in framebuffer pixels, ImGui works in window units (HiDPI).
  const float scale = io.DisplayFramebufferScale.x > 0 ? io.DisplayFramebufferScale.x : 1.0f;
  const float sidebar = float(ctx.sidebarWidth) / scale;
  ImGui::SetNextWindowSize(ImVec2(sidebar, io.DisplaySize.y), ImGuiCond_Always);
  const std::string title = "coilsim" + (ctx.sceneName.empty() ? std::string() : "  " + ctx.sceneName) + "###panel";
  ImGui::Begin(title.c_str(), nullptr,
               ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse |
                   ImGuiWindowFlags_NoScrollbar | ImGuiWindowFlags_NoScrollWithMouse);
  // The compact clinical layout: what a clinician needs while pushing stays
  // open, the engineer's figures start closed.
  const bool compact = io.DisplaySize.y < 900.0f;
  const ImGuiTreeNodeFlags engineer = compact ? ImGuiTreeNodeFlags_None : ImGuiTreeNodeFlags_DefaultOpen;
  transportRow(session, ctx);
  // The device controls never scroll away.
  if (session.hasDeployment()) {
    ImGui::Separator();
    drawDeploymentControls(session, ctx);
  }
  ImGui::Separator();
  // Everything else scrolls in the rest of the column.
  ImGui::BeginChild("##sections", ImVec2(0, 0), false);
  std::string sections = session.hasDeployment() ? "Device" : "";  // for the layout dump: which were drawn
  auto header = [&](const std::string& name, ImGuiTreeNodeFlags flags) {
    sections += (sections.empty() ? "" : "|") + name;
    return ImGui::CollapsingHeader(name.c_str(), flags);
  };
  // Warnings (protrusion, wall force) first, where they are seen while pushing.
  if (ctx.readouts && header(ctx.readouts.title, ImGuiTreeNodeFlags_DefaultOpen))
    drawReadouts(ctx.readouts.compute(session.model(), session.state()));
  if (session.hasDeployment() && header("Device messages", ImGuiTreeNodeFlags_None)) drawDeviceMessages(session);
  if (!session.hasDeployment() && header("Deployment", ImGuiTreeNodeFlags_DefaultOpen))
    drawDeploymentControls(session, ctx);
  if (header("View", ImGuiTreeNodeFlags_DefaultOpen)) viewSection(views, ctx);
  if (ctx.setup && header("Coil and catheter", engineer)) drawSetupSection(*ctx.setup, session, ctx);
  if (header("Simulation", engineer)) simulationSection(session, ctx);
  if (header("Colours and markers", ImGuiTreeNodeFlags_None)) overlaySection(session, ctx);
  if (header("Effects", engineer)) effectsSection(session, ctx);
  if (ctx.layout) ctx.layout->fact("sections", sections);
  if (ctx.interactive) ImGui::TextDisabled("F1 or ?: every key and mouse action");
  if (!ctx.glInfo.empty() && ctx.interactive) ImGui::TextDisabled("%s", ctx.glInfo.c_str());
  if (ctx.layout) {
    ctx.layout->fact("sections_scroll_y", double(ImGui::GetScrollY()));
    ctx.layout->fact("sections_scroll_max_y", double(ImGui::GetScrollMaxY()));
  }
  ImGui::EndChild();
  if (ctx.layout) {
    const ImVec2 p = ImGui::GetWindowPos(), sz = ImGui::GetWindowSize();
    ctx.layout->mark("panel", p.x, p.y, p.x + sz.x, p.y + sz.y);
  }
  ImGui::End();

  drawDetachConfirmation(session, ctx);
  if (ctx.helpOpen) drawHelpOverlay("Keys and mouse (F1)###help", runWindowHelp(), sidebar, io.DisplaySize.x,
                                    io.DisplaySize.y, ctx.layout);
  if (ctx.layout) {
    const DeviceState& ds = session.deploymentState();
    ctx.layout->fact("detach_confirm_open", ctx.device.confirmDetach);
    ctx.layout->fact("help_open", ctx.helpOpen);
    ctx.layout->fact("time_s", session.state().time);
    ctx.layout->fact("deployed_mm", units::mToMm(ds.deployed));
    ctx.layout->fact("coil_mm", session.deployment() ? units::mToMm(session.deployment()->coilLength) : 0.0);
    ctx.layout->fact("detached", ds.detached);
    ctx.layout->fact("last_message",
                     session.deviceMessages().empty() ? std::string() : session.deviceMessages().back());
  }
}

void drawViewLabels(const std::vector<render::ViewportInfo>& viewports, int frameHeight, const Views& views) {
  ImDrawList* draw = ImGui::GetForegroundDrawList();
  const ImVec2 fb = ImGui::GetIO().DisplayFramebufferScale;
  const float sx = fb.x > 0 ? fb.x : 1.0f, sy = fb.y > 0 ? fb.y : 1.0f;
  for (const render::ViewportInfo& vp : viewports) {
    if (vp.label == "3D") continue;
    // Viewports count pixels from the bottom, ImGui window units from the top.
    const float right = float(vp.x + vp.width) / sx - 10.0f, top = float(frameHeight - (vp.y + vp.height)) / sy + 8.0f;
    char text[96];
    if (vp.label == "AP")
      std::snprintf(text, sizeof text, "%s  %+.0f\xc2\xb0 / %+.0f\xc2\xb0", vp.label.c_str(), views.rotationDeg(),
                    views.angulationDeg());
    else
      std::snprintf(text, sizeof text, "%s", vp.label.c_str());
    const ImVec2 size = ImGui::CalcTextSize(text);
    draw->AddText(ImVec2(right - size.x, top), IM_COL32(255, 255, 255, 230), text);
  }
}

}  // namespace coilsim::ui
