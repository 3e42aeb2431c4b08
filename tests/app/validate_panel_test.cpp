// The validation panel drawn (tests/app/CMakeLists.txt compiles this file
// only in a build with the ui layer; graphics_none_test.cpp checks that a
// build without it refuses the panel as a usage error).
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "app/run_binary.h"

namespace apptest {
namespace {

namespace fs = std::filesystem;

// The panel's one line per fit: "... stage error B1 -> A1 B2 -> A2 ...".
std::vector<std::pair<double, double>> beforeAfter(const std::string& out) {
  std::vector<std::pair<double, double>> v;
  const size_t at = out.find("stage error");
  if (at == std::string::npos) return v;
  std::istringstream in(out.substr(at + 11, out.find('\n', at) - at - 11));
  double b = 0, a = 0;
  std::string arrow;
  while (in >> b >> arrow >> a) v.emplace_back(b, a);
  return v;
}

const std::string kExample = kSource + "/examples/measurements/soft-catheter-helix.json";

// The example hides a compliant catheter (examples/measurements/README.md):
// the panel's scripted click on that toggle and its fit bring every stage's
// error down. Off-screen (OSMesa), as `--screenshot` without `--window` runs.
TEST(ValidatePanel, OffscreenToggleAndFitLowerTheError) {
  const fs::path dir = scratch("validate_panel_offscreen");
  const Exec r = coilsim({"validate", kExample, "--screenshot", (dir / "panel.png").string(), "--toggle",
                          "catheter_compliance", "--auto-fit", "--spacing", "4", "--quiet"},
                         dir);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_CONTAINS(r.out, "fit with effects [catheter_compliance]");
  const auto ba = beforeAfter(r.out);
  ASSERT_EQ(ba.size(), 3u) << r.out;
  double sumB = 0, sumA = 0;
  for (const auto& [b, a] : ba) {
    EXPECT_LT(a, b) << r.out;
    sumB += b, sumA += a;
  }
  EXPECT_LT(sumA, 0.5 * sumB) << r.out;
  EXPECT_GT(fs::file_size(dir / "panel.png"), 10000u);
}

// The real window under Xvfb: opened, toggled, fitted, its last frame written.
TEST(ValidatePanel, WindowUnderXvfbTogglesFitsAndWritesItsFrame) {
  // xvfb-run comes with Debian's xvfb, which scripts/bootstrap installs.
  ASSERT_EQ(std::system("command -v xvfb-run >/dev/null 2>&1"), 0) << "xvfb-run is missing: run scripts/bootstrap";
  const fs::path dir = scratch("validate_panel_window");
  std::string cmd = "xvfb-run -a -s '-screen 0 1400x900x24' ";
  cmd.append(quote(COILSIM_BINARY));
  for (const std::string& a : {std::string("validate"), kExample, std::string("--window"), std::string("--toggle"),
                               std::string("catheter_compliance"), std::string("--auto-fit"), std::string("--spacing"),
                               std::string("4"), std::string("--quiet"), std::string("--screenshot"),
                               (dir / "window.png").string()})
    cmd.append(" ").append(quote(a));
  cmd.append(" >").append(quote((dir / "stdout.txt").string()));
  cmd.append(" 2>").append(quote((dir / "stderr.txt").string()));
  const int status = std::system(cmd.c_str());
  const std::string out = slurp(dir / "stdout.txt"), err = slurp(dir / "stderr.txt");
  ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << err;
  const auto ba = beforeAfter(out);
  ASSERT_EQ(ba.size(), 3u) << out;
  double sumB = 0, sumA = 0;
  for (const auto& [b, a] : ba) {
    EXPECT_LT(a, b) << out;
    sumB += b, sumA += a;
  }
  EXPECT_LT(sumA, 0.5 * sumB) << out;
  EXPECT_GT(fs::file_size(dir / "window.png"), 10000u);
}

}  // namespace
}  // namespace apptest
