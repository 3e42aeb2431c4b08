#pragma once
// Small owners of GL objects: a triangle mesh in buffers and an off-screen
// framebuffer. They need the current context that created them.
#include <string>
#include <vector>

#include "render/geometry.h"
#include "render/gl_api.h"

namespace coilsim::render {

class GpuMesh {
 public:
  GpuMesh() = default;
  GpuMesh(const GpuMesh&) = delete;
  GpuMesh& operator=(const GpuMesh&) = delete;
  ~GpuMesh() { destroy(); }
  // Replaces vertices and indices (buffers grow as needed, never shrink).
  void upload(const TriangleMesh& mesh);
  // Replaces the indices only (a re-sorted draw order).
  void uploadIndices(const std::vector<std::uint32_t>& indices);
  void draw() const;
  bool empty() const { return count_ == 0; }
  void destroy();

 private:
  void create();
  GLuint vao_ = 0, vbo_ = 0, ebo_ = 0;
  GLsizei count_ = 0;
  size_t vertexBytes_ = 0, indexBytes_ = 0;
};

// A framebuffer with one colour attachment (a texture, or a multisampled
// renderbuffer when samples > 0) and optionally a depth renderbuffer.
class RenderTarget {
 public:
  RenderTarget() = default;
  RenderTarget(const RenderTarget&) = delete;
  RenderTarget& operator=(const RenderTarget&) = delete;
  ~RenderTarget() { destroy(); }
  // Returns false and says why (the driver's status) in `error`.
  bool create(int width, int height, GLenum colourFormat, int samples, bool depth, std::string& error);
  void destroy();
  GLuint framebuffer() const { return fbo_; }
  GLuint texture() const { return texture_; }
  int width() const { return width_; }
  int height() const { return height_; }
  int samples() const { return samples_; }
  GLenum format() const { return format_; }

 private:
  GLuint fbo_ = 0, texture_ = 0, colour_ = 0, depth_ = 0;
  int width_ = 0, height_ = 0, samples_ = 0;
  GLenum format_ = 0;
};

}  // namespace coilsim::render
