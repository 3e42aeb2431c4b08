#include "app/case_cmd.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <exception>

#include "app/graphics.h"
#include "app/exit_codes.h"
#include "io/json_reader.h"
#include "io/json_writer.h"
#include "planning/case_editor.h"
#include "planning/case_maker.h"

namespace coilsim::app {
namespace {

constexpr const char* kUsage =
    "usage: coilsim case new SURFACE --out CASE.json [--sac-point X,Y,Z] [--catalogue DIR]\n"
    "  SURFACE: a closed vessel surface in mm (STL, OBJ, PLY, OFF) with one aneurysm;\n"
    "  finds the sac and its neck, measures the sac, sizes the first coil, places the\n"
    "  catheter tip inside the neck and writes a case for coilsim plan and practice.\n"
    "  --sac-point: a point inside the sac (mm), when the search finds several or none.\n"
    "       coilsim case edit CASE.json [--neck-shift MM] [--neck-through X,Y,Z] [--tip X,Y,Z] --out NEW.json\n"
    "  moves the neck plane (along its normal, or through a point) and the catheter tip,\n"
    "  prints the morphology again and writes the edited case.\n"
    "       coilsim case edit CASE.json --window [--out NEW.json] [--screenshot PNG]\n"
    "  the same in a window (coilsim help case: the keys and the mouse); Ctrl+S saves to\n"
    "  --out, or over CASE.json after asking. --screenshot without --window: the editor's\n"
    "  view off-screen, as a picture.\n";

bool parsePoint(const std::string& s, Vec3& p) {
  const char* at = s.data();
  const char* end = s.data() + s.size();
  for (int k = 0; k < 3; ++k) {
    double x = 0;
    const auto [next, ec] = std::from_chars(at, end, x);
    if (ec != std::errc() || !std::isfinite(x)) return false;
    p[k] = x;
    at = next;
    if (k < 2) {
      if (at == end || *at != ',') return false;
      ++at;
    }
  }
  return at == end;
}

void printMorphology(const planning::MadeCase& c) {
  const geometry::SacMorphology& m = c.morphology;
  std::printf("sac: centre (%.2f, %.2f, %.2f) mm, inscribed radius %.2f mm\n", c.sac.centre.x(), c.sac.centre.y(),
              c.sac.centre.z(), c.sac.radius);
  std::printf("neck plane: point (%.2f, %.2f, %.2f) mm, normal into the sac (%.3f, %.3f, %.3f)\n", m.neckCentre.x(),
              m.neckCentre.y(), m.neckCentre.z(), c.sac.neck.normal.x(), c.sac.neck.normal.y(), c.sac.neck.normal.z());
  std::printf("parent vessel: diameter %.2f mm at (%.2f, %.2f, %.2f)\n", 2 * c.sac.vesselRadius, c.sac.vesselPoint.x(),
              c.sac.vesselPoint.y(), c.sac.vesselPoint.z());
  std::printf("morphology:\n"
              "  sac volume        %8.1f mm^3\n"
              "  max diameter      %8.2f mm\n"
              "  mean diameter     %8.2f mm  (dome height, width, depth: %.2f, %.2f, %.2f)\n"
              "  neck width        %8.2f mm  (neck area %.1f mm^2)\n"
              "  dome height       %8.2f mm\n"
              "  aspect ratio      %8.2f\n"
              "  dome-to-neck      %8.2f\n"
              "  size ratio        %8.2f\n",
              m.volume, m.maxDiameter, m.meanDiameter, m.domeHeight, m.width, m.depth, m.neckWidth, m.neckArea,
              m.domeHeight, m.aspectRatio, m.domeToNeck, m.sizeRatio);
  std::printf("first coil: %s\n  nearest in the catalogue:", c.firstCoil.rule.c_str());
  for (const std::string& n : c.firstCoil.neighbours) std::printf(" %s", n.c_str());
  std::printf("\ncatheter tip (%.2f, %.2f, %.2f) mm, pointing (%.3f, %.3f, %.3f)\n", c.catheter.tip.x(),
              c.catheter.tip.y(), c.catheter.tip.z(), c.catheter.direction.x(), c.catheter.direction.y(),
              c.catheter.direction.z());
}

int runNew(const std::vector<std::string>& args) {
  auto usage = [](const std::string& message) {
    std::fprintf(stderr, "coilsim case new: %s\n%s", message.c_str(), kUsage);
    return kExitUsage;
  };
  planning::CaseRequest r;
  for (size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    const bool valued = a == "--out" || a == "--sac-point" || a == "--catalogue";
    if (valued && i + 1 >= args.size()) return usage(a + " needs a value");
    if (a == "--out") {
      r.out = args[++i];
    } else if (a == "--sac-point") {
      Vec3 p;
      if (!parsePoint(args[++i], p)) return usage("--sac-point needs three numbers x,y,z in mm, got \"" + args[i] + "\"");
      r.sacPoint = p;
    } else if (a == "--catalogue") {
      r.catalogue = args[++i];
    } else if (!a.empty() && a[0] == '-') {
      return usage("unknown option \"" + a + "\"");
    } else if (r.surface.empty()) {
      r.surface = a;
    } else {
      return usage("one surface at a time, got \"" + r.surface + "\" and \"" + a + "\"");
    }
  }
  if (r.surface.empty()) return usage("needs a surface file");
  if (r.out.empty()) return usage("needs --out CASE.json");
  if (const std::string why = io::whyNotWritable(r.out); !why.empty()) return usage(why);
  try {
    const planning::MadeCase c = planning::makeCase(r);
    printMorphology(c);
    io::writeFileAtomic(r.out, io::formatJson(c.document));
    std::printf("wrote %s (coilsim plan %s --out DIR compares its coils)\n", r.out.c_str(), r.out.c_str());
    return kExitOk;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "coilsim case new: %s\n", e.what());
    return kExitUsage;
  }
}

void printEdited(const planning::CaseEditor& e) {
  const geometry::SacMorphology& m = e.morphology();
  std::printf("neck plane: point (%.2f, %.2f, %.2f) mm, normal (%.3f, %.3f, %.3f)\n", e.neck().point.x(), e.neck().point.y(),
              e.neck().point.z(), e.neck().normal.x(), e.neck().normal.y(), e.neck().normal.z());
  std::printf("sac volume %.1f mm^3, neck width %.2f mm, dome height %.2f mm, mean diameter %.2f mm, aspect ratio %.2f, "
              "dome-to-neck %.2f\n",
              m.volume, m.neckWidth, m.domeHeight, m.meanDiameter, m.aspectRatio, m.domeToNeck);
}

int runEdit(const std::vector<std::string>& args) {
  auto usage = [](const std::string& message) {
    std::fprintf(stderr, "coilsim case edit: %s\n%s", message.c_str(), kUsage);
    return kExitUsage;
  };
  std::string file, out, screenshot;
  bool window = false;
  std::vector<std::pair<std::string, std::string>> edits;  // in the order given
  for (size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    if (a == "--window") {
      window = true;
    } else if (a == "--out" || a == "--neck-shift" || a == "--neck-through" || a == "--tip" || a == "--screenshot") {
      if (i + 1 >= args.size()) return usage(a + " needs a value");
      if (a == "--out") out = args[++i];
      else if (a == "--screenshot") screenshot = args[++i];
      else edits.emplace_back(a, args[++i]);
    } else if (!a.empty() && a[0] == '-') {
      return usage("unknown option \"" + a + "\"");
    } else if (file.empty()) {
      file = a;
    } else {
      return usage("one case at a time, got \"" + file + "\" and \"" + a + "\"");
    }
  }
  if (file.empty()) return usage("needs a case file");
  if (out.empty() && !window && screenshot.empty()) return usage("needs --out NEW.json (or --window)");
  for (const std::string& path : {out, screenshot})
    if (!path.empty())
      if (const std::string why = io::whyNotWritable(path); !why.empty()) return usage(why);
  if ((window || !screenshot.empty()) && !haveUi())
    return usage("this build has no window or screenshots (no ui layer)");
  try {
    planning::CaseEditor e(file);
    for (const auto& [option, value] : edits) {
      Vec3 p;
      double mm = 0;
      bool ok = false;
      if (option == "--neck-shift") {
        const auto [end, ec] = std::from_chars(value.data(), value.data() + value.size(), mm);
        if (ec != std::errc() || end != value.data() + value.size()) return usage("--neck-shift needs a number of mm");
        ok = e.moveNeck(mm);
      } else {
        if (!parsePoint(value, p)) return usage(option + " needs three numbers x,y,z in mm, got \"" + value + "\"");
        ok = option == "--tip" ? e.placeTip(p) : e.placeNeckThrough(p);
      }
      if (!ok) {
        std::fprintf(stderr, "coilsim case edit: %s: %s %s refused: %s\n", file.c_str(), option.c_str(), value.c_str(),
                     e.refusal().c_str());
        return kExitUsage;
      }
    }
    printEdited(e);
    if (window || !screenshot.empty()) {
      const int code = caseEditorGraphics(e, file, out.empty() ? file : out, window, screenshot);
      if (code >= 0) return code;
      if (out.empty()) return kExitOk;
    }
    e.save(out);
    std::printf("wrote %s\n", out.c_str());
    return kExitOk;
  } catch (const std::exception& ex) {
    std::fprintf(stderr, "coilsim case edit: %s\n", ex.what());
    return kExitUsage;
  }
}

}  // namespace

int runCaseCommand(const std::vector<std::string>& args) {
  if (args.empty() || args[0] == "--help" || args[0] == "-h") {
    std::fputs(kUsage, args.empty() ? stderr : stdout);
    return args.empty() ? kExitUsage : kExitOk;
  }
  const std::vector<std::string> rest(args.begin() + 1, args.end());
  if (args[0] == "new") return runNew(rest);
  if (args[0] == "edit") return runEdit(rest);
  std::fprintf(stderr, "coilsim case: unknown sub-command \"%s\"\n%s", args[0].c_str(), kUsage);
  return kExitUsage;
}

}  // namespace coilsim::app
