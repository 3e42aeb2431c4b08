#pragma once
// A parameter declared once: its name is the JSON key and CLI flag, its unit
// and bounds drive checks and UI widgets. Values inside the core are SI;
// `toSI` converts the edge unit (the one files and UI use) to SI.
#include <string_view>

namespace coilsim {

struct ParamSpec {
  std::string_view name;         // JSON key / CLI name, e.g. "density_g_cm3"
  std::string_view unit;         // edge unit, e.g. "g/cm3"
  std::string_view description;  // one line for help texts and tooltips
  double defaultValue;           // in the edge unit
  double min;                    // bounds, in the edge unit
  double max;
  double toSI;                   // SI value = edge value * toSI
};

}  // namespace coilsim
