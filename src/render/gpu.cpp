#include "render/gpu.h"

#include <cstddef>
#include <cstdio>

namespace coilsim::render {

void GpuMesh::create() {
  glGenVertexArrays(1, &vao_);
  glGenBuffers(1, &vbo_);
  glGenBuffers(1, &ebo_);
  glBindVertexArray(vao_);
  glBindBuffer(GL_ARRAY_BUFFER, vbo_);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, ebo_);
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(Vertex), reinterpret_cast<void*>(offsetof(Vertex, position)));
  glEnableVertexAttribArray(1);
  glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, sizeof(Vertex), reinterpret_cast<void*>(offsetof(Vertex, normal)));
  glEnableVertexAttribArray(2);
  glVertexAttribPointer(2, 4, GL_FLOAT, GL_FALSE, sizeof(Vertex), reinterpret_cast<void*>(offsetof(Vertex, colour)));
  glBindVertexArray(0);
}

void GpuMesh::upload(const TriangleMesh& mesh) {
  if (!vao_) create();
  glBindVertexArray(vao_);
  const size_t vb = mesh.vertices.size() * sizeof(Vertex);
  glBindBuffer(GL_ARRAY_BUFFER, vbo_);
  if (vb > vertexBytes_) {
    vertexBytes_ = vb + vb / 2;
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(vertexBytes_), nullptr, GL_DYNAMIC_DRAW);
  }
  if (vb) glBufferSubData(GL_ARRAY_BUFFER, 0, GLsizeiptr(vb), mesh.vertices.data());
  glBindVertexArray(0);
  uploadIndices(mesh.indices);
}

void GpuMesh::uploadIndices(const std::vector<std::uint32_t>& indices) {
  if (!vao_) create();
  glBindVertexArray(vao_);
  const size_t ib = indices.size() * sizeof(std::uint32_t);
  if (ib > indexBytes_) {
    indexBytes_ = ib + ib / 2;
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(indexBytes_), nullptr, GL_DYNAMIC_DRAW);
  }
  if (ib) glBufferSubData(GL_ELEMENT_ARRAY_BUFFER, 0, GLsizeiptr(ib), indices.data());
  glBindVertexArray(0);
  count_ = GLsizei(indices.size());
}

void GpuMesh::draw() const {
  if (!count_) return;
  glBindVertexArray(vao_);
  glDrawElements(GL_TRIANGLES, count_, GL_UNSIGNED_INT, nullptr);
  glBindVertexArray(0);
}

void GpuMesh::destroy() {
  if (!gl.DeleteBuffers) return;  // the context is gone; nothing to free
  if (ebo_) glDeleteBuffers(1, &ebo_);
  if (vbo_) glDeleteBuffers(1, &vbo_);
  if (vao_) glDeleteVertexArrays(1, &vao_);
  vao_ = vbo_ = ebo_ = 0;
  count_ = 0;
  vertexBytes_ = indexBytes_ = 0;
}

bool RenderTarget::create(int width, int height, GLenum colourFormat, int samples, bool depth, std::string& error) {
  destroy();
  while (glGetError() != GL_NO_ERROR) {
  }  // report only this function's errors below
  width_ = width;
  height_ = height;
  samples_ = samples;
  format_ = colourFormat;
  glGenFramebuffers(1, &fbo_);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
  if (samples > 0) {
    glGenRenderbuffers(1, &colour_);
    glBindRenderbuffer(GL_RENDERBUFFER, colour_);
    glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, colourFormat, width, height);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, colour_);
  } else {
    glGenTextures(1, &texture_);
    glBindTexture(GL_TEXTURE_2D, texture_);
    const bool isFloat = colourFormat == GL_RGBA32F || colourFormat == GL_RGBA16F;
    glTexImage2D(GL_TEXTURE_2D, 0, GLint(colourFormat), width, height, 0, GL_RGBA, isFloat ? GL_FLOAT : GL_UNSIGNED_BYTE,
                 nullptr);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glBindTexture(GL_TEXTURE_2D, 0);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, texture_, 0);
  }
  if (depth) {
    glGenRenderbuffers(1, &depth_);
    glBindRenderbuffer(GL_RENDERBUFFER, depth_);
    if (samples > 0)
      glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, GL_DEPTH_COMPONENT24, width, height);
    else
      glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, width, height);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_);
  }
  glBindRenderbuffer(GL_RENDERBUFFER, 0);
  const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  if (status != GL_FRAMEBUFFER_COMPLETE || glGetError() != GL_NO_ERROR) {
    char buf[160];
    std::snprintf(buf, sizeof buf, "off-screen framebuffer %dx%d (format 0x%x, %d samples) is incomplete (status 0x%x)",
                  width, height, unsigned(colourFormat), samples, unsigned(status));
    error = buf;
    destroy();
    return false;
  }
  return true;
}

void RenderTarget::destroy() {
  if (!gl.DeleteFramebuffers) return;
  if (fbo_) glDeleteFramebuffers(1, &fbo_);
  if (texture_) glDeleteTextures(1, &texture_);
  if (colour_) glDeleteRenderbuffers(1, &colour_);
  if (depth_) glDeleteRenderbuffers(1, &depth_);
  fbo_ = texture_ = colour_ = depth_ = 0;
  width_ = height_ = 0;
}

}  // namespace coilsim::render
