#pragma once
// One number through a printf format ("%.3g"), for messages and reports.
#include <cmath>
#include <cstdio>
#include <string>

#include "validation/text.h"

namespace coilsim::app {

using validation::fmt;  // one number through a printf format, as the reports word it

// A unit after a number: " GPa", nothing for a ratio (unit "1").
inline std::string unitSuffix(const std::string& unit) { return unit.empty() || unit == "1" ? "" : " " + unit; }

// "+- 0.071 GPa" for a fitted value's one-sigma uncertainty (edge units),
// or what an infinite one means: the data do not see the parameter.
inline std::string plusMinus(double sigma, const std::string& unit) {
  if (!(sigma < INFINITY)) return "(not identifiable from these data)";
  return "+- " + fmt("%.2g", sigma) + unitSuffix(unit);
}

}  // namespace coilsim::app
