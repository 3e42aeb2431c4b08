#pragma once
// One ImGui context with the OpenGL3 renderer backend (compiled in
// coilsim::render against our GL loader) and, in the window, the GLFW
// platform backend. Off-screen there is no platform: display size and time
// step are set by hand, so the panel is drawn as in the window.
#include <string>

struct GLFWwindow;

namespace coilsim::ui {

class ImGuiLayer {
 public:
  ImGuiLayer() = default;
  ImGuiLayer(const ImGuiLayer&) = delete;
  ImGuiLayer& operator=(const ImGuiLayer&) = delete;
  ~ImGuiLayer();

  // Needs the current GL context. `window` may be null (off-screen).
  // Returns false with the reason in `error`.
  bool init(GLFWwindow* window, std::string& error);
  // Starts a frame of width x height pixels (used only without a window).
  void newFrame(int width, int height, double dt);
  // Ends the frame and draws it into the bound framebuffer.
  void render();
  // Whether ImGui wants the mouse or keyboard for itself this frame.
  bool wantsMouse() const;
  bool wantsKeyboard() const;

 private:
  bool context_ = false, platform_ = false, renderer_ = false;
};

}  // namespace coilsim::ui
