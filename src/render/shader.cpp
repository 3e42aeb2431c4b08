#include "render/shader.h"

#include <vector>

#include "render/embedded_shaders.h"

namespace coilsim::render {

std::string_view shaderSource(std::string_view name) {
  for (const embedded::ShaderFile& f : embedded::kShaderFiles)
    if (f.name == name) return f.source;
  return {};
}

namespace {

GLuint compile(GLenum kind, std::string_view name, std::string& error) {
  const std::string_view text = shaderSource(name);
  if (text.empty()) {
    error = "shader " + std::string(name) + " is not embedded in this binary";
    return 0;
  }
  GLuint s = glCreateShader(kind);
  const char* src = text.data();
  const GLint len = GLint(text.size());
  glShaderSource(s, 1, &src, &len);
  glCompileShader(s);
  GLint ok = 0;
  glGetShaderiv(s, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    GLint n = 0;
    glGetShaderiv(s, GL_INFO_LOG_LENGTH, &n);
    std::vector<char> log(size_t(n > 1 ? n : 1), '\0');
    glGetShaderInfoLog(s, GLsizei(log.size()), nullptr, log.data());
    error = "shaders/" + std::string(name) + " does not compile: " + log.data();
    glDeleteShader(s);
    return 0;
  }
  return s;
}

}  // namespace

Program::~Program() {
  if (id_ && gl.DeleteProgram) glDeleteProgram(id_);
}

bool Program::build(std::string_view vertexName, std::string_view fragmentName, std::string& error) {
  GLuint vs = compile(GL_VERTEX_SHADER, vertexName, error);
  if (!vs) return false;
  GLuint fs = compile(GL_FRAGMENT_SHADER, fragmentName, error);
  if (!fs) {
    glDeleteShader(vs);
    return false;
  }
  GLuint p = glCreateProgram();
  glAttachShader(p, vs);
  glAttachShader(p, fs);
  glLinkProgram(p);
  glDetachShader(p, vs);
  glDetachShader(p, fs);
  glDeleteShader(vs);
  glDeleteShader(fs);
  GLint ok = 0;
  glGetProgramiv(p, GL_LINK_STATUS, &ok);
  if (!ok) {
    GLint n = 0;
    glGetProgramiv(p, GL_INFO_LOG_LENGTH, &n);
    std::vector<char> log(size_t(n > 1 ? n : 1), '\0');
    glGetProgramInfoLog(p, GLsizei(log.size()), nullptr, log.data());
    error = "shaders " + std::string(vertexName) + " + " + std::string(fragmentName) + " do not link: " + log.data();
    glDeleteProgram(p);
    return false;
  }
  if (id_) glDeleteProgram(id_);
  id_ = p;
  return true;
}

}  // namespace coilsim::render
