#pragma once
// The OpenGL 3.3 core entry points coilsim uses, resolved at run time through
// the current context's GetProcAddress (glfwGetProcAddress or
// OSMesaGetProcAddress) into one function table of our own. libGL and
// libOSMesa both export gl* symbols, so nothing here calls either directly:
// every gl* name below is a macro for a table entry, and one binary serves
// the window and the off-screen backend.
//
// Include this instead of any GL header (after <GL/osmesa.h> where that is
// needed). The ImGui OpenGL3 backend is compiled with
// IMGUI_IMPL_OPENGL_LOADER_CUSTOM and this header force-included, so it calls
// through the same table.
#include <GL/glcorearb.h>

#include "render/gl_loader.h"

// X(PFN type, name without the gl prefix), one per entry point used by
// coilsim or by imgui_impl_opengl3.cpp.
#define COILSIM_GL_FUNCTIONS(X) \
  X(PFNGLACTIVETEXTUREPROC, ActiveTexture) \
  X(PFNGLATTACHSHADERPROC, AttachShader) \
  X(PFNGLBINDATTRIBLOCATIONPROC, BindAttribLocation) \
  X(PFNGLBINDBUFFERPROC, BindBuffer) \
  X(PFNGLBINDFRAMEBUFFERPROC, BindFramebuffer) \
  X(PFNGLBINDRENDERBUFFERPROC, BindRenderbuffer) \
  X(PFNGLBINDSAMPLERPROC, BindSampler) \
  X(PFNGLBINDTEXTUREPROC, BindTexture) \
  X(PFNGLBINDVERTEXARRAYPROC, BindVertexArray) \
  X(PFNGLBLENDEQUATIONPROC, BlendEquation) \
  X(PFNGLBLENDEQUATIONSEPARATEPROC, BlendEquationSeparate) \
  X(PFNGLBLENDFUNCPROC, BlendFunc) \
  X(PFNGLBLENDFUNCSEPARATEPROC, BlendFuncSeparate) \
  X(PFNGLBLITFRAMEBUFFERPROC, BlitFramebuffer) \
  X(PFNGLBUFFERDATAPROC, BufferData) \
  X(PFNGLBUFFERSUBDATAPROC, BufferSubData) \
  X(PFNGLCHECKFRAMEBUFFERSTATUSPROC, CheckFramebufferStatus) \
  X(PFNGLCLEARPROC, Clear) \
  X(PFNGLCLEARCOLORPROC, ClearColor) \
  X(PFNGLCLEARDEPTHPROC, ClearDepth) \
  X(PFNGLCOLORMASKPROC, ColorMask) \
  X(PFNGLCOMPILESHADERPROC, CompileShader) \
  X(PFNGLCREATEPROGRAMPROC, CreateProgram) \
  X(PFNGLCREATESHADERPROC, CreateShader) \
  X(PFNGLCULLFACEPROC, CullFace) \
  X(PFNGLDELETEBUFFERSPROC, DeleteBuffers) \
  X(PFNGLDELETEFRAMEBUFFERSPROC, DeleteFramebuffers) \
  X(PFNGLDELETEPROGRAMPROC, DeleteProgram) \
  X(PFNGLDELETERENDERBUFFERSPROC, DeleteRenderbuffers) \
  X(PFNGLDELETESHADERPROC, DeleteShader) \
  X(PFNGLDELETETEXTURESPROC, DeleteTextures) \
  X(PFNGLDELETEVERTEXARRAYSPROC, DeleteVertexArrays) \
  X(PFNGLDEPTHFUNCPROC, DepthFunc) \
  X(PFNGLDEPTHMASKPROC, DepthMask) \
  X(PFNGLDETACHSHADERPROC, DetachShader) \
  X(PFNGLDISABLEPROC, Disable) \
  X(PFNGLDRAWARRAYSPROC, DrawArrays) \
  X(PFNGLDRAWBUFFERPROC, DrawBuffer) \
  X(PFNGLDRAWELEMENTSPROC, DrawElements) \
  X(PFNGLDRAWELEMENTSBASEVERTEXPROC, DrawElementsBaseVertex) \
  X(PFNGLENABLEPROC, Enable) \
  X(PFNGLENABLEVERTEXATTRIBARRAYPROC, EnableVertexAttribArray) \
  X(PFNGLFINISHPROC, Finish) \
  X(PFNGLFLUSHPROC, Flush) \
  X(PFNGLFRAMEBUFFERRENDERBUFFERPROC, FramebufferRenderbuffer) \
  X(PFNGLFRAMEBUFFERTEXTURE2DPROC, FramebufferTexture2D) \
  X(PFNGLFRONTFACEPROC, FrontFace) \
  X(PFNGLGENBUFFERSPROC, GenBuffers) \
  X(PFNGLGENFRAMEBUFFERSPROC, GenFramebuffers) \
  X(PFNGLGENRENDERBUFFERSPROC, GenRenderbuffers) \
  X(PFNGLGENTEXTURESPROC, GenTextures) \
  X(PFNGLGENVERTEXARRAYSPROC, GenVertexArrays) \
  X(PFNGLGETATTRIBLOCATIONPROC, GetAttribLocation) \
  X(PFNGLGETERRORPROC, GetError) \
  X(PFNGLGETINTEGERVPROC, GetIntegerv) \
  X(PFNGLGETPROGRAMINFOLOGPROC, GetProgramInfoLog) \
  X(PFNGLGETPROGRAMIVPROC, GetProgramiv) \
  X(PFNGLGETSHADERINFOLOGPROC, GetShaderInfoLog) \
  X(PFNGLGETSHADERIVPROC, GetShaderiv) \
  X(PFNGLGETSTRINGPROC, GetString) \
  X(PFNGLGETSTRINGIPROC, GetStringi) \
  X(PFNGLGETUNIFORMLOCATIONPROC, GetUniformLocation) \
  X(PFNGLISENABLEDPROC, IsEnabled) \
  X(PFNGLLINKPROGRAMPROC, LinkProgram) \
  X(PFNGLPIXELSTOREIPROC, PixelStorei) \
  X(PFNGLPOLYGONMODEPROC, PolygonMode) \
  X(PFNGLREADBUFFERPROC, ReadBuffer) \
  X(PFNGLREADPIXELSPROC, ReadPixels) \
  X(PFNGLRENDERBUFFERSTORAGEPROC, RenderbufferStorage) \
  X(PFNGLRENDERBUFFERSTORAGEMULTISAMPLEPROC, RenderbufferStorageMultisample) \
  X(PFNGLSCISSORPROC, Scissor) \
  X(PFNGLSHADERSOURCEPROC, ShaderSource) \
  X(PFNGLTEXIMAGE2DPROC, TexImage2D) \
  X(PFNGLTEXPARAMETERIPROC, TexParameteri) \
  X(PFNGLUNIFORM1FPROC, Uniform1f) \
  X(PFNGLUNIFORM1IPROC, Uniform1i) \
  X(PFNGLUNIFORM2FPROC, Uniform2f) \
  X(PFNGLUNIFORM3FPROC, Uniform3f) \
  X(PFNGLUNIFORM4FPROC, Uniform4f) \
  X(PFNGLUNIFORMMATRIX4FVPROC, UniformMatrix4fv) \
  X(PFNGLUSEPROGRAMPROC, UseProgram) \
  X(PFNGLVERTEXATTRIBPOINTERPROC, VertexAttribPointer) \
  X(PFNGLVIEWPORTPROC, Viewport)

namespace coilsim::render {

struct GlFunctions {
#define COILSIM_GL_MEMBER(type, name) type name = nullptr;
  COILSIM_GL_FUNCTIONS(COILSIM_GL_MEMBER)
#undef COILSIM_GL_MEMBER
};

// The table for the context made current last by a backend. One context at
// a time: a backend reloads the table whenever it makes its context current.
extern GlFunctions gl;

}  // namespace coilsim::render

// The gl* names used in C++ code, routed through the table.
#define glActiveTexture (::coilsim::render::gl.ActiveTexture)
#define glAttachShader (::coilsim::render::gl.AttachShader)
#define glBindAttribLocation (::coilsim::render::gl.BindAttribLocation)
#define glBindBuffer (::coilsim::render::gl.BindBuffer)
#define glBindFramebuffer (::coilsim::render::gl.BindFramebuffer)
#define glBindRenderbuffer (::coilsim::render::gl.BindRenderbuffer)
#define glBindSampler (::coilsim::render::gl.BindSampler)
#define glBindTexture (::coilsim::render::gl.BindTexture)
#define glBindVertexArray (::coilsim::render::gl.BindVertexArray)
#define glBlendEquation (::coilsim::render::gl.BlendEquation)
#define glBlendEquationSeparate (::coilsim::render::gl.BlendEquationSeparate)
#define glBlendFunc (::coilsim::render::gl.BlendFunc)
#define glBlendFuncSeparate (::coilsim::render::gl.BlendFuncSeparate)
#define glBlitFramebuffer (::coilsim::render::gl.BlitFramebuffer)
#define glBufferData (::coilsim::render::gl.BufferData)
#define glBufferSubData (::coilsim::render::gl.BufferSubData)
#define glCheckFramebufferStatus (::coilsim::render::gl.CheckFramebufferStatus)
#define glClear (::coilsim::render::gl.Clear)
#define glClearColor (::coilsim::render::gl.ClearColor)
#define glClearDepth (::coilsim::render::gl.ClearDepth)
#define glColorMask (::coilsim::render::gl.ColorMask)
#define glCompileShader (::coilsim::render::gl.CompileShader)
#define glCreateProgram (::coilsim::render::gl.CreateProgram)
#define glCreateShader (::coilsim::render::gl.CreateShader)
#define glCullFace (::coilsim::render::gl.CullFace)
#define glDeleteBuffers (::coilsim::render::gl.DeleteBuffers)
#define glDeleteFramebuffers (::coilsim::render::gl.DeleteFramebuffers)
#define glDeleteProgram (::coilsim::render::gl.DeleteProgram)
#define glDeleteRenderbuffers (::coilsim::render::gl.DeleteRenderbuffers)
#define glDeleteShader (::coilsim::render::gl.DeleteShader)
#define glDeleteTextures (::coilsim::render::gl.DeleteTextures)
#define glDeleteVertexArrays (::coilsim::render::gl.DeleteVertexArrays)
#define glDepthFunc (::coilsim::render::gl.DepthFunc)
#define glDepthMask (::coilsim::render::gl.DepthMask)
#define glDetachShader (::coilsim::render::gl.DetachShader)
#define glDisable (::coilsim::render::gl.Disable)
#define glDrawArrays (::coilsim::render::gl.DrawArrays)
#define glDrawBuffer (::coilsim::render::gl.DrawBuffer)
#define glDrawElements (::coilsim::render::gl.DrawElements)
#define glDrawElementsBaseVertex (::coilsim::render::gl.DrawElementsBaseVertex)
#define glEnable (::coilsim::render::gl.Enable)
#define glEnableVertexAttribArray (::coilsim::render::gl.EnableVertexAttribArray)
#define glFinish (::coilsim::render::gl.Finish)
#define glFlush (::coilsim::render::gl.Flush)
#define glFramebufferRenderbuffer (::coilsim::render::gl.FramebufferRenderbuffer)
#define glFramebufferTexture2D (::coilsim::render::gl.FramebufferTexture2D)
#define glFrontFace (::coilsim::render::gl.FrontFace)
#define glGenBuffers (::coilsim::render::gl.GenBuffers)
#define glGenFramebuffers (::coilsim::render::gl.GenFramebuffers)
#define glGenRenderbuffers (::coilsim::render::gl.GenRenderbuffers)
#define glGenTextures (::coilsim::render::gl.GenTextures)
#define glGenVertexArrays (::coilsim::render::gl.GenVertexArrays)
#define glGetAttribLocation (::coilsim::render::gl.GetAttribLocation)
#define glGetError (::coilsim::render::gl.GetError)
#define glGetIntegerv (::coilsim::render::gl.GetIntegerv)
#define glGetProgramInfoLog (::coilsim::render::gl.GetProgramInfoLog)
#define glGetProgramiv (::coilsim::render::gl.GetProgramiv)
#define glGetShaderInfoLog (::coilsim::render::gl.GetShaderInfoLog)
#define glGetShaderiv (::coilsim::render::gl.GetShaderiv)
#define glGetString (::coilsim::render::gl.GetString)
#define glGetStringi (::coilsim::render::gl.GetStringi)
#define glGetUniformLocation (::coilsim::render::gl.GetUniformLocation)
#define glIsEnabled (::coilsim::render::gl.IsEnabled)
#define glLinkProgram (::coilsim::render::gl.LinkProgram)
#define glPixelStorei (::coilsim::render::gl.PixelStorei)
#define glPolygonMode (::coilsim::render::gl.PolygonMode)
#define glReadBuffer (::coilsim::render::gl.ReadBuffer)
#define glReadPixels (::coilsim::render::gl.ReadPixels)
#define glRenderbufferStorage (::coilsim::render::gl.RenderbufferStorage)
#define glRenderbufferStorageMultisample (::coilsim::render::gl.RenderbufferStorageMultisample)
#define glScissor (::coilsim::render::gl.Scissor)
#define glShaderSource (::coilsim::render::gl.ShaderSource)
#define glTexImage2D (::coilsim::render::gl.TexImage2D)
#define glTexParameteri (::coilsim::render::gl.TexParameteri)
#define glUniform1f (::coilsim::render::gl.Uniform1f)
#define glUniform1i (::coilsim::render::gl.Uniform1i)
#define glUniform2f (::coilsim::render::gl.Uniform2f)
#define glUniform3f (::coilsim::render::gl.Uniform3f)
#define glUniform4f (::coilsim::render::gl.Uniform4f)
#define glUniformMatrix4fv (::coilsim::render::gl.UniformMatrix4fv)
#define glUseProgram (::coilsim::render::gl.UseProgram)
#define glVertexAttribPointer (::coilsim::render::gl.VertexAttribPointer)
#define glViewport (::coilsim::render::gl.Viewport)
