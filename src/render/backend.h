#pragma once
// Where frames go, behind one interface and chosen by name (house style 5):
// "glfw" opens a window with an OpenGL 3.3 core context, "osmesa" renders
// off-screen through Mesa (llvmpipe). Creating a backend makes its context
// current and loads the GL function table (render/gl_api.h) for it.
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace coilsim::render {

struct BackendOptions {
  int width = 1280, height = 720;  // window or off-screen buffer size, pixels
  std::string title = "coilsim";
  bool vsync = true;               // window only
};

class Backend {
 public:
  virtual ~Backend() = default;
  virtual std::string_view name() const = 0;
  // Makes this backend's context current and reloads the GL table for it.
  virtual bool makeCurrent(std::string& error) = 0;
  // Size of the default framebuffer in pixels (a window may be resized or
  // have more pixels than screen units).
  virtual int framebufferWidth() const = 0;
  virtual int framebufferHeight() const = 0;
  // Shows the frame (swap buffers) or waits for it to finish (off-screen).
  virtual void present() = 0;
  // The GLFWwindow* of the "glfw" backend, for input; null otherwise.
  virtual void* nativeWindow() { return nullptr; }
};

// The backend called `name` ("glfw" or "osmesa"), its context current and GL
// loaded. Returns null and says why in `error`: unknown name, no display,
// no OpenGL 3.3 core context.
std::unique_ptr<Backend> createBackend(std::string_view name, const BackendOptions& options, std::string& error);

// The names createBackend knows.
std::vector<std::string> backendNames();

// Defined in backend_glfw.cpp and backend_osmesa.cpp.
std::unique_ptr<Backend> createGlfwBackend(const BackendOptions& options, std::string& error);
std::unique_ptr<Backend> createOsmesaBackend(const BackendOptions& options, std::string& error);

}  // namespace coilsim::render
