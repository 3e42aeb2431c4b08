#pragma once
// Writing JSON files people read: objects indented, arrays of numbers on one
// line (a node's [x, y, z] stays together), and written atomically.
#include <string>

#include <nlohmann/json.hpp>

namespace coilsim::io {

// Indented text of `value`; arrays holding only scalars stay on one line.
// Ends with a newline.
std::string formatJson(const nlohmann::json& value);
std::string formatJson(const nlohmann::ordered_json& value);  // keeps the key order

// Writes `text` to `path` through a temporary file in the same directory and
// a rename, so readers never see a half-written file. Throws std::runtime_error
// naming the path (and the system's reason) on failure; no temporary is left.
void writeFileAtomic(const std::string& path, const std::string& text);

// Empty if writeFileAtomic(path, ...) can create the file (its directory
// exists and is writable), else why not, naming the path. For commands that
// would otherwise learn it only after a long run or a whole session.
std::string whyNotWritable(const std::string& path);

}  // namespace coilsim::io
