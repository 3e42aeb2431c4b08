#pragma once
// One number through a printf format ("%.3g"), for messages and reports.
#include <cstdio>
#include <string>

namespace coilsim::app {

inline std::string fmt(const char* format, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, format, v);
  return buf;
}

}  // namespace coilsim::app
