// Off-screen rendering through Mesa's OSMesa (llvmpipe): a GL 3.3 core
// context drawing into a buffer in memory.
#include <GL/osmesa.h>

#include <vector>

#include "render/backend.h"
#include "render/gl_loader.h"

namespace coilsim::render {
namespace {

GlProc osmesaProc(const char* name) { return reinterpret_cast<GlProc>(OSMesaGetProcAddress(name)); }

class OsmesaBackend final : public Backend {
 public:
  ~OsmesaBackend() override {
    if (context_) OSMesaDestroyContext(context_);
    unloadGl();
  }

  bool init(const BackendOptions& o, std::string& error) {
    width_ = o.width;
    height_ = o.height;
    // Core profile 3.3 (llvmpipe offers up to 4.5); depth and stencil in our
    // own framebuffers, so the OSMesa buffer needs neither.
    const int attribs[] = {OSMESA_FORMAT, OSMESA_RGBA, OSMESA_DEPTH_BITS, 24, OSMESA_STENCIL_BITS, 0,
                           OSMESA_ACCUM_BITS, 0, OSMESA_PROFILE, OSMESA_CORE_PROFILE,
                           OSMESA_CONTEXT_MAJOR_VERSION, 3, OSMESA_CONTEXT_MINOR_VERSION, 3, 0};
    context_ = OSMesaCreateContextAttribs(attribs, nullptr);
    if (!context_) {
      error = "OSMesa could not create an OpenGL 3.3 core context (is Mesa's llvmpipe available?)";
      return false;
    }
    buffer_.assign(size_t(width_) * height_ * 4, 0);
    return makeCurrent(error);
  }

  std::string_view name() const override { return "osmesa"; }

  bool makeCurrent(std::string& error) override {
    if (!OSMesaMakeCurrent(context_, buffer_.data(), GL_UNSIGNED_BYTE, width_, height_)) {
      error = "OSMesaMakeCurrent failed for a " + std::to_string(width_) + "x" + std::to_string(height_) + " buffer";
      return false;
    }
    if (!loadGl(osmesaProc, error)) {
      error = "OSMesa: " + error;
      return false;
    }
    return true;
  }

  int framebufferWidth() const override { return width_; }
  int framebufferHeight() const override { return height_; }
  void present() override {
    // Nothing to show: frames are read back from the renderer's own target.
  }

 private:
  OSMesaContext context_ = nullptr;
  std::vector<unsigned char> buffer_;
  int width_ = 0, height_ = 0;
};

}  // namespace

std::unique_ptr<Backend> createOsmesaBackend(const BackendOptions& options, std::string& error) {
  auto b = std::make_unique<OsmesaBackend>();
  if (!b->init(options, error)) return nullptr;
  return b;
}

}  // namespace coilsim::render
