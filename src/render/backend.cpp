#include "render/backend.h"

namespace coilsim::render {

std::vector<std::string> backendNames() { return {"glfw", "osmesa"}; }

std::unique_ptr<Backend> createBackend(std::string_view name, const BackendOptions& options, std::string& error) {
  if (options.width <= 0 || options.height <= 0 || options.width > 16384 || options.height > 16384) {
    error = "frame size " + std::to_string(options.width) + "x" + std::to_string(options.height) +
            " is not between 1x1 and 16384x16384";
    return nullptr;
  }
  if (name == "glfw") return createGlfwBackend(options, error);
  if (name == "osmesa") return createOsmesaBackend(options, error);
  error = "unknown render backend '" + std::string(name) + "' (known: glfw, osmesa)";
  return nullptr;
}

}  // namespace coilsim::render
