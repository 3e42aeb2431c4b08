// The window: GLFW with an OpenGL 3.3 core context.
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include "render/backend.h"
#include "render/gl_loader.h"

namespace coilsim::render {
namespace {

std::string lastGlfwError;
void onGlfwError(int code, const char* text) { lastGlfwError = std::to_string(code) + ": " + text; }

GlProc glfwProc(const char* name) { return reinterpret_cast<GlProc>(glfwGetProcAddress(name)); }

class GlfwBackend final : public Backend {
 public:
  ~GlfwBackend() override {
    if (window_) glfwDestroyWindow(window_);
    unloadGl();
    if (initialised_) glfwTerminate();
  }

  bool init(const BackendOptions& o, std::string& error) {
    glfwSetErrorCallback(onGlfwError);
    if (!glfwInit()) {
      error = "cannot open a window: GLFW found no display (" + lastGlfwError + "); use the off-screen path instead";
      return false;
    }
    initialised_ = true;
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    glfwWindowHint(GLFW_SAMPLES, 0);  // anti-aliasing happens in the renderer's own target
    glfwWindowHint(GLFW_DEPTH_BITS, 0);
    window_ = glfwCreateWindow(o.width, o.height, o.title.c_str(), nullptr, nullptr);
    if (!window_) {
      error = "cannot open a window with an OpenGL 3.3 core context (" + lastGlfwError + ")";
      return false;
    }
    if (!makeCurrent(error)) return false;
    glfwSwapInterval(o.vsync ? 1 : 0);
    return true;
  }

  std::string_view name() const override { return "glfw"; }

  bool makeCurrent(std::string& error) override {
    glfwMakeContextCurrent(window_);
    if (!loadGl(glfwProc, error)) {
      error = "window: " + error;
      return false;
    }
    return true;
  }

  int framebufferWidth() const override {
    int w = 0, h = 0;
    glfwGetFramebufferSize(window_, &w, &h);
    return w;
  }
  int framebufferHeight() const override {
    int w = 0, h = 0;
    glfwGetFramebufferSize(window_, &w, &h);
    return h;
  }
  void present() override { glfwSwapBuffers(window_); }
  void* nativeWindow() override { return window_; }

 private:
  GLFWwindow* window_ = nullptr;
  bool initialised_ = false;
};

}  // namespace

std::unique_ptr<Backend> createGlfwBackend(const BackendOptions& options, std::string& error) {
  auto b = std::make_unique<GlfwBackend>();
  if (!b->init(options, error)) return nullptr;
  return b;
}

}  // namespace coilsim::render
