#pragma once
// Reading a command line against the table of commands (app/commands.h):
// every option known, every value present, of its kind and within its
// bounds, before the command runs. Errors are UsageError (exit 2).
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "app/commands.h"

namespace coilsim::app {

// A bad command line; what() names the option and what it needed.
struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct ParsedArgs {
  const CommandSpec* command = nullptr;
  std::vector<std::string> operands;
  std::vector<std::pair<std::string, std::string>> options;  // name and value ("" for a flag), in order given
  bool help = false;                                         // --help or -h was given

  bool has(std::string_view name) const;
  // The last value given for `name`; nullopt when it was not given.
  std::optional<std::string> text(std::string_view name) const;
  std::optional<double> number(std::string_view name) const;
  std::optional<long> integer(std::string_view name) const;
  std::optional<std::pair<int, int>> size(std::string_view name) const;
  // The arguments again, "--name=value" as "--name value", for a command
  // that reads them itself after this check.
  std::vector<std::string> normalised() const;
};

// Checks `args` (after the command's name) against `command`'s table.
// Throws UsageError naming the option: unknown (with the nearest known
// one), missing its value (an option is never taken as a value: "--out
// --headless" is refused), a number with trailing text or out of bounds, a
// choice not among its choices, too few or too many operands.
ParsedArgs parseArgs(const CommandSpec& command, const std::vector<std::string>& args);

// A decimal number, all of `s`, finite; false otherwise.
bool parseNumber(std::string_view s, double& out);
// A whole number, all of `s`; false otherwise.
bool parseInteger(std::string_view s, long& out);
// "WxH" of a size option (ValueKind::Size), each within its bounds; nullopt
// otherwise, and then `why` says so as the command line's check does
// ("--size needs WIDTHxHEIGHT in pixels, each in [16, 16384], got \"8x8\"").
std::optional<std::pair<int, int>> parseSize(const OptionSpec& option, std::string_view text, std::string& why);

// What a value of this option must be: "a number > 0", "a whole number in
// [1, 256]", "a timeline file (JSON)".
std::string expectedValue(const OptionSpec& option);
// Its bounds: "> 0", "in [1, 256]", "" when it has none.
std::string boundsOf(const OptionSpec& option);

// Levenshtein distance (insertions, deletions, substitutions).
size_t editDistance(std::string_view a, std::string_view b);

// The candidate nearest to `word`, when near enough to be a typo (at most a
// third of its letters, and at least 1, wrong); "" otherwise.
std::string nearest(std::string_view word, std::span<const std::string_view> candidates);

// " (did you mean X?)" or "".
std::string didYouMean(std::string_view word, std::span<const std::string_view> candidates);

}  // namespace coilsim::app
