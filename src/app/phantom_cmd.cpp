#include "app/phantom_cmd.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <exception>
#include <filesystem>

#include "app/exit_codes.h"
#include "geometry/mesh_report.h"
#include "geometry/phantom.h"
#include "geometry/volume.h"
#include "io/mesh_file.h"

namespace coilsim::app {
namespace {

constexpr const char* kUsage =
    "usage: coilsim phantom --type sidewall|curved|bifurcation --sac-mm D [--dome-to-neck R | --neck-mm W]\n"
    "                       [--sac-height-mm H] [--lobes N] [--vessel-mm V] [--resolution-mm H]\n"
    "                       --out FILE.stl\n"
    "  D sac diameter (1-40 mm); R dome-to-neck ratio D/W (1-10, default 2); W neck width (mm);\n"
    "  H sac height along the dome axis (default D: a sphere; else an ellipsoid); N lobes (1-6);\n"
    "  V parent vessel diameter (default 4 mm); resolution: grid spacing (default 0.3 mm).\n"
    "  Writes FILE.stl (binary, mm) and FILE.phantom.json (sac centre, radii, neck plane).\n";

bool number(const std::string& s, double& out) {
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), out);
  return ec == std::errc() && end == s.data() + s.size() && std::isfinite(out);
}

}  // namespace

int runPhantomCommand(const std::vector<std::string>& args) {
  auto usage = [](const std::string& message) {
    std::fprintf(stderr, "coilsim phantom: %s\n%s", message.c_str(), kUsage);
    return kExitUsage;
  };
  geometry::PhantomSpec spec;
  std::string out;
  bool haveType = false, haveSac = false, haveRatio = false, haveNeck = false;
  for (size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    if (a == "--help" || a == "-h") {
      std::fputs(kUsage, stdout);
      return kExitOk;
    }
    if (i + 1 >= args.size() || a.rfind("--", 0) != 0) return usage("unknown argument or missing value: \"" + a + "\"");
    const std::string& v = args[++i];
    double x = 0;
    auto num = [&](double lo, double hi) {
      if (!number(v, x) || x < lo || x > hi)
        throw std::invalid_argument(a + " needs a number in [" + std::to_string(lo) + ", " + std::to_string(hi) +
                                    "], got \"" + v + "\"");
      return x;
    };
    try {
      if (a == "--type") {
        if (!geometry::parseVesselType(v, spec.vessel))
          return usage("--type needs sidewall, curved or bifurcation, got \"" + v + "\"");
        haveType = true;
      } else if (a == "--sac-mm") {
        spec.sacDiameter = num(1, 40), haveSac = true;
      } else if (a == "--dome-to-neck") {
        spec.domeToNeck = num(1, 10), haveRatio = true;
      } else if (a == "--neck-mm") {
        spec.neckWidth = num(0.1, 40), haveNeck = true;
      } else if (a == "--sac-height-mm") {
        spec.sacHeight = num(0.5, 120);
      } else if (a == "--lobes") {
        spec.lobes = int(num(1, 6));
        if (spec.lobes != x) return usage("--lobes needs a whole number in [1, 6], got \"" + v + "\"");
      } else if (a == "--vessel-mm") {
        spec.vesselDiameter = num(1, 10);
      } else if (a == "--resolution-mm") {
        spec.resolution = num(0.02, 5);
      } else if (a == "--out") {
        out = v;
      } else {
        return usage("unknown option \"" + a + "\"");
      }
    } catch (const std::invalid_argument& e) {
      return usage(e.what());
    }
  }
  if (!haveType) return usage("--type is required");
  if (!haveSac) return usage("--sac-mm is required");
  if (haveRatio && haveNeck) return usage("give --dome-to-neck or --neck-mm, not both");
  if (out.empty()) return usage("--out FILE.stl is required");
  if (std::filesystem::path(out).extension() != ".stl") return usage("--out must name an .stl file, got \"" + out + "\"");

  try {
    const geometry::Phantom p = geometry::makePhantom(spec);
    const geometry::MeshReport r = geometry::analyseMesh(p.mesh);
    if (!r.usable()) {
      std::fprintf(stderr, "coilsim phantom: the generated surface is not usable (%s); try a finer --resolution-mm\n",
                   geometry::describeProblems(r).front().c_str());
      return kExitFailure;
    }
    io::writeBinaryStl(p.mesh, out);
    const std::string sidecar = io::phantomSidecarPath(out);
    io::writePhantomSidecar(p.info, sidecar);
    std::printf("%s: %s phantom, sac %.2f x %.2f mm, neck %.2f mm, %zu triangles, volume %.1f mm^3, "
                "sac above the neck plane %.1f mm^3\n%s: sac centre and neck plane\n",
                out.c_str(), p.info.type.c_str(), 2 * p.info.sacRadii.x(), 2 * p.info.sacRadii.z(), p.info.neckWidth,
                r.triangles, r.volume, geometry::volumeAbovePlane(p.mesh, p.info.neck), sidecar.c_str());
    return kExitOk;
  } catch (const std::invalid_argument& e) {
    return usage(e.what());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "coilsim phantom: %s\n", e.what());
    return kExitUsage;
  }
}

}  // namespace coilsim::app
