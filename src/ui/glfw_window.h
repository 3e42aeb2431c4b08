#pragma once
// The ui's one way to open a window: render's "glfw" backend (GLFW, an
// OpenGL 3.3 core context made current), the renderer started on it and
// ImGui attached after the window's own input callbacks. Closing tears them
// down in the order GL and ImGui need: ImGui's backends first, then the
// renderer's GL objects, then the window and GLFW. The run (and practice),
// validate and case editor windows open theirs with it.
#include <memory>
#include <string>

#include "render/backend.h"
#include "render/renderer.h"
#include "ui/imgui_layer.h"

struct GLFWwindow;

namespace coilsim::ui {

class GlfwWindow {
 public:
  GlfwWindow(const GlfwWindow&) = delete;
  GlfwWindow& operator=(const GlfwWindow&) = delete;
  ~GlfwWindow() = default;

  // Opens `options.title` at `options.width` x `options.height` and starts
  // the renderer on it. On failure (no display, no OpenGL 3.3 core context,
  // no GL objects) says why on stderr ("coilsim: ...") and returns null.
  static std::unique_ptr<GlfwWindow> open(const render::BackendOptions& options);

  // Attaches ImGui. Call it after installing the window's own GLFW
  // callbacks: ImGui's backend chains to those installed before it. On
  // failure says why on stderr and returns false.
  bool attachImGui();

  GLFWwindow* handle() const { return window_; }
  render::Renderer& renderer() { return renderer_; }
  ImGuiLayer& imgui() { return imgui_; }
  // The drawable size in pixels (zero while minimised) and the window's
  // size in screen units (what the cursor and ImGui's layout count in).
  int framebufferWidth() const { return backend_->framebufferWidth(); }
  int framebufferHeight() const { return backend_->framebufferHeight(); }
  void windowSize(int& width, int& height) const;
  // Shows the frame drawn (swaps the buffers).
  void present() { backend_->present(); }

 private:
  explicit GlfwWindow(std::unique_ptr<render::Backend> backend);

  // Destroyed last to first: ImGui, the renderer, then the window.
  std::unique_ptr<render::Backend> backend_;
  GLFWwindow* window_ = nullptr;
  render::Renderer renderer_;
  ImGuiLayer imgui_;
};

}  // namespace coilsim::ui
