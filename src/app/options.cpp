// Checking a command line against the command table (see options.h).
#include "app/options.h"

#include <algorithm>
#include <charconv>
#include <cctype>
#include <cmath>
#include <cstdio>

namespace coilsim::app {
namespace {

std::string bound(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

// "3d|xray|biplane" -> {"3d", "xray", "biplane"}.
std::vector<std::string_view> choicesOf(const OptionSpec& o) {
  std::vector<std::string_view> out;
  std::string_view c = o.choices;
  while (!c.empty()) {
    const size_t bar = c.find('|');
    out.push_back(c.substr(0, bar));
    c = bar == std::string_view::npos ? std::string_view() : c.substr(bar + 1);
  }
  return out;
}

bool inBounds(const OptionSpec& o, double v) { return (o.openMin ? v > o.min : v >= o.min) && v <= o.max; }

// A word that reads as an option rather than a value: "--headless", "-h";
// not a negative number.
// A negative number or a point with a negative first coordinate ("-6,0,5") is a value: no option name
// starts with a digit.
bool looksLikeOption(std::string_view s) {
  double d = 0;
  if (s.size() < 2 || s[0] != '-') return false;
  if (std::isdigit(static_cast<unsigned char>(s[1])) || s[1] == '.') return false;
  return !parseNumber(s, d);
}

std::vector<std::string_view> optionNames(const CommandSpec& c) {
  std::vector<std::string_view> names{"--help"};
  for (const OptionSpec& o : c.options) names.push_back(o.name);
  return names;
}

// Throws unless `value` is a valid value of `o`.
void checkValue(const CommandSpec& c, const OptionSpec& o, const std::string& value) {
  auto fail = [&] {
    throw UsageError(std::string(o.name) + " needs " + expectedValue(o) + ", got \"" + value + "\"" +
                     (c.name == "run" ? "" : " (coilsim " + std::string(c.name) + " --help)"));
  };
  double d = 0;
  long n = 0;
  switch (o.kind) {
    case ValueKind::None:
      break;
    case ValueKind::Number:
      if (!parseNumber(value, d) || !inBounds(o, d)) fail();
      break;
    case ValueKind::Integer:
      if (!parseInteger(value, n) || !inBounds(o, double(n))) fail();
      break;
    case ValueKind::Choice: {
      const auto choices = choicesOf(o);
      if (std::find(choices.begin(), choices.end(), value) == choices.end()) fail();
      break;
    }
    case ValueKind::Size: {
      std::string why;
      if (!parseSize(o, value, why)) fail();
      break;
    }
    default:
      if (value.empty()) fail();
  }
}

}  // namespace

std::optional<std::pair<int, int>> parseSize(const OptionSpec& o, std::string_view text, std::string& why) {
  const size_t x = text.find('x');
  long w = 0, h = 0;
  if (x == std::string_view::npos || !parseInteger(text.substr(0, x), w) || !parseInteger(text.substr(x + 1), h) ||
      !inBounds(o, double(w)) || !inBounds(o, double(h))) {
    why = std::string(o.name) + " needs " + expectedValue(o) + ", got \"" + std::string(text) + "\"";
    return std::nullopt;
  }
  return std::make_pair(int(w), int(h));
}

bool parseNumber(std::string_view s, double& out) {
  if (!s.empty() && s[0] == '+') s.remove_prefix(1);  // from_chars reads no '+'
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), out);
  return !s.empty() && ec == std::errc() && end == s.data() + s.size() && std::isfinite(out);
}

bool parseInteger(std::string_view s, long& out) {
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), out);
  return !s.empty() && ec == std::errc() && end == s.data() + s.size();
}

std::string boundsOf(const OptionSpec& o) {
  if (o.min == -kNoBound && o.max == kNoBound) return "";
  if (o.max == kNoBound) return (o.openMin ? "> " : ">= ") + bound(o.min);
  return "in " + std::string(o.openMin ? "(" : "[") + bound(o.min) + ", " + bound(o.max) + "]";
}

std::string expectedValue(const OptionSpec& o) {
  // "a timeline file" from the placeholder TIMELINE: the words a user reads in the usage.
  std::string what(o.value);
  for (char& ch : what) ch = char(std::tolower(static_cast<unsigned char>(ch)));
  const std::string bounds = boundsOf(o);
  switch (o.kind) {
    case ValueKind::Number:
      return "a number" + (bounds.empty() ? "" : " " + bounds);
    case ValueKind::Integer:
      return "a whole number" + (bounds.empty() ? "" : " " + bounds);
    case ValueKind::Choice: {
      const auto c = choicesOf(o);
      std::string s;
      for (size_t i = 0; i < c.size(); ++i) s += (i == 0 ? "" : i + 1 == c.size() ? " or " : ", ") + std::string(c[i]);
      return s;
    }
    case ValueKind::Size:
      return "WIDTHxHEIGHT in pixels, each in [" + bound(o.min) + ", " + bound(o.max) + "]";
    case ValueKind::JsonFile:
      return what == "file" ? "a JSON file" : "a " + what + " file (JSON)";
    case ValueKind::MeshFile:
      return "a mesh file (STL, OBJ, PLY, OFF)";
    case ValueKind::OutFile:
      return what == "file" ? "a file name" : "a " + what + " file name";
    case ValueKind::Directory:
      return "a directory";
    case ValueKind::List:
      return "a comma-separated list (" + std::string(o.value) + ")";
    case ValueKind::CoilList:
    case ValueKind::Coil:
      return "catalogue coil names (" + std::string(o.value) + "; coilsim completion coils lists them)";
    default:
      return "a value (" + std::string(o.value) + ")";
  }
}

ParsedArgs parseArgs(const CommandSpec& c, const std::vector<std::string>& args) {
  ParsedArgs p;
  p.command = &c;
  const std::vector<std::string_view> known = optionNames(c);
  for (size_t i = 0; i < args.size(); ++i) {
    const std::string& arg = args[i];
    if (arg == "--help" || arg == "-h") {
      p.help = true;
      continue;
    }
    if (!looksLikeOption(arg)) {
      p.operands.push_back(arg);
      continue;
    }
    const size_t eq = arg.find('=');
    const std::string name = arg.substr(0, eq);
    const OptionSpec* o = findOption(c, name);
    if (!o)
      throw UsageError("unknown option \"" + name + "\" for " + std::string(c.name) + didYouMean(name, known) +
                       "; coilsim " + std::string(c.name) + " --help lists its options");
    std::string value;
    if (o->kind == ValueKind::None) {
      if (eq != std::string::npos) throw UsageError(name + " takes no value, got \"" + arg + "\"");
    } else if (eq != std::string::npos) {
      value = arg.substr(eq + 1);
    } else if (i + 1 >= args.size()) {
      throw UsageError(name + " needs " + expectedValue(*o));
    } else if (looksLikeOption(args[i + 1])) {
      throw UsageError(name + " needs " + expectedValue(*o) + ", got the option \"" + args[i + 1] +
                       "\" instead (an option is never taken as a value)");
    } else {
      value = args[++i];
    }
    checkValue(c, *o, value);
    p.options.emplace_back(name, value);
  }
  if (p.help) return p;  // the usage is asked for: operands do not matter
  const std::string what = c.operand.empty() ? std::string("arguments") : std::string(c.operand);
  if (int(p.operands.size()) < c.minOperands)
    throw UsageError(std::string(c.name) + " needs " + what + " (coilsim " + std::string(c.name) + " --help)");
  if (c.maxOperands >= 0 && int(p.operands.size()) > c.maxOperands)
    throw UsageError(c.maxOperands == 0 ? std::string(c.name) + " takes no operand, got \"" + p.operands[0] + "\""
                                        : std::string(c.name) + " takes one " + what + ", got \"" + p.operands[0] +
                                              "\" and \"" + p.operands[1] + "\"");
  return p;
}

bool ParsedArgs::has(std::string_view name) const {
  return std::any_of(options.begin(), options.end(), [&](const auto& o) { return o.first == name; });
}

std::optional<std::string> ParsedArgs::text(std::string_view name) const {
  for (auto it = options.rbegin(); it != options.rend(); ++it)
    if (it->first == name) return it->second;
  return std::nullopt;
}

std::optional<double> ParsedArgs::number(std::string_view name) const {
  double d = 0;
  if (const auto t = text(name); t && parseNumber(*t, d)) return d;
  return std::nullopt;
}

std::optional<long> ParsedArgs::integer(std::string_view name) const {
  long n = 0;
  if (const auto t = text(name); t && parseInteger(*t, n)) return n;
  return std::nullopt;
}

std::optional<std::pair<int, int>> ParsedArgs::size(std::string_view name) const {
  const auto t = text(name);
  if (!t) return std::nullopt;
  const size_t x = t->find('x');
  long w = 0, h = 0;
  if (x == std::string::npos || !parseInteger(std::string_view(*t).substr(0, x), w) ||
      !parseInteger(std::string_view(*t).substr(x + 1), h))
    return std::nullopt;
  return std::make_pair(int(w), int(h));
}

std::vector<std::string> ParsedArgs::normalised() const {
  std::vector<std::string> out = operands;
  for (const auto& [name, value] : options) {
    out.push_back(name);
    const OptionSpec* o = command ? findOption(*command, name) : nullptr;
    if (o && o->kind != ValueKind::None) out.push_back(value);
  }
  return out;
}

size_t editDistance(std::string_view a, std::string_view b) {
  std::vector<size_t> row(b.size() + 1);
  for (size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (size_t i = 1; i <= a.size(); ++i) {
    size_t diagonal = row[0];
    row[0] = i;
    for (size_t j = 1; j <= b.size(); ++j) {
      const size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = up;
    }
  }
  return row[b.size()];
}

std::string nearest(std::string_view word, std::span<const std::string_view> candidates) {
  std::string_view best;
  size_t bestDistance = SIZE_MAX;
  for (std::string_view c : candidates)
    if (const size_t d = editDistance(word, c); d < bestDistance) best = c, bestDistance = d;
  const size_t letters = word.size() - std::min<size_t>(word.find_first_not_of('-'), word.size());
  const size_t allowed = std::max<size_t>(1, letters / 3);
  return bestDistance <= allowed ? std::string(best) : std::string();
}

std::string didYouMean(std::string_view word, std::span<const std::string_view> candidates) {
  const std::string n = nearest(word, candidates);
  return n.empty() ? std::string() : " (did you mean " + n + "?)";
}

}  // namespace coilsim::app
