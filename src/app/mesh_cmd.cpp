#include "app/mesh_cmd.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <exception>
#include <string>

#include "app/exit_codes.h"
#include "io/json_reader.h"
#include "io/mesh_file.h"

namespace coilsim::app {
namespace {

// Aneurysms are about 2 to 60 mm across, a head about 200 mm: a surface far
// outside that was most likely read in the wrong unit.
constexpr double kLargestPlausibleMm = 300, kSmallestPlausibleMm = 1;

// Why the surface's size (mm) is implausible, or "".
std::string sizeWarning(const TriangleMesh& mesh, double scale) {
  if (mesh.vertices.empty()) return "";
  Vec3 lo = mesh.vertices.front(), hi = lo;
  for (const Vec3& v : mesh.vertices) lo = lo.cwiseMin(v), hi = hi.cwiseMax(v);
  const double across = (hi - lo).maxCoeff();
  char buf[320];
  if (across > kLargestPlausibleMm)
    std::snprintf(buf, sizeof buf,
                  "%.4g mm across with --scale-to-mm %g: no aneurysm is that size (nor a head, ~200 mm); "
                  "is the file in mm already (--scale-to-mm 1)?", across, scale);
  else if (across < kSmallestPlausibleMm)
    std::snprintf(buf, sizeof buf,
                  "%.4g mm across with --scale-to-mm %g: smaller than any aneurysm; a file in metres needs "
                  "--scale-to-mm 1000", across, scale);
  else
    return "";
  return buf;
}

}  // namespace

int runMeshCommand(const std::vector<std::string>& args) {
  auto usage = [](const std::string& message) {
    std::fprintf(stderr, "coilsim mesh: %s\nusage: coilsim mesh FILE [--scale-to-mm S]\n", message.c_str());
    return kExitUsage;
  };
  std::string file;
  double scale = 1;
  for (size_t i = 0; i < args.size(); ++i) {
    if (args[i] == "--scale-to-mm") {
      if (i + 1 >= args.size()) return usage("--scale-to-mm needs a number > 0");
      const std::string& v = args[++i];
      const auto [end, ec] = std::from_chars(v.data(), v.data() + v.size(), scale);
      if (ec != std::errc() || end != v.data() + v.size() || !(scale > 0) || !std::isfinite(scale))
        return usage("--scale-to-mm needs a finite number > 0, got \"" + v + "\"");
    } else if (!args[i].empty() && args[i][0] == '-') {
      return usage("unknown option \"" + args[i] + "\"");
    } else if (file.empty()) {
      file = args[i];
    } else {
      return usage("one mesh file at a time, got \"" + file + "\" and \"" + args[i] + "\"");
    }
  }
  if (file.empty()) return usage("needs a mesh file (STL, OBJ, PLY, OFF)");
  try {
    const io::MeshInspection in = io::inspectMeshFile(file, scale);
    std::fputs(io::describeInspection(in).c_str(), stdout);
    if (const std::string w = sizeWarning(in.mesh, scale); !w.empty())
      std::fprintf(stderr, "coilsim mesh: warning: %s: %s\n", file.c_str(), w.c_str());
    if (!in.repaired.usable) {
      std::fprintf(stderr, "coilsim: %s: cannot be used as a wall: %s\n", file.c_str(), in.repaired.reason.c_str());
      return kExitUsage;
    }
    return kExitOk;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "coilsim: %s\n", e.what());
    return kExitUsage;
  }
}

}  // namespace coilsim::app
