#pragma once
// Reading JSON input files with errors a user can act on: every message names
// the file, the place in it (a JSON pointer such as /rods/0/length_mm, or a
// line and column for malformed text) and what was expected. Shared by every
// reader of user files (scenes, measurements), each of which decides whether
// unknown keys are errors (allowKeys) or ignored.
#include <array>
#include <initializer_list>
#include <limits>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

namespace coilsim::io {

// A problem with an input file; what() is the complete, user-facing message.
class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Parses `text`; `file` only labels messages. Throws InputError on malformed
// JSON (with line and column), on a duplicate key, on a number outside the
// range of a double and on nesting deeper than kMaxJsonDepth (with its JSON path).
nlohmann::json parseJson(std::string_view text, const std::string& file);

// Reads and parses the file at `path`; throws InputError naming the path if
// it is missing, a directory, larger than kMaxJsonFileBytes or cannot be
// read, or as parseJson.
nlohmann::json readJsonFile(const std::string& path);

// The largest input JSON file read (64 MiB): far above any scene, timeline,
// measurement or session, and small enough to hold in memory.
inline constexpr size_t kMaxJsonFileBytes = size_t(64) << 20;
// The deepest nesting of arrays and objects parseJson accepts.
inline constexpr size_t kMaxJsonDepth = 256;

// The largest magnitude number() accepts (in the file's unit), whatever its
// bounds: a larger value overflows once converted to SI and multiplied
// (1e308 GPa -> inf Pa), so it is refused at its JSON path. No physical
// input of coilsim comes near it.
inline constexpr double kMaxMagnitude = 1e12;

// Allowed values of a number, in the file's unit, and how to describe them.
struct Bounds {
  double min = -std::numeric_limits<double>::infinity();
  double max = std::numeric_limits<double>::infinity();
  bool minOpen = false, maxOpen = false;  // strict inequality at that end
  std::string_view unit;                  // appended to the description, may be empty

  static Bounds any() { return {}; }
  static Bounds positive() { return {0, std::numeric_limits<double>::infinity(), true, false, {}}; }
  static Bounds nonNegative() { return {0, std::numeric_limits<double>::infinity(), false, false, {}}; }
  static Bounds closed(double lo, double hi, std::string_view unit = {}) { return {lo, hi, false, false, unit}; }
  static Bounds open(double lo, double hi) { return {lo, hi, true, true, {}}; }
  bool contains(double v) const;
  // e.g. "a finite number > 0", "a finite number in [0, 25] g/cm3"
  std::string describe() const;
};

// One value of a parsed document and where it is. A node may stand for a
// missing key: reading a value from it fails with "missing", so required
// keys need no separate check. Nodes refer into the document, which must
// outlive them.
class JsonNode {
 public:
  JsonNode(const nlohmann::json& root, std::string file);

  bool exists() const { return value_ != nullptr; }
  const nlohmann::json& value() const;  // fails unless exists()
  const std::string& file() const { return file_; }
  // JSON pointer of this node, "/" for the root.
  std::string path() const { return path_.empty() ? "/" : path_; }
  // "file: /path"
  std::string where() const;

  // Throws InputError "file: /path: expected <expected>, got <value>" (or
  // "..., but it is missing").
  [[noreturn]] void expected(std::string_view expected) const;
  // Throws InputError "file: /path: <message>".
  [[noreturn]] void fail(std::string_view message) const;

  // Objects. child() of a missing key is a missing node; child() on a
  // non-object fails. allowKeys fails on the first key not in `allowed`,
  // listing the allowed ones.
  bool isObject() const { return exists() && value_->is_object(); }
  bool has(std::string_view key) const;
  JsonNode child(std::string_view key) const;
  std::optional<JsonNode> optional(std::string_view key) const;
  void allowKeys(std::span<const std::string_view> allowed) const;
  void allowKeys(std::initializer_list<std::string_view> allowed) const {
    allowKeys(std::span<const std::string_view>(allowed.begin(), allowed.size()));
  }
  std::vector<std::string> keys() const;  // fails unless an object

  // Arrays. items() fails unless this is an array with a size in [minSize, maxSize].
  bool isArray() const { return exists() && value_->is_array(); }
  std::vector<JsonNode> items(size_t minSize = 0, size_t maxSize = std::numeric_limits<size_t>::max(),
                              std::string_view what = "an array") const;

  // Scalars; each fails with the expectation when the type or value is wrong
  // (number(): also when its magnitude exceeds kMaxMagnitude).
  double number(const Bounds& bounds = Bounds::any()) const;
  long integer(long min, long max) const;
  bool boolean() const;
  std::string string(bool allowEmpty = false) const;
  // One of `choices`; the message lists them.
  std::string oneOf(std::initializer_list<std::string_view> choices) const;
  // [x, y, z], each within bounds.
  std::array<double, 3> vec3(const Bounds& bounds = Bounds::any()) const;

 private:
  JsonNode(const nlohmann::json* value, std::string file, std::string path);
  const nlohmann::json* value_;
  std::string file_;
  std::string path_;  // JSON pointer, "" for the root
};

// Short text for a value in messages: strings quoted, containers by size,
// long values cut.
std::string describeValue(const nlohmann::json& value);

// Escapes a key for a JSON pointer segment (RFC 6901: ~ -> ~0, / -> ~1).
std::string pointerSegment(std::string_view key);

}  // namespace coilsim::io
