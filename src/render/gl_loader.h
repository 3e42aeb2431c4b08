#pragma once
// Loading the GL function table, declared without any GL header so that
// backends can include their platform headers (<GL/osmesa.h> pulls in
// <GL/gl.h>) without clashing with render/gl_api.h.
#include <string>

namespace coilsim::render {

using GlProc = void (*)();
using GetProcAddressFn = GlProc (*)(const char* name);

// Fills the table in render/gl_api.h through `getProc` for the current
// context and checks that it is OpenGL 3.3 or newer. Returns false and names
// the missing entry point or the version found in `error`.
bool loadGl(GetProcAddressFn getProc, std::string& error);

// Empties the table; backends call it when their context is destroyed, so
// that GL objects outliving it are not freed through dangling pointers.
void unloadGl();

// "4.5 (Core Profile) Mesa 22.3.6 / llvmpipe (LLVM 15.0.6, 256 bits)" or
// similar, for logs and error messages; empty before loadGl succeeded.
std::string glDescription();

// True when the current context renders in software (llvmpipe, softpipe,
// swrast), where multisampling costs several times the frame.
bool softwareRenderer();

}  // namespace coilsim::render
