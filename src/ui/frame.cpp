#include "ui/frame.h"

#include <imgui.h>

#include <algorithm>
#include <optional>

#include "render/xray_look.h"
#include "ui/contact_overlay.h"

namespace coilsim::ui {

render::Bounds sceneBounds(const Session& session) {
  render::Bounds b = render::boundsOf(session.drawData());
  const Deployment* dep = session.deployment();
  if (!dep || dep->restX.empty()) return b;
  // Where the coil will go: its whole rest shape leaving the tip in the tip's
  // frame (a helix is screw-symmetric, so every partly deployed rest shape
  // lies on it). The camera then frames the deployment from the start, and
  // the window and a headless screenshot of the same state look alike.
  const Quat c = dep->tip.rotation() * dep->restF.front().conjugate();
  for (const Vec3& p : dep->restX) b.add(dep->tip.position + c * (p - dep->restX.front()), dep->section.radius);
  return b;
}

int sidebarWidth(const FrameParts& p, int width) {
  if (!p.drawPanel) return 0;
  return std::min(std::clamp(int(0.3 * width), 300, 380), width / 2);
}

bool drawFrame(FrameParts& p, int width, int height, double dt, std::string& error) {
  // The panel is a sidebar on the left; the scene fills the rest.
  p.panel.sidebarWidth = sidebarWidth(p, width);
  const render::Rect area{p.panel.sidebarWidth, 0, width - p.panel.sidebarWidth, height};
  const render::Bounds bounds = sceneBounds(p.session);
  p.views.fitIfNew(bounds, area.width, area.height);
  if (p.panel.fitRequested) {
    p.views.fit(bounds, area.width, area.height);
    p.panel.fitRequested = false;
  }
  p.settings.mode = p.views.mode();
  p.settings.drawPoints = p.panel.overlays.contacts;
  // Contact markers smaller than the coil, on its surface: its colour stays visible.
  p.settings.pointRadius = contactMarkerRadius(p.session.model());
  if (!p.renderer.render(p.session.drawData(), p.views.camera(), p.settings, width, height, area, error))
    return false;
  p.imgui.newFrame(width, height, dt);
  if (p.drawPanel) drawPanel(p.session, p.views, p.panel);
  drawViewLabels(p.renderer.viewports(), height, p.views);
  const ImVec2 fbScale = ImGui::GetIO().DisplayFramebufferScale;
  // In the X-ray views the swatches are the greys the matter is drawn in.
  std::optional<render::XRayGreys> greys;
  if (p.settings.mode != render::ViewMode::Shaded && !p.panel.legend.empty())
    greys = render::xrayGreys(p.session.drawData(), p.views.camera(), p.settings.xray);
  drawSceneLegend(p.panel.legend, float(p.panel.sidebarWidth) / (fbScale.x > 0 ? fbScale.x : 1.0f),
                  float(height) / (fbScale.y > 0 ? fbScale.y : 1.0f), greys ? &*greys : nullptr, p.panel.layout);
  p.renderer.bindFrame();
  p.imgui.render();
  return true;
}

void layoutPanelOnly(FrameParts& p, int width, int height) {
  p.panel.sidebarWidth = sidebarWidth(p, width);
  p.imgui.newFrame(width, height, 1.0 / 60.0);
  if (p.drawPanel) drawPanel(p.session, p.views, p.panel);
  ImGui::EndFrame();
}

}  // namespace coilsim::ui
