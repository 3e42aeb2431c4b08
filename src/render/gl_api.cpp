#include "render/gl_api.h"

#include <cstdio>

namespace coilsim::render {

GlFunctions gl;

namespace {
std::string description;
}

bool loadGl(GetProcAddressFn getProc, std::string& error) {
  gl = GlFunctions{};
  description.clear();
  if (!getProc) {
    error = "no GetProcAddress for the GL context";
    return false;
  }
  // Every entry point must resolve; a null one would crash much later.
#define COILSIM_GL_LOAD(type, name)                                   \
  gl.name = reinterpret_cast<type>(getProc("gl" #name));              \
  if (!gl.name) {                                                     \
    error = "OpenGL entry point gl" #name " is missing from the context"; \
    gl = GlFunctions{};                                               \
    return false;                                                     \
  }
  COILSIM_GL_FUNCTIONS(COILSIM_GL_LOAD)
#undef COILSIM_GL_LOAD

  GLint major = 0, minor = 0;
  glGetIntegerv(GL_MAJOR_VERSION, &major);
  glGetIntegerv(GL_MINOR_VERSION, &minor);
  auto text = [](GLenum what) {
    const GLubyte* s = glGetString(what);
    return s ? std::string(reinterpret_cast<const char*>(s)) : std::string("?");
  };
  const std::string version = text(GL_VERSION), renderer = text(GL_RENDERER);
  if (major * 10 + minor < 33) {
    error = "OpenGL 3.3 core is needed, the context offers " + version + " (" + renderer + ")";
    gl = GlFunctions{};
    return false;
  }
  description = version + " / " + renderer;
  return true;
}

void unloadGl() {
  gl = GlFunctions{};
  description.clear();
}

std::string glDescription() { return description; }

bool softwareRenderer() {
  for (const char* name : {"llvmpipe", "softpipe", "swrast", "Software Rasterizer"})
    if (description.find(name) != std::string::npos) return true;
  return false;
}

}  // namespace coilsim::render
