#pragma once
// The one table of coilsim's commands and their options. The parser
// (app/options.h), every help text and the bash completion (app/help.h) are
// generated from it, so an option is named, typed, bounded and explained
// once. A command's own code then reads the values the parser checked.
#include <limits>
#include <span>
#include <string_view>

namespace coilsim::app {

// What an option's value (or a command's operand) is: it decides how the
// parser checks it and what the completion offers.
enum class ValueKind {
  None,       // a flag
  Text,       // any non-empty text
  Number,     // a finite decimal number within [min, max] (or (min, max) when open)
  Integer,    // a whole number within [min, max]
  Choice,     // one of `choices` ("3d|xray|biplane")
  Size,       // WIDTHxHEIGHT in pixels, each within [min, max]
  List,       // comma separated names
  CoilList,   // catalogue coil names: a,b for candidates, a+b for a sequence
  Coil,       // one catalogue coil name
  JsonFile,   // a .json file (scene, case, timeline, session, measurement)
  MeshFile,   // STL, OBJ, PLY, OFF
  OutFile,    // a file to write
  Directory,  // a directory (read or written)
};

inline constexpr double kNoBound = std::numeric_limits<double>::infinity();

struct OptionSpec {
  std::string_view name;  // "--out"
  ValueKind kind = ValueKind::None;
  std::string_view value;  // placeholder in the usage: "FILE", "S"
  std::string_view help;   // one line; the parser adds the bounds to errors
  double min = -kNoBound, max = kNoBound;
  bool openMin = false;      // min excluded: "> 0"
  std::string_view choices;  // Choice: "a|b|c"
};

struct CommandSpec {
  std::string_view name;
  std::string_view summary;   // one line, for the command list
  std::string_view synopsis;  // usage lines after "coilsim ", '\n' between forms
  std::string_view operand;   // what its positional arguments are ("SCENE"), empty: none
  ValueKind operandKind = ValueKind::None;
  int minOperands = 0, maxOperands = 0;  // maxOperands < 0: any number
  std::span<const OptionSpec> options;
  std::string_view notes;  // further paragraphs of its help (exit codes, defaults)
};

// Every command, in the order the main help lists them.
std::span<const CommandSpec> commands();

// The command named `name`, or nullptr.
const CommandSpec* findCommand(std::string_view name);

// The option `name` ("--out") of `command`, or nullptr.
const OptionSpec* findOption(const CommandSpec& command, std::string_view name);

// Steps a run may take; a longer run is refused before it starts (exit 2).
inline constexpr long kMaxRunSteps = 100'000'000;

}  // namespace coilsim::app
