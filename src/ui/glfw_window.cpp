#include "ui/glfw_window.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <cstdio>
#include <utility>

namespace coilsim::ui {

GlfwWindow::GlfwWindow(std::unique_ptr<render::Backend> backend)
    : backend_(std::move(backend)), window_(static_cast<GLFWwindow*>(backend_->nativeWindow())) {}

std::unique_ptr<GlfwWindow> GlfwWindow::open(const render::BackendOptions& options) {
  std::string error;
  auto backend = render::createBackend("glfw", options, error);
  if (!backend) {
    std::fprintf(stderr, "coilsim: %s\n", error.c_str());
    return nullptr;
  }
  std::unique_ptr<GlfwWindow> w(new GlfwWindow(std::move(backend)));
  if (!w->renderer_.init(error)) {
    std::fprintf(stderr, "coilsim: %s\n", error.c_str());
    return nullptr;
  }
  return w;
}

bool GlfwWindow::attachImGui() {
  std::string error;
  if (imgui_.init(window_, error)) return true;
  std::fprintf(stderr, "coilsim: %s\n", error.c_str());
  return false;
}

void GlfwWindow::windowSize(int& width, int& height) const {
  width = height = 0;
  glfwGetWindowSize(window_, &width, &height);
}

}  // namespace coilsim::ui
