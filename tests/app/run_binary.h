#pragma once
// Running the real `coilsim` binary from a test: a scratch directory per
// test, the exit code and both output streams, and no display (so nothing
// opens a window).
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <sys/wait.h>

#include <nlohmann/json.hpp>
#include <unistd.h>

#define EXPECT_CONTAINS(text, part) \
  EXPECT_NE(std::string(text).find(part), std::string::npos) << "  in: " << std::string(text)

namespace apptest {

namespace fs = std::filesystem;

inline const std::string kSource = COILSIM_SOURCE_DIR;

struct Exec {
  int code = -1;
  std::string out, err;
};

inline std::string slurp(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

inline std::string quote(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

// A fresh directory for one test's files, of this process alone (builds side by side run the same tests).
inline fs::path scratch(const std::string& name) {
  const fs::path dir = fs::path(testing::TempDir()) / ("coilsim_app_" + name + "." + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

// Runs coilsim with `args` and no display; stdout and stderr go to files in `dir`.
inline Exec coilsim(const std::vector<std::string>& args, const fs::path& dir) {
  std::string cmd = "env -u DISPLAY -u WAYLAND_DISPLAY " + quote(COILSIM_BINARY);
  for (const std::string& a : args) cmd.append(" ").append(quote(a));
  cmd.append(" >").append(quote((dir / "stdout.txt").string()));
  cmd.append(" 2>").append(quote((dir / "stderr.txt").string()));
  const int status = std::system(cmd.c_str());
  Exec r;
  r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.out = slurp(dir / "stdout.txt");
  r.err = slurp(dir / "stderr.txt");
  return r;
}

inline std::string scene(const std::string& name) { return kSource + "/scenes/" + name; }

inline nlohmann::json readJson(const fs::path& p) { return nlohmann::json::parse(slurp(p)); }

}  // namespace apptest
