#pragma once
// GLSL programs built from the shaders embedded at build time.
#include <string>
#include <string_view>

#include "render/gl_api.h"

namespace coilsim::render {

// The text of shaders/<name> as embedded in the binary; empty if unknown.
std::string_view shaderSource(std::string_view name);

class Program {
 public:
  Program() = default;
  Program(const Program&) = delete;
  Program& operator=(const Program&) = delete;
  ~Program();
  // Compiles and links two embedded shaders. Returns false with the file
  // name and the driver's log in `error`.
  bool build(std::string_view vertexName, std::string_view fragmentName, std::string& error);
  void use() const { glUseProgram(id_); }
  GLint uniform(const char* name) const { return glGetUniformLocation(id_, name); }
  GLuint id() const { return id_; }

 private:
  GLuint id_ = 0;
};

}  // namespace coilsim::render
