# Writes every shaders/*.glsl into one C++ header as raw string literals, so
# the binary does not depend on the working directory.
# Usage: cmake -DSHADER_DIR=<dir> -DOUTPUT=<header> -P embed_shaders.cmake
file(GLOB files "${SHADER_DIR}/*.glsl")
list(SORT files)
set(delimiter "coilsim_glsl")
set(body "")
foreach(f IN LISTS files)
  get_filename_component(name "${f}" NAME)
  file(READ "${f}" text)
  string(FIND "${text}" ")${delimiter}\"" clash)
  if(NOT clash EQUAL -1)
    message(FATAL_ERROR "${f} contains the raw-string delimiter )${delimiter}\"")
  endif()
  string(APPEND body "    {\"${name}\", R\"${delimiter}(${text})${delimiter}\"},\n")
endforeach()
set(content "// Generated from shaders/*.glsl by src/render/embed_shaders.cmake; do not edit.
#pragma once
#include <string_view>

namespace coilsim::render::embedded {

struct ShaderFile {
  std::string_view name;
  std::string_view source;
};

inline constexpr ShaderFile kShaderFiles[] = {
${body}};

}  // namespace coilsim::render::embedded
")
# Rewrite only on change, so that an unchanged shader set rebuilds nothing.
if(EXISTS "${OUTPUT}")
  file(READ "${OUTPUT}" old)
endif()
if(NOT "${old}" STREQUAL "${content}")
  file(WRITE "${OUTPUT}" "${content}")
endif()
