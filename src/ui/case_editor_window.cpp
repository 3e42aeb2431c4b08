// The case editor window (see case_editor_window.h): the window's events
// queued in the order they came and handed to CaseEditorControls, the
// panel (morphology, messages, Save, the questions), and the two frame
// loops (window and off-screen).
#define GLFW_INCLUDE_NONE
#include "ui/case_editor_window.h"

#include <GLFW/glfw3.h>
#include <imgui.h>

#include <algorithm>
#include <cstdio>
#include <optional>
#include <vector>

#include "render/gl_loader.h"
#include "render/image.h"
#include "render/renderer.h"
#include "ui/case_editor_controls.h"
#include "ui/glfw_window.h"
#include "ui/imgui_layer.h"
#include "ui/realtime.h"
#include "ui/offscreen_context.h"

namespace coilsim::ui {
namespace {

// One window event. The queue keeps a press and release that fall between
// two frames (a quick click, a key tapped) and their order.
struct Event {
  enum Kind { Key, Press, Release, Move, Scroll } kind = Move;
  int code = 0;  // GLFW key or mouse button
  int mods = 0;
  double x = 0, y = 0;  // cursor (window pixels) or scroll
};

struct Queue {
  std::vector<Event> events;
  double scale = 1;  // framebuffer pixels per window unit
  // The cursor as the motion events left it. A button event carries no
  // position, and asking the window system gives where the pointer is now,
  // which on a busy machine is already past the press.
  double x = 0, y = 0;
};

Queue* queueOf(GLFWwindow* w) { return static_cast<Queue*>(glfwGetWindowUserPointer(w)); }

void onKey(GLFWwindow* w, int key, int, int action, int mods) {
  if (action != GLFW_RELEASE) queueOf(w)->events.push_back({Event::Key, key, mods, 0, 0});
}
void onButton(GLFWwindow* w, int button, int action, int mods) {
  Queue* q = queueOf(w);
  q->events.push_back({action == GLFW_PRESS ? Event::Press : Event::Release, button, mods, q->x, q->y});
}
void onMove(GLFWwindow* w, double x, double y) {
  Queue* q = queueOf(w);
  q->x = x * q->scale, q->y = y * q->scale;
  q->events.push_back({Event::Move, 0, 0, q->x, q->y});
}
void onScroll(GLFWwindow* w, double, double dy) { queueOf(w)->events.push_back({Event::Scroll, 0, 0, 0, dy}); }

std::optional<EditorKey> editorKey(int key) {
  switch (key) {
    case GLFW_KEY_UP: return EditorKey::Up;
    case GLFW_KEY_DOWN: return EditorKey::Down;
    case GLFW_KEY_PAGE_UP: return EditorKey::PageUp;
    case GLFW_KEY_PAGE_DOWN: return EditorKey::PageDown;
    case GLFW_KEY_I: return EditorKey::TiltUp;
    case GLFW_KEY_K: return EditorKey::TiltDown;
    case GLFW_KEY_J: return EditorKey::TiltLeft;
    case GLFW_KEY_L: return EditorKey::TiltRight;
    case GLFW_KEY_T: return EditorKey::AimTip;
    case GLFW_KEY_F: return EditorKey::Fit;
    case GLFW_KEY_S: return EditorKey::Save;
    case GLFW_KEY_N: return EditorKey::No;
    case GLFW_KEY_ENTER:
    case GLFW_KEY_KP_ENTER: return EditorKey::Enter;
    case GLFW_KEY_ESCAPE: return EditorKey::Escape;
    default: return std::nullopt;
  }
}

EditorMods modsOf(int mods) { return {(mods & GLFW_MOD_SHIFT) != 0, (mods & GLFW_MOD_CONTROL) != 0}; }

void handOver(Queue& q, CaseEditorControls& c, bool panelWantsMouse) {
  for (const Event& e : q.events) {
    switch (e.kind) {
      case Event::Key:
        if (const auto k = editorKey(e.code)) c.key(*k, modsOf(e.mods));
        break;
      case Event::Press:
        if (!panelWantsMouse) c.press(e.code == GLFW_MOUSE_BUTTON_RIGHT ? 1 : e.code, e.x, e.y, modsOf(e.mods));
        break;
      case Event::Release: c.release(e.code == GLFW_MOUSE_BUTTON_RIGHT ? 1 : e.code, e.x, e.y); break;
      case Event::Move: c.move(e.x, e.y); break;
      case Event::Scroll:
        if (!panelWantsMouse) c.scroll(e.y);
        break;
    }
  }
  q.events.clear();
}

int sidebarOf(int width) { return std::min(std::max(int(0.28 * width), 340), 420); }

void drawQuestion(CaseEditorControls& c) {
  const EditorAsk ask = c.asking();
  if (ask == EditorAsk::None) return;
  const char* id = ask == EditorAsk::Overwrite ? "Overwrite the case?" : "Unsaved edits";
  ImGui::OpenPopup(id);
  const ImVec2 centre = ImGui::GetMainViewport()->GetCenter();
  ImGui::SetNextWindowPos(centre, ImGuiCond_Always, ImVec2(0.5f, 0.5f));
  if (!ImGui::BeginPopupModal(id, nullptr, ImGuiWindowFlags_AlwaysAutoResize)) return;
  if (ask == EditorAsk::Overwrite) {
    ImGui::Text("Save over %s?", c.hooks().savePath.c_str());
    if (ImGui::Button("Overwrite (Enter)")) c.confirm();
    ImGui::SameLine();
    if (ImGui::Button("Cancel (Esc)")) c.cancel();
  } else {
    ImGui::Text("The edits are not saved to %s.", c.hooks().savePath.c_str());
    if (ImGui::Button("Save and close (Enter)")) c.confirm();
    ImGui::SameLine();
    if (ImGui::Button("Close without saving (N)")) c.discard();
    ImGui::SameLine();
    if (ImGui::Button("Cancel (Esc)")) c.cancel();
  }
  ImGui::EndPopup();
}

void drawPanel(CaseEditorControls& c, int sidebar, int height) {
  ImGui::SetNextWindowPos(ImVec2(0, 0));
  ImGui::SetNextWindowSize(ImVec2(float(sidebar), float(height)));
  ImGui::Begin("Case editor", nullptr,
               ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse);
  const CaseEditorHooks& h = c.hooks();
  ImGui::TextWrapped("%s", h.title.c_str());
  ImGui::TextWrapped("saves to %s%s", h.savePath.c_str(), h.saveOverwrites ? " (asks first)" : "");
  ImGui::Separator();
  ImGui::TextUnformatted("Morphology");
  if (ImGui::BeginTable("morphology", 2, ImGuiTableFlags_RowBg | ImGuiTableFlags_SizingStretchProp)) {
    for (const auto& [name, value] : c.view().rows) {
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(name.c_str());
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(value.c_str());
    }
    ImGui::EndTable();
  }
  ImGui::Separator();
  if (!c.message().empty()) {
    const ImVec4 colour = c.refused() ? ImVec4(1.0f, 0.45f, 0.4f, 1) : ImVec4(0.6f, 0.9f, 0.6f, 1);
    ImGui::PushStyleColor(ImGuiCol_Text, colour);
    ImGui::TextWrapped("%s", c.message().c_str());
    ImGui::PopStyleColor();
  }
  ImGui::TextUnformatted(c.view().unsaved ? "unsaved edits" : "no unsaved edits");
  if (ImGui::Button("Save (Ctrl+S)")) c.save();
  ImGui::SameLine();
  if (ImGui::Button("Aim tip (T)")) c.aimTip();
  if (ImGui::Button("Fit view (F)")) c.fit();
  ImGui::SameLine();
  if (ImGui::Button("Close (Esc)")) c.closeRequested();
  ImGui::Separator();
  ImGui::TextWrapped(
      "Shift + drag up/down: the neck plane along its normal, %.2f mm a pixel (up: toward the dome). "
      "Up/Down: %.1f mm, Page Up/Down: %.0f mm. I/K, J/L: tilt it %.0f deg. Ctrl + click on the surface: the "
      "neck plane through that point. Click on the surface, or drag the tip: the catheter tip in the middle of "
      "the lumen under the cursor; T aims it at the neck. Drag: orbit, right drag: pan, wheel: zoom.",
      kNeckDragMmPerPixel, kNeckKeyStepMm, kNeckPageStepMm, kTiltKeyStepDeg);
  ImGui::TextWrapped("Grey: the vessel; orange: the sac; cyan: the neck plane and its normal; yellow: the tip.");
  ImGui::End();
  drawQuestion(c);
}

struct Frame {
  render::Renderer& renderer;
  ImGuiLayer& imgui;
  render::RenderSettings settings{};
};

bool drawFrame(Frame& f, CaseEditorControls& c, int width, int height, double dt, std::string& error) {
  const int side = sidebarOf(width);
  // The renderer's area counts from the bottom; the controls' from the top (the full height: the same).
  c.setArea(side, 0, width - side, height);
  const render::Rect area{side, 0, width - side, height};
  if (!f.renderer.render(c.view().scene, c.camera(), f.settings, width, height, area, error)) return false;
  f.imgui.newFrame(width, height, dt);
  drawPanel(c, side, height);
  f.renderer.bindFrame();
  f.imgui.render();
  return true;
}

bool writePicture(const render::Image& image, const std::string& path, std::string& error) {
  if (!render::writePng(path, image, error)) return false;
  std::printf("case edit: wrote %s (%dx%d)\n", path.c_str(), image.width, image.height);
  return true;
}

void printView(const CaseEditorControls& c, int side, int width, int height) {
  const render::Camera& k = c.camera();
  const Vec3 e = k.eye(), t = k.target, u = k.up();
  std::printf("case edit: 3D view at x %d, width %d, height %d (window pixels from the top left); camera eye %.9g "
              "%.9g %.9g m, target %.9g %.9g %.9g m, up %.9g %.9g %.9g, vertical field of view %.9g rad\n",
              side, width - side, height, e.x(), e.y(), e.z(), t.x(), t.y(), t.z(), u.x(), u.y(), u.z(), k.fovY);
  std::fflush(stdout);
}

}  // namespace

int runCaseEditorWindow(const CaseEditorHooks& hooks, const CaseEditorWindowOptions& o) {
  render::BackendOptions bo;
  bo.width = o.width, bo.height = o.height;
  bo.title = "coilsim case edit - " + hooks.title;
  const auto win = GlfwWindow::open(bo);
  if (!win) return 1;
  GLFWwindow* window = win->handle();
  Queue queue;
  int ww = 0, wh = 0;
  win->windowSize(ww, wh);
  queue.scale = ww > 0 ? double(win->framebufferWidth()) / ww : 1.0;
  glfwGetCursorPos(window, &queue.x, &queue.y);
  queue.x *= queue.scale, queue.y *= queue.scale;
  // Our callbacks first: ImGui's GLFW backend chains to them.
  glfwSetWindowUserPointer(window, &queue);
  glfwSetKeyCallback(window, onKey);
  glfwSetMouseButtonCallback(window, onButton);
  glfwSetCursorPosCallback(window, onMove);
  glfwSetScrollCallback(window, onScroll);
  if (!win->attachImGui()) return 1;
  Frame f{win->renderer(), win->imgui()};
  f.settings.samples = render::softwareRenderer() ? 0 : 4;
  CaseEditorControls c(hooks);
  std::string error;
  int exitCode = 0;
  double last = wallSeconds();
  bool told = false;
  while (true) {
    glfwPollEvents();
    if (glfwWindowShouldClose(window)) {
      glfwSetWindowShouldClose(window, 0);
      c.closeRequested();
    }
    const double now = wallSeconds(), dt = now - last;
    last = now;
    const int fbw = win->framebufferWidth(), fbh = win->framebufferHeight();
    if (fbw <= 0 || fbh <= 0) {
      glfwWaitEventsTimeout(0.05);
      continue;
    }
    c.setArea(sidebarOf(fbw), 0, fbw - sidebarOf(fbw), fbh);
    handOver(queue, c, ImGui::GetIO().WantCaptureMouse);
    if (!drawFrame(f, c, fbw, fbh, dt, error)) {
      std::fprintf(stderr, "coilsim: %s\n", error.c_str());
      exitCode = 1;
      break;
    }
    f.renderer.present(fbw, fbh);
    if (!told) printView(c, sidebarOf(fbw), fbw, fbh), told = true;
    if (c.closing() && !o.screenshotPath.empty()) {
      render::Image image;
      if (!render::Renderer::readWindowPixels(fbw, fbh, image) || !writePicture(image, o.screenshotPath, error)) {
        std::fprintf(stderr, "coilsim: could not write the window's picture %s: %s\n", o.screenshotPath.c_str(),
                     error.c_str());
        exitCode = 1;
      }
    }
    win->present();
    if (c.closing()) break;
  }
  return exitCode;
}

bool renderCaseEditorOffscreen(const CaseEditorHooks& hooks, const CaseEditorWindowOptions& o, std::string& error) {
  const auto backend = offscreenContext(o.screenshotPath, o.width, o.height, error);
  if (!backend) return false;
  render::Renderer renderer;
  ImGuiLayer imgui;
  if (!renderer.init(error) || !imgui.init(nullptr, error)) return false;
  Frame f{renderer, imgui};
  CaseEditorControls c(hooks);
  // ImGui sizes tables and auto-fitting items on their first frame: two frames.
  for (int k = 0; k < 2; ++k)
    if (!drawFrame(f, c, o.width, o.height, 1.0 / 60.0, error)) return false;
  render::Image image;
  return readBackFrame(renderer, image, error) && writePicture(image, o.screenshotPath, error);
}

}  // namespace coilsim::ui
