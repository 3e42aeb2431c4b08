#include "io/json_writer.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <stdexcept>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace coilsim::io {
namespace {

template <class Json>
bool allScalars(const Json& a) {
  for (const auto& v : a)
    if (v.is_structured()) return false;
  return true;
}

template <class Json>
void format(const Json& v, int depth, std::string& out) {
  const std::string pad(2 * (depth + 1), ' '), closePad(2 * depth, ' ');
  if (v.is_object() && !v.empty()) {
    out += "{\n";
    size_t i = 0;
    for (const auto& [key, item] : v.items()) {
      out += pad + Json(key).dump() + ": ";
      format(item, depth + 1, out);
      out += ++i < v.size() ? ",\n" : "\n";
    }
    out += closePad + "}";
  } else if (v.is_array() && !v.empty() && !allScalars(v)) {
    out += "[\n";
    for (size_t i = 0; i < v.size(); ++i) {
      out += pad;
      format(v[i], depth + 1, out);
      out += i + 1 < v.size() ? ",\n" : "\n";
    }
    out += closePad + "]";
  } else if (v.is_array()) {
    out += "[";
    for (size_t i = 0; i < v.size(); ++i) out += (i ? ", " : "") + v[i].dump();
    out += "]";
  } else {
    out += v.dump();
  }
}

std::string systemError(const std::string& what, const std::string& path) {
  return path + ": " + what + ": " + std::strerror(errno);
}

}  // namespace

std::string formatJson(const nlohmann::json& value) {
  std::string out;
  format(value, 0, out);
  return out + "\n";
}

std::string formatJson(const nlohmann::ordered_json& value) {
  std::string out;
  format(value, 0, out);
  return out + "\n";
}

std::string whyNotWritable(const std::string& path) {
  namespace fs = std::filesystem;
  const fs::path target(path);
  const fs::path dir = target.has_parent_path() ? target.parent_path() : fs::path(".");
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) return path + ": the directory " + dir.string() + " does not exist";
  if (::access(dir.c_str(), W_OK) != 0) return systemError("cannot write in " + dir.string(), path);
  if (fs::is_directory(target, ec)) return path + ": is a directory, not a file name";
  return {};
}

void writeFileAtomic(const std::string& path, const std::string& text) {
  namespace fs = std::filesystem;
  const fs::path target(path);
  const fs::path dir = target.has_parent_path() ? target.parent_path() : fs::path(".");
  std::string hidden = ".";  // built in steps: GCC 12 warns falsely on "." + string
  hidden += target.filename().string();
  hidden += ".tmp-XXXXXX";
  std::string tmp = (dir / hidden).string();
  const int fd = mkstemp(tmp.data());
  if (fd < 0) throw std::runtime_error(systemError("cannot create a temporary file in " + dir.string(), path));
  size_t written = 0;
  while (written < text.size()) {
    const ssize_t n = ::write(fd, text.data() + written, text.size() - written);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      const std::string message = systemError("cannot write", path);
      ::close(fd);
      ::unlink(tmp.c_str());
      throw std::runtime_error(message);
    }
    written += size_t(n);
  }
  // mkstemp creates 0600; a result is an ordinary file (0644 less the umask).
  const mode_t mask = ::umask(0);
  ::umask(mask);
  ::fchmod(fd, 0666 & ~mask);
  const bool synced = ::fsync(fd) == 0;
  const bool closed = ::close(fd) == 0;
  if (!synced || !closed) {
    const std::string message = systemError("cannot write", path);
    ::unlink(tmp.c_str());
    throw std::runtime_error(message);
  }
  if (std::rename(tmp.c_str(), path.c_str()) != 0) {
    const std::string message = systemError("cannot replace", path);
    ::unlink(tmp.c_str());
    throw std::runtime_error(message);
  }
}

}  // namespace coilsim::io
