// The validation workbench window (see validation_panel.h): the panel's
// state, the background fit, the ImGui drawing and the two frame loops
// (window and off-screen).
#define GLFW_INCLUDE_NONE
#include "ui/validation_panel.h"

#include <GLFW/glfw3.h>
#include <imgui.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <mutex>
#include <optional>
#include <thread>
#include <utility>

#include "render/image.h"
#include "render/renderer.h"
#include "ui/glfw_window.h"
#include "ui/help_overlay.h"
#include "ui/imgui_layer.h"
#include "ui/layout_dump.h"
#include "ui/realtime.h"
#include "ui/validation_charts.h"
#include "ui/views.h"
#include "ui/offscreen_context.h"

namespace coilsim::ui {
namespace {

// What the panel holds between frames; the fit runs on its own thread and
// hands its progress and result over under the mutex.
class Workbench {
 public:
  explicit Workbench(const ValidationHooks& h) : hooks_(h), after_(h.after) {
    on_.assign(h.effects.size(), false);
    // The longest stage first: it shows the most of the coil.
    stage_ = h.before.stages.empty() ? 0 : h.before.stages.size() - 1;
    for (const std::string& e : h.initiallyOn) toggle(e);
  }
  ~Workbench() {
    stop_ = true;  // a closing window does not wait for the whole fit
    if (thread_.joinable()) thread_.join();
  }

  // Flips one effect's toggle; false if there is no such effect.
  bool toggle(const std::string& effect) {
    for (size_t i = 0; i < hooks_.effects.size(); ++i)
      if (hooks_.effects[i] == effect) return on_[i] = !on_[i], true;
    return false;
  }

  void startFit() {
    if (fitting_ || !hooks_.fit) return;
    if (thread_.joinable()) thread_.join();
    std::vector<std::string> effects;
    for (size_t i = 0; i < on_.size(); ++i)
      if (on_[i]) effects.push_back(hooks_.effects[i]);
    {
      std::lock_guard<std::mutex> lock(mutex_);
      live_.clear();
      evaluations_ = 0;
    }
    fitting_ = true;
    stop_ = false;
    ++fits_;
    thread_ = std::thread([this, effects] {
      ValidationView v = hooks_.fit(
          effects,
          [this](int k, double rms) {
            std::lock_guard<std::mutex> lock(mutex_);
            live_.push_back(float(rms));
            evaluations_ = k;
          },
          [this] { return stop_.load(); });
      v.effects = effects;  // what was asked, whatever the callback says
      std::lock_guard<std::mutex> lock(mutex_);
      done_ = std::move(v);
      fitting_ = false;
    });
  }

  // Takes a finished fit's result on the drawing thread.
  void poll() {
    std::lock_guard<std::mutex> lock(mutex_);
    if (!done_) return;
    after_ = std::move(*done_);
    done_.reset();
    if (after_.history.empty()) after_.history = live_;
    sceneChanged_ = true;
  }

  bool fitting() const { return fitting_; }
  int fits() const { return fits_; }
  const ValidationView& after() const { return after_; }
  // What the plots and the 3D view show: the base model until a fit, or when asked.
  bool showingBefore() const { return showBefore_ || after_.stages.empty(); }
  const ValidationView& shown() const { return showingBefore() ? hooks_.before : after_; }
  const DrawData* scene() const {
    const ValidationView& v = shown();
    return stage_ < v.scenes.size() ? &v.scenes[stage_] : nullptr;
  }
  bool takeSceneChanged() { return std::exchange(sceneChanged_, false); }

  void draw(int sidebarWidth, int width, int height);
  // Where draw() marks its controls (null: nowhere).
  void setLayout(LayoutDump* layout) { layout_ = layout; }
  // Keys as in the run and practice windows: F1 or ? shows or hides the
  // help; Esc hides it, or else asks the window to close.
  void onKey(int key, int mods) {
    if (key == GLFW_KEY_F1 || (key == GLFW_KEY_SLASH && (mods & GLFW_MOD_SHIFT))) helpOpen_ = !helpOpen_;
    else if (key == GLFW_KEY_ESCAPE && helpOpen_) helpOpen_ = false;
    else if (key == GLFW_KEY_ESCAPE && !ImGui::GetIO().WantTextInput) closeRequested_ = true;
  }
  bool closeRequested() const { return closeRequested_; }

 private:
  void drawTable();
  void drawFit();
  void drawErrorPlots();

  ValidationHooks hooks_;
  std::vector<char> on_;  // (effects) toggles; char: a vector<bool> has no bool& to hand ImGui
  ValidationView after_;
  size_t stage_ = 0;
  bool showBefore_ = false, sceneChanged_ = true;
  bool helpOpen_ = false, closeRequested_ = false;
  LayoutDump* layout_ = nullptr;
  std::thread thread_;
  std::mutex mutex_;
  std::atomic<bool> fitting_{false}, stop_{false};
  int fits_ = 0;
  std::vector<float> live_;  // RMS residual (mm) per evaluation of the running fit
  int evaluations_ = 0;
  std::optional<ValidationView> done_;
};

// The last item's rectangle in the layout dump, if there is one.
void mark(LayoutDump* layout, const char* name) {
  if (layout) layout->markLastItem(name);
}

void Workbench::drawTable() {
  const ValidationView& b = hooks_.before;
  // Short headers, the quantities named above them: the table fits the
  // 537-pixel panel of a 1280x720 window.
  ImGui::TextWrapped("Stage error before and after the fit; after it, node error (mean +- sd), mean displacement "
                     "and mean distance to the measured line, in mm:");
  if (!ImGui::BeginTable("stages", 7, ImGuiTableFlags_Borders | ImGuiTableFlags_RowBg | ImGuiTableFlags_SizingFixedFit))
    return;
  for (const char* h : {"stage", "l (mm)", "before", "after", "node error", "displ.", "dist."})
    ImGui::TableSetupColumn(h);
  // The headers one by one, so that the last one's place is known (a table
  // too wide for the panel puts it beyond the panel's edge).
  ImGui::TableNextRow(ImGuiTableRowFlags_Headers);
  int clipped = 0;  // headers narrower than their name: a table squeezed into too narrow a panel
  for (int c = 0; c < 7; ++c) {
    ImGui::TableSetColumnIndex(c);
    ImGui::TableHeader(ImGui::TableGetColumnName(c));
    clipped += ImGui::GetItemRectSize().x + 0.5f < ImGui::CalcTextSize(ImGui::TableGetColumnName(c)).x;
  }
  mark(layout_, "stages_last_column");
  if (layout_) layout_->fact("stages_clipped_headers", double(clipped));
  for (size_t k = 0; k < b.stages.size(); ++k) {
    const ValidationStageRow& s = b.stages[k];
    const ValidationStageRow* a = k < after_.stages.size() ? &after_.stages[k] : nullptr;
    ImGui::TableNextRow();
    ImGui::TableNextColumn();
    if (ImGui::Selectable(s.name.c_str(), stage_ == k, ImGuiSelectableFlags_SpanAllColumns)) {
      stage_ = k;
      sceneChanged_ = true;
    }
    ImGui::TableNextColumn();
    ImGui::Text("%.1f", s.deployedMm);
    ImGui::TableNextColumn();
    s.ok ? ImGui::Text("%.4f", s.stageError) : ImGui::TextUnformatted("failed");
    ImGui::TableNextColumn();
    if (a && a->ok) {
      const bool better = a->stageError < s.stageError;
      ImGui::TextColored(better ? ImVec4(0.5f, 1.0f, 0.5f, 1) : ImVec4(1, 0.7f, 0.4f, 1), "%.4f", a->stageError);
      ImGui::TableNextColumn();
      ImGui::Text("%.3f +- %.3f", a->nodeErrorMean, a->nodeErrorSd);
      ImGui::TableNextColumn();
      ImGui::Text("%.3f", a->meanDisplacementMm);
      ImGui::TableNextColumn();
      ImGui::Text("%.3f", a->meanDistanceMm);
    } else {
      ImGui::TextUnformatted(a ? "failed" : "-");
      for (int c = 0; c < 3; ++c) ImGui::TableNextColumn();
    }
  }
  ImGui::EndTable();
}

void Workbench::drawFit() {
  ImGui::TextUnformatted("Effects beyond the base model:");
  const bool busy = fitting_;
  if (ImGui::BeginTable("effects", 3)) {
    for (size_t i = 0; i < hooks_.effects.size(); ++i) {
      ImGui::TableNextColumn();
      bool on = on_[i];
      if (busy) ImGui::BeginDisabled();
      if (ImGui::Checkbox(hooks_.effects[i].c_str(), &on)) on_[i] = on;
      if (busy) ImGui::EndDisabled();
      if (i < hooks_.descriptions.size() && ImGui::IsItemHovered())
        ImGui::SetTooltip("%s", hooks_.descriptions[i].c_str());
    }
    ImGui::EndTable();
  }
  mark(layout_, "effects");
  if (busy) {
    if (ImGui::Button("Stop")) stop_ = true;
  } else if (ImGui::Button("Fit")) {
    startFit();
  }
  mark(layout_, "fit");
  ImGui::SameLine();
  std::vector<float> history;
  int evaluations = 0;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    history = busy || after_.history.empty() ? live_ : after_.history;
    evaluations = busy ? evaluations_ : int(history.size());
  }
  const float fraction = std::min(1.0f, float(evaluations) / float(std::max(1, hooks_.maxEvaluations)));
  char label[96];
  std::snprintf(label, sizeof label, busy ? "fitting: evaluation %d" : "%d evaluations", evaluations);
  ImGui::ProgressBar(busy ? fraction : (fits_ > 0 ? 1.0f : 0.0f), ImVec2(-1, 0), label);
  mark(layout_, "progress");
  float top = 0;
  for (float h : history) top = std::max(top, h);
  char title[96] = "RMS residual per coordinate (mm)";
  if (!history.empty())
    std::snprintf(title, sizeof title, "RMS residual (mm): %.4f, first %.4f", history.back(), history.front());
  if (history.empty()) {
    ImGui::TextDisabled("RMS residual (mm) per optimiser evaluation: no fit yet");
  } else {
    std::vector<float> index(history.size());
    for (size_t i = 0; i < index.size(); ++i) index[i] = float(i + 1);
    ChartAxes axes{"optimiser evaluation", "RMS residual (mm)", 1.0f, float(std::max<size_t>(history.size(), 2)),
                   0.0f, 1.1f * top + 1e-6f, true};
    drawLineChart("##iterations", index, history, axes, title, 0.0f, 110.0f);
  }
  if (!after_.ok) ImGui::TextColored(ImVec4(1, 0.4f, 0.4f, 1), "fit failed: %s", after_.message.c_str());
  if (stop_ && busy) ImGui::TextUnformatted("stopping after this evaluation...");
  if (!after_.effects.empty() || !after_.fitted.empty()) {
    std::string on;
    for (const std::string& e : after_.effects) on += (on.empty() ? "" : ", ") + e;
    ImGui::Text("After: effects %s", on.empty() ? "none" : on.c_str());
    // Wrapped: an effect's parameter name with its value and sigma is wider than the panel.
    for (const std::string& f : after_.fitted) {
      ImGui::Bullet();
      ImGui::TextWrapped("%s", f.c_str());
    }
  }
}

void Workbench::drawErrorPlots() {
  const ValidationView& v = shown();
  float top = 0;
  for (const ValidationStageRow& s : v.stages) {
    top = std::max(top, s.noiseFloorMm);
    for (float e : s.errorMm) top = std::max(top, e);
  }
  ImGui::TextWrapped("Node error |x_sim - x_meas| (mm) against arc length (mm), %s; one scale for all stages; "
                     "dashed: the noise floor sqrt(3) point_sigma.",
                     showingBefore() ? "before" : "after");
  float arcMax = 1;
  for (const ValidationStageRow& s : v.stages)
    if (!s.arcMm.empty()) arcMax = std::max(arcMax, s.arcMm.back());
  for (const ValidationStageRow& s : v.stages) {
    char title[160];
    const float peak = s.errorMm.empty() ? 0.0f : *std::max_element(s.errorMm.begin(), s.errorMm.end());
    std::snprintf(title, sizeof title, "%s: peak %.3f mm, noise %.3f mm", s.name.c_str(), double(peak),
                  double(s.noiseFloorMm));
    const ChartAxes axes{"arc length s (mm)", "node error (mm)", 0.0f, arcMax, 0.0f, 1.1f * top + 1e-6f};
    drawLineChart(("##arc" + s.name).c_str(), s.arcMm, s.errorMm, axes, title, s.noiseFloorMm, 92.0f);
  }
}

void Workbench::draw(int sidebarWidth, int width, int height) {
  ImGui::SetNextWindowPos(ImVec2(0, 0));
  ImGui::SetNextWindowSize(ImVec2(float(sidebarWidth), float(height)));
  ImGui::Begin("Validation", nullptr, ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse);
  ImGui::TextWrapped("%s", hooks_.title.c_str());
  ImGui::Separator();
  drawTable();
  mark(layout_, "stages");
  ImGui::Separator();
  drawFit();
  ImGui::Separator();
  if (ImGui::Checkbox("show the base model (before)", &showBefore_)) sceneChanged_ = true;
  mark(layout_, "show_before");
  drawErrorPlots();
  ImGui::Separator();
  const ValidationView& v = shown();
  if (stage_ < v.stages.size()) {
    const ValidationStageRow& s = v.stages[stage_];
    const float peak = s.errorMm.empty() ? 0.0f : *std::max_element(s.errorMm.begin(), s.errorMm.end());
    ImGui::TextWrapped("3D (%s): %s (peak %.3f mm), the coil coloured by node error, the measured centre line grey, "
                       "the catheter's last 5 mm dark. Drag to orbit, wheel to zoom; click a stage in the table to see it.",
                       showingBefore() ? "before" : "after", s.name.c_str(), double(peak));
    drawErrorColourScale(hooks_.errorScale);
  }
  ImGui::TextDisabled("F1 or ?: every key and mouse action; Esc closes the window");
  if (layout_) {
    const ImVec2 p = ImGui::GetWindowPos(), s = ImGui::GetWindowSize();
    layout_->mark("panel", p.x, p.y, p.x + s.x, p.y + s.y);
    layout_->fact("fitting", bool(fitting_));
    layout_->fact("fits", double(fits_));
    layout_->fact("help_open", helpOpen_);
  }
  ImGui::End();
  if (helpOpen_)
    drawHelpOverlay("Keys and mouse (F1)###help", validateWindowHelp(), float(sidebarWidth), float(width),
                    float(height), layout_);
}

struct Frame {
  render::Renderer& renderer;
  ImGuiLayer& imgui;
  Views views{};
  render::RenderSettings settings{};
};

int sidebarOf(int width) { return std::min(std::max(int(0.42 * width), 420), 620); }

bool drawFrame(Frame& f, Workbench& w, int width, int height, double dt, std::string& error) {
  const int side = sidebarOf(width);
  const render::Rect area{side, 0, width - side, height};
  static const DrawData empty;
  const DrawData& scene = w.scene() ? *w.scene() : empty;
  if (w.takeSceneChanged()) f.views.fit(render::boundsOf(scene), area.width, area.height);
  f.settings.drawPoints = false;
  if (!f.renderer.render(scene, f.views.camera(), f.settings, width, height, area, error)) return false;
  f.imgui.newFrame(width, height, dt);
  w.draw(side, width, height);
  f.renderer.bindFrame();
  f.imgui.render();
  return true;
}

// Mouse over the scene: drag orbits, the wheel zooms.
void steerCamera(Frame& f, int sidebar) {
  const ImGuiIO& io = ImGui::GetIO();
  if (io.WantCaptureMouse || io.MousePos.x < float(sidebar)) return;
  if (io.MouseDown[0]) f.views.camera().orbit(-0.01 * io.MouseDelta.x, 0.01 * io.MouseDelta.y);
  if (io.MouseWheel != 0) f.views.camera().zoom(std::pow(1.1, double(io.MouseWheel)));
}

bool applyScript(Workbench& w, const ValidationWindowOptions& o, std::string& error) {
  for (const std::string& e : o.toggle)
    if (!w.toggle(e)) {
      error = "no effect called '" + e + "' to toggle";
      return false;
    }
  if (o.autoFit) w.startFit();
  return true;
}

bool writeImage(const render::Image& image, const std::string& path, std::string& error) {
  if (!render::writePng(path, image, error)) return false;
  std::printf("coilsim: wrote %s (%dx%d)\n", path.c_str(), image.width, image.height);
  return true;
}

}  // namespace

int runValidationWindow(const ValidationHooks& hooks, const ValidationWindowOptions& o) {
  render::BackendOptions bo;
  bo.width = o.width, bo.height = o.height;
  bo.title = "coilsim validate - " + hooks.title;
  const auto win = GlfwWindow::open(bo);
  if (!win) return 1;
  GLFWwindow* window = win->handle();
  Workbench w(hooks);
  LayoutDump layout(LayoutDump::pathFromEnvironment());
  if (layout.enabled()) w.setLayout(&layout);
  // Keys through a GLFW callback, installed before ImGui's (which chains to
  // it): a key pressed and released within one frame is still seen.
  glfwSetWindowUserPointer(window, &w);
  glfwSetKeyCallback(window, [](GLFWwindow* win, int key, int, int action, int mods) {
    if (action == GLFW_PRESS) static_cast<Workbench*>(glfwGetWindowUserPointer(win))->onKey(key, mods);
  });
  if (!win->attachImGui()) return 1;
  Frame f{win->renderer(), win->imgui()};
  std::string error;
  if (!applyScript(w, o, error)) {
    std::fprintf(stderr, "coilsim: %s\n", error.c_str());
    return 2;
  }
  const bool scripted = !o.screenshotPath.empty();
  const double start = wallSeconds();
  double last = start;
  int exitCode = 0, framesAfterFit = 0;
  while (!glfwWindowShouldClose(window) && !w.closeRequested()) {
    glfwPollEvents();
    const double now = wallSeconds(), dt = now - last;
    last = now;
    w.poll();
    const int fbw = win->framebufferWidth(), fbh = win->framebufferHeight();
    if (fbw <= 0 || fbh <= 0) {
      glfwWaitEventsTimeout(0.05);
      continue;
    }
    int ww = 0, wh = 0;
    win->windowSize(ww, wh);
    layout.begin(float(ww), float(wh));
    if (!drawFrame(f, w, fbw, fbh, dt, error)) {
      std::fprintf(stderr, "coilsim: %s\n", error.c_str());
      exitCode = 1;
      break;
    }
    if (!layout.write(error)) {
      std::fprintf(stderr, "coilsim: %s\n", error.c_str());
      layout = LayoutDump("");  // said once; the window goes on
      w.setLayout(nullptr);
    }
    steerCamera(f, sidebarOf(fbw));
    f.renderer.present(fbw, fbh);
    // A scripted run closes two frames after its fit (ImGui lays a new table out once).
    if (scripted && !w.fitting() && (!o.autoFit || w.fits() > 0) && ++framesAfterFit > 2) {
      render::Image image;
      if (!render::Renderer::readWindowPixels(fbw, fbh, image) || !writeImage(image, o.screenshotPath, error)) {
        std::fprintf(stderr, "coilsim: could not write the window's picture %s: %s\n", o.screenshotPath.c_str(),
                     error.c_str());
        exitCode = 1;
      }
      if (!w.after().ok) exitCode = 1;
      glfwSetWindowShouldClose(window, 1);
    }
    if (scripted && now - start > o.wallLimitSeconds) {
      std::fprintf(stderr, "coilsim: the scripted fit did not end within %.0f s\n", o.wallLimitSeconds);
      exitCode = 1;
      glfwSetWindowShouldClose(window, 1);
    }
    win->present();
  }
  return exitCode;
}

bool renderValidationOffscreen(const ValidationHooks& hooks, const ValidationWindowOptions& o, std::string& error) {
  const auto backend = offscreenContext(o.screenshotPath, o.width, o.height, error);
  if (!backend) return false;
  render::Renderer renderer;
  ImGuiLayer imgui;
  if (!renderer.init(error) || !imgui.init(nullptr, error)) return false;
  Frame f{renderer, imgui};
  Workbench w(hooks);
  LayoutDump layout(LayoutDump::pathFromEnvironment());
  if (layout.enabled()) w.setLayout(&layout);
  if (!applyScript(w, o, error)) return false;
  while (w.fitting()) std::this_thread::sleep_for(std::chrono::milliseconds(20));
  w.poll();
  // ImGui sizes tables and auto-fitting items on their first frame: two frames.
  for (int k = 0; k < 2; ++k) {
    layout.begin(float(o.width), float(o.height));
    if (!drawFrame(f, w, o.width, o.height, 1.0 / 60.0, error)) return false;
  }
  if (!layout.write(error)) return false;
  render::Image image;
  if (!readBackFrame(renderer, image, error) || !writeImage(image, o.screenshotPath, error)) return false;
  if (!w.after().ok) {
    error = "the fit failed: " + w.after().message;
    return false;
  }
  return true;
}

}  // namespace coilsim::ui
