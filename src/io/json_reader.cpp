#include "io/json_reader.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace coilsim::io {
namespace {

using nlohmann::json;

std::string formatNumber(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

// 1-based line and column of byte `position` (the count of bytes read when
// the parser stopped, so the offending byte is the one before it).
std::pair<size_t, size_t> lineColumn(std::string_view text, size_t position) {
  position = std::min(position, text.size());
  size_t line = 1, lineStart = 0;
  for (size_t i = 0; i + 1 < position; ++i)
    if (text[i] == '\n') ++line, lineStart = i + 1;
  return {line, position > lineStart ? position - lineStart : 1};
}

// Builds the document like nlohmann's DOM parser, but knows the JSON path of
// every value, so it can name where a duplicate key or an out-of-range
// number is (the DOM parser keeps the last duplicate silently and reports an
// overflow without a place).
class PathSax {
 public:
  PathSax(std::string_view text, const std::string& file) : text_(text), file_(file) {}

  json root;
  std::string error;

  bool null() { return insert(json(nullptr)); }
  bool boolean(bool v) { return insert(json(v)); }
  bool number_integer(json::number_integer_t v) { return insert(json(v)); }
  bool number_unsigned(json::number_unsigned_t v) { return insert(json(v)); }
  bool number_float(json::number_float_t v, const json::string_t&) { return insert(json(v)); }
  bool string(json::string_t& v) { return insert(json(std::move(v))); }
  bool binary(json::binary_t& v) { return insert(json::binary(std::move(v))); }
  bool start_object(size_t) { return open(json::object()); }
  bool start_array(size_t) { return open(json::array()); }
  bool end_object() { return close(); }
  bool end_array() { return close(); }
  bool key(json::string_t& k) {
    if (stack_.back()->contains(k)) {
      error = file_ + ": " + pathTo(pointerSegment(k)) +
              ": duplicate key (JSON keeps only one of the two values; remove one)";
      return false;
    }
    key_ = std::move(k);
    return true;
  }
  bool parse_error(size_t position, const std::string& lastToken, const nlohmann::detail::exception& ex) {
    const auto [line, column] = lineColumn(text_, position);
    const std::string at = file_ + ": line " + std::to_string(line) + ", column " + std::to_string(column) + ": ";
    if (ex.id == 406) {  // number overflow: the only out_of_range the parser reports
      error = at + pathTo(nextSegment()) + ": expected a finite number, got " + lastToken +
              " (beyond the range of a double)";
      return false;
    }
    // nlohmann's text is "[json.exception.parse_error.101] parse error at line L, column C: <what>".
    std::string what = ex.what();
    if (const size_t p = what.find("] "); p != std::string::npos) what = what.substr(p + 2);
    if (what.rfind("parse error", 0) == 0)
      if (const size_t p = what.find(": "); p != std::string::npos) what = what.substr(p + 2);
    error = at + "malformed JSON: " + what;
    return false;
  }

 private:
  std::string nextSegment() const {
    if (stack_.empty()) return {};
    return stack_.back()->is_array() ? std::to_string(stack_.back()->size()) : pointerSegment(key_);
  }
  std::string pathTo(const std::string& last) const {
    std::string p;
    for (const std::string& s : segments_) p += "/" + s;
    if (!stack_.empty()) p += "/" + last;
    return p.empty() ? "/" : p;
  }
  json* place(json&& v) {
    if (stack_.empty()) {
      root = std::move(v);
      return &root;
    }
    json& parent = *stack_.back();
    if (parent.is_array()) {
      parent.push_back(std::move(v));
      return &parent.back();
    }
    return &(parent[key_] = std::move(v));
  }
  bool insert(json&& v) {
    place(std::move(v));
    return true;
  }
  bool open(json&& container) {
    const std::string segment = nextSegment();
    // No coilsim file nests more than a few levels; a file of nothing but
    // "[[[[..." would otherwise cost memory per level (and a deep destructor).
    if (stack_.size() >= kMaxJsonDepth) {
      error = file_ + ": " + pathTo(segment) + ": nested deeper than " + std::to_string(kMaxJsonDepth) +
              " levels (arrays and objects inside each other)";
      return false;
    }
    json* p = place(std::move(container));
    if (!stack_.empty()) segments_.push_back(segment);
    stack_.push_back(p);
    return true;
  }
  bool close() {
    stack_.pop_back();
    if (!stack_.empty()) segments_.pop_back();
    return true;
  }

  std::string_view text_;
  const std::string& file_;
  std::vector<json*> stack_;           // open containers; pointers stay valid (see open())
  std::vector<std::string> segments_;  // path segment of each open container but the root
  std::string key_;                    // key of the next value in the innermost object
};

size_t editDistance(std::string_view a, std::string_view b) {
  std::vector<size_t> row(b.size() + 1);
  for (size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (size_t i = 1; i <= a.size(); ++i) {
    size_t diag = row[0];
    row[0] = i;
    for (size_t j = 1; j <= b.size(); ++j) {
      const size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diag + (a[i - 1] != b[j - 1])});
      diag = up;
    }
  }
  return row[b.size()];
}

// The allowed key a user most likely meant: the same name with a unit added
// ("length" -> "length_mm") or a small typo.
std::string_view closestKey(std::string_view key, std::span<const std::string_view> allowed) {
  for (std::string_view a : allowed)
    if (a.size() > key.size() && a.substr(0, key.size()) == key && a[key.size()] == '_') return a;
  std::string_view best;
  size_t bestDistance = 3;
  for (std::string_view a : allowed)
    if (const size_t d = editDistance(key, a); d < bestDistance) best = a, bestDistance = d;
  return best;
}

}  // namespace

std::string pointerSegment(std::string_view key) {
  std::string out;
  for (char c : key) {
    if (c == '~') out += "~0";
    else if (c == '/') out += "~1";
    else out += c;
  }
  return out;
}

std::string describeValue(const json& v) {
  if (v.is_array()) return v.empty() ? "an empty array" : "an array of " + std::to_string(v.size());
  if (v.is_object()) return v.empty() ? "an empty object" : "an object";
  std::string s = v.dump();
  if (s.size() > 48) s = s.substr(0, 44) + "...";
  return s;
}

nlohmann::json parseJson(std::string_view text, const std::string& file) {
  PathSax sax(text, file);
  const bool ok = json::sax_parse(text.begin(), text.end(), &sax);
  if (!ok || !sax.error.empty())
    throw InputError(sax.error.empty() ? file + ": malformed JSON" : sax.error);
  return std::move(sax.root);
}

nlohmann::json readJsonFile(const std::string& path) {
  // Checked before opening: a directory opens as an empty stream, which
  // would read as "malformed JSON".
  std::error_code ec;
  const std::filesystem::file_status status = std::filesystem::status(path, ec);
  if (std::filesystem::is_directory(status)) throw InputError(path + ": is a directory, not a JSON file");
  if (std::filesystem::is_regular_file(status))
    if (const auto size = std::filesystem::file_size(path, ec); !ec && size > kMaxJsonFileBytes)
      throw InputError(path + ": the file holds " + std::to_string(size) + " bytes, more than the " +
                       std::to_string(kMaxJsonFileBytes) + " an input JSON file may hold");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path + ": cannot open the file (does it exist and is it readable?)");
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw InputError(path + ": read error");
  return parseJson(text.str(), path);
}

bool Bounds::contains(double v) const {
  if (!std::isfinite(v)) return false;
  const bool aboveMin = minOpen ? v > min : v >= min;
  const bool belowMax = maxOpen ? v < max : v <= max;
  return aboveMin && belowMax;
}

std::string Bounds::describe() const {
  std::string s = "a finite number";
  const bool hasMin = std::isfinite(min), hasMax = std::isfinite(max);
  if (hasMin && hasMax)
    s += std::string(" in ") + (minOpen ? "(" : "[") + formatNumber(min) + ", " + formatNumber(max) +
         (maxOpen ? ")" : "]");
  else if (hasMin)
    s += std::string(minOpen ? " > " : " >= ") + formatNumber(min);
  else if (hasMax)
    s += std::string(maxOpen ? " < " : " <= ") + formatNumber(max);
  if (!unit.empty() && unit != "1") s.append(" ").append(unit);  // "1": a ratio, no unit to show
  return s;
}

JsonNode::JsonNode(const nlohmann::json& root, std::string file) : value_(&root), file_(std::move(file)) {}

JsonNode::JsonNode(const nlohmann::json* value, std::string file, std::string path)
    : value_(value), file_(std::move(file)), path_(std::move(path)) {}

const json& JsonNode::value() const {
  if (!value_) expected("a value");
  return *value_;
}

std::string JsonNode::where() const { return file_ + ": " + path(); }

void JsonNode::expected(std::string_view what) const {
  if (!value_) throw InputError(where() + ": missing; expected " + std::string(what));
  throw InputError(where() + ": expected " + std::string(what) + ", got " + describeValue(*value_));
}

void JsonNode::fail(std::string_view message) const { throw InputError(where() + ": " + std::string(message)); }

bool JsonNode::has(std::string_view key) const { return isObject() && value_->contains(key); }

JsonNode JsonNode::child(std::string_view key) const {
  if (!isObject()) expected("an object");
  const auto it = value_->find(key);
  return JsonNode(it == value_->end() ? nullptr : &*it, file_, path_ + "/" + pointerSegment(key));
}

std::optional<JsonNode> JsonNode::optional(std::string_view key) const {
  JsonNode c = child(key);
  if (!c.exists()) return std::nullopt;
  return c;
}

void JsonNode::allowKeys(std::span<const std::string_view> allowed) const {
  if (!isObject()) expected("an object");
  for (const auto& [key, value] : value_->items()) {
    if (std::find(allowed.begin(), allowed.end(), key) != allowed.end()) continue;
    std::string list;
    for (std::string_view a : allowed) list += (list.empty() ? "" : ", ") + std::string(a);
    std::string message = "unknown key";
    if (const std::string_view guess = closestKey(key, allowed); !guess.empty())
      message += " (did you mean \"" + std::string(guess) + "\"?)";
    message += "; allowed here: " + (list.empty() ? std::string("none") : list);
    child(key).fail(message);
  }
}

std::vector<std::string> JsonNode::keys() const {
  if (!isObject()) expected("an object");
  std::vector<std::string> out;
  for (const auto& [key, value] : value_->items()) out.push_back(key);
  return out;
}

std::vector<JsonNode> JsonNode::items(size_t minSize, size_t maxSize, std::string_view what) const {
  if (!isArray() || value_->size() < minSize || value_->size() > maxSize) expected(what);
  std::vector<JsonNode> out;
  for (size_t i = 0; i < value_->size(); ++i)
    out.push_back(JsonNode(&(*value_)[i], file_, path_ + "/" + std::to_string(i)));
  return out;
}

double JsonNode::number(const Bounds& bounds) const {
  if (!exists() || !value_->is_number()) expected(bounds.describe());
  const double v = value_->get<double>();
  if (!bounds.contains(v)) expected(bounds.describe());
  if (std::abs(v) > kMaxMagnitude)
    expected(bounds.describe() + " of magnitude <= " + formatNumber(kMaxMagnitude) +
             " (a larger value overflows once converted to SI units)");
  return v;
}

long JsonNode::integer(long min, long max) const {
  const std::string what = "an integer in [" + std::to_string(min) + ", " + std::to_string(max) + "]";
  if (!exists() || !value_->is_number()) expected(what);
  const double v = value_->get<double>();
  // 20.0 is accepted as 20: the value is the same; 20.5 is not.
  if (!std::isfinite(v) || v != std::floor(v) || v < double(min) || v > double(max)) expected(what);
  return value_->is_number_integer() ? value_->get<long>() : long(v);
}

bool JsonNode::boolean() const {
  if (!exists() || !value_->is_boolean()) expected("true or false");
  return value_->get<bool>();
}

std::string JsonNode::string(bool allowEmpty) const {
  if (!exists() || !value_->is_string()) expected(allowEmpty ? "a string" : "a non-empty string");
  std::string s = value_->get<std::string>();
  if (!allowEmpty && s.empty()) expected("a non-empty string");
  return s;
}

std::string JsonNode::oneOf(std::initializer_list<std::string_view> choices) const {
  std::string list;
  for (std::string_view c : choices) list += (list.empty() ? "\"" : ", \"") + std::string(c) + "\"";
  const std::string what = choices.size() == 1 ? list : "one of " + list;
  if (!exists() || !value_->is_string()) expected(what);
  const std::string s = value_->get<std::string>();
  if (std::find(choices.begin(), choices.end(), s) == choices.end()) expected(what);
  return s;
}

std::array<double, 3> JsonNode::vec3(const Bounds& bounds) const {
  const std::vector<JsonNode> xyz = items(3, 3, "[x, y, z]: an array of 3 numbers");
  return {xyz[0].number(bounds), xyz[1].number(bounds), xyz[2].number(bounds)};
}

}  // namespace coilsim::io
