#include "ui/imgui_layer.h"

#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

namespace coilsim::ui {

ImGuiLayer::~ImGuiLayer() {
  if (renderer_) ImGui_ImplOpenGL3_Shutdown();
  if (platform_) ImGui_ImplGlfw_Shutdown();
  if (context_) ImGui::DestroyContext();
}

bool ImGuiLayer::init(GLFWwindow* window, std::string& error) {
  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  context_ = true;
  ImGuiIO& io = ImGui::GetIO();
  io.IniFilename = nullptr;  // no imgui.ini next to the user's files
  ImGui::StyleColorsDark();
  ImGuiStyle& style = ImGui::GetStyle();
  style.WindowRounding = 6.0f;
  style.FrameRounding = 3.0f;
  style.Colors[ImGuiCol_WindowBg].w = 0.88f;
  if (window) {
    // install_callbacks chains to callbacks installed before, such as ours.
    if (!ImGui_ImplGlfw_InitForOpenGL(window, true)) {
      error = "ImGui could not attach to the GLFW window";
      return false;
    }
    platform_ = true;
  }
  if (!ImGui_ImplOpenGL3_Init("#version 330 core")) {
    error = "ImGui's OpenGL3 backend could not start";
    return false;
  }
  renderer_ = true;
  return true;
}

void ImGuiLayer::newFrame(int width, int height, double dt) {
  ImGui_ImplOpenGL3_NewFrame();
  if (platform_) {
    ImGui_ImplGlfw_NewFrame();
  } else {
    ImGuiIO& io = ImGui::GetIO();
    io.DisplaySize = ImVec2(float(width), float(height));
    io.DisplayFramebufferScale = ImVec2(1, 1);
    io.DeltaTime = float(dt > 0 ? dt : 1.0 / 60.0);
  }
  ImGui::NewFrame();
}

void ImGuiLayer::render() {
  ImGui::Render();
  ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
}

bool ImGuiLayer::wantsMouse() const { return ImGui::GetIO().WantCaptureMouse; }
bool ImGuiLayer::wantsKeyboard() const { return ImGui::GetIO().WantCaptureKeyboard; }

}  // namespace coilsim::ui
