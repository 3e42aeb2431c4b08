#include "app/data_paths.h"

#include <cstdlib>
#include <filesystem>
#include <system_error>

#include "planning/case_file.h"

#ifndef COILSIM_SOURCE_DIR
#define COILSIM_SOURCE_DIR "."
#endif

namespace coilsim::app {
namespace {

namespace fs = std::filesystem;

// The running executable (Linux: /proc/self/exe); empty when unknown.
fs::path executable() {
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  return ec ? fs::path() : exe;
}

}  // namespace

std::string dataDirectory() {
  if (const char* env = std::getenv("COILSIM_DATA_DIR"); env && *env) return env;
  if (const fs::path exe = executable(); !exe.empty()) {
    const fs::path share = exe.parent_path().parent_path() / "share" / "coilsim";
    std::error_code ec;
    if (fs::is_directory(share / "assets" / "coils", ec)) return share.string();
  }
  return COILSIM_SOURCE_DIR;
}

void useDataDirectory() { planning::setDataDirectory(dataDirectory()); }

}  // namespace coilsim::app
