#pragma once
// A number in the words of a report or a message (the app layer uses it too).
#include <cstdio>
#include <string>

namespace coilsim::validation {

// `v` printed with the printf format `f` (one double).
inline std::string fmt(const char* f, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, f, v);
  return buf;
}

}  // namespace coilsim::validation
