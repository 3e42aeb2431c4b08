#pragma once
// A parameter declared once: its name is the JSON key and CLI flag, its unit
// and bounds drive checks and UI widgets. Values inside the core are SI;
// `toSI` converts the edge unit (the one files and UI use) to SI.
#include <cstddef>
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

// The index of the parameter called `name` in a table, found at compile
// time: effects read their values as values[paramIndex(kParams, "name")],
// so reordering a table cannot silently change the physics, and a name that
// is not in the table does not compile.
template <std::size_t N>
consteval std::size_t paramIndex(const ParamSpec (&specs)[N], std::string_view name) {
  for (std::size_t i = 0; i < N; ++i)
    if (specs[i].name == name) return i;
  throw "no parameter of that name in this table";  // not a constant expression: a compile error
}

}  // namespace coilsim
