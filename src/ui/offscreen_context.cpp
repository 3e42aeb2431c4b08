#include "ui/offscreen_context.h"

namespace coilsim::ui {

std::unique_ptr<render::Backend> offscreenContext(const std::string& path, int width, int height, std::string& error) {
  if (path.empty()) {
    error = "no screenshot path given for the off-screen render";
    return nullptr;
  }
  render::BackendOptions bo;
  bo.width = width, bo.height = height;
  return render::createBackend("osmesa", bo, error);
}

bool readBackFrame(render::Renderer& renderer, render::Image& image, std::string& error) {
  if (renderer.readFrame(image)) return true;
  error = "could not read the off-screen frame back";
  return false;
}

}  // namespace coilsim::ui
