// The `coilsim` command line: sub-commands run, bench, help, --version.
#include "app/cli.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <string>
#include <string_view>
#include <vector>

#include "app/bench.h"
#include "app/case_cmd.h"
#include "app/diagnose_cmd.h"
#include "app/mesh_cmd.h"
#include "app/phantom_cmd.h"
#include "app/plan_cmd.h"
#include "app/practice_cmd.h"
#include "app/run_scene.h"
#include "app/validate_cmd.h"
#include "physics/effect.h"

// The build passes the project version; this fallback only serves builds
// that do not (see the report of issue 2).
#ifndef COILSIM_VERSION
#define COILSIM_VERSION "0.1.0"
#endif

namespace coilsim {
namespace {

using app::kExitOk;
using app::kExitUsage;

void printUsage(std::FILE* to) {
  std::fputs(
      "usage: coilsim run SCENE [options]   simulate a scene file (scenes/*.json, docs/scene-format.md)\n"
      "       coilsim SCENE [options]       the same\n"
      "       coilsim bench [--json]        time steps and solvers (see README)\n"
      "       coilsim mesh FILE | phantom --type T --sac-mm D --out F.stl   check a mesh; make an aneurysm phantom\n"
      "       coilsim plan SCENE|CASE --coils a,b --out DIR   compare catalogue coils in an aneurysm (docs/planning.md)\n"
      "       coilsim plan-merge DIR... --out DIR             merge plans (e.g. of a Slurm job array)\n"
      "       coilsim practice CASE ...     play or replay a practice session, write its score sheet\n"
      "       coilsim case new SURFACE --out CASE.json [--sac-point x,y,z]   a case from a patient's surface\n"
      "       coilsim validate FILE [--effects a,b] [--fit young_modulus,...] --out DIR   model vs a measurement\n"
      "       coilsim validate FILE --window   the same as a panel: effect toggles, Fit, live plots, 3D error\n"
      "       coilsim diagnose FILE [--fit ...] --out DIR   which physical effect is missing (docs/validation.md)\n"
      "       coilsim help                  this text\n"
      "       coilsim --version\n"
      "\n"
      "run options:\n"
      "  --headless          run off-screen: print a summary, no window\n"
      "  --out FILE          write the final state as JSON (coilsim-result/1, atomically)\n"
      "  --input TIMELINE    drive the scene's coil deployment by timed commands (coilsim-timeline/1:\n"
      "                      push, pull, twist, stop, detach, retract; see timelines/*.json)\n"
      "  --duration S        simulated seconds, instead of the scene's duration_s (dynamic scenes)\n"
      "  --steps N           number of time steps instead (dynamic scenes)\n",
      to);
  if (app::haveUi())
    std::fputs(
        "  --screenshot PNG    write a picture of the final state (off-screen), or of the window's last frame\n"
        "  --view V            3d, xray or biplane (default 3d)\n"
        "  --size WxH          image or window size in pixels (default 1280x720)\n",
        to);
  else
    std::fputs("  (this build has no ui layer: no window, no screenshots)\n", to);
  std::fputs(
      "\n"
      "Without --headless, a window opens if there is a display; otherwise the scene\n"
      "runs off-screen as with --headless.\n"
      "exit codes: 0 ok (refused timeline commands are reported, not failures), 1 simulation\n"
      "            failed (step refused, static solve not converged) or rendering failed,\n"
      "            2 bad command line or input file (scene or timeline)\n"
      "\n"
      "effects a scene can switch on under \"effects\" (parameters: unit, default, range):\n",
      to);
  for (const Effect* e : EffectRegistry::global().all()) {
    std::fprintf(to, "  %-10s %s\n", std::string(e->name()).c_str(), std::string(e->description()).c_str());
    for (const ParamSpec& p : e->params())
      std::fprintf(to, "    %-22s %s, default %g, in [%g, %g]: %s\n", std::string(p.name).c_str(),
                   std::string(p.unit).c_str(), p.defaultValue, p.min, p.max, std::string(p.description).c_str());
  }
}

int usageError(const std::string& message) {
  std::fprintf(stderr, "coilsim: %s\n(coilsim help lists the commands and options)\n", message.c_str());
  return kExitUsage;
}

bool parseDouble(std::string_view s, double& out) {
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), out);
  return ec == std::errc() && end == s.data() + s.size() && std::isfinite(out);
}

bool parseLong(std::string_view s, long& out) {
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), out);
  return ec == std::errc() && end == s.data() + s.size();
}

bool isRunOption(const std::string& arg) {
  const std::string name = arg.substr(0, arg.find('='));
  for (const char* o : {"--headless", "--out", "--input", "--duration", "--steps", "--screenshot", "--view", "--size"})
    if (name == o) return true;
  return false;
}

// Parses the arguments of `run`; returns false after printing what is wrong.
bool parseRunArgs(const std::vector<std::string>& args, app::RunOptions& o) {
  auto fail = [](const std::string& message) {
    usageError(message);
    return false;
  };
  for (size_t i = 0; i < args.size(); ++i) {
    std::string arg = args[i], value;
    bool hasValue = false;
    if (arg.rfind("--", 0) == 0) {
      if (const size_t eq = arg.find('='); eq != std::string::npos)
        value = arg.substr(eq + 1), arg = arg.substr(0, eq), hasValue = true;
    }
    auto next = [&]() -> bool {
      if (hasValue) return true;
      if (i + 1 >= args.size()) return false;
      value = args[++i];
      return true;
    };
    if (arg == "--headless") {
      if (hasValue) return fail("--headless takes no value");
      o.headless = true;
    } else if (arg == "--out") {
      if (!next() || value.empty()) return fail("--out needs a file name");
      o.out = value;
    } else if (arg == "--input") {
      if (!next() || value.empty()) return fail("--input needs a timeline file, e.g. timelines/push-helix.json");
      o.input = value;
    } else if (arg == "--duration") {
      double d = 0;
      if (!next() || !parseDouble(value, d) || !(d > 0))
        return fail("--duration needs a number of seconds > 0, got \"" + value + "\"");
      o.durationS = d;
    } else if (arg == "--steps") {
      long n = 0;
      if (!next() || !parseLong(value, n) || n < 1 || n > 1'000'000'000)
        return fail("--steps needs an integer in [1, 1e9], got \"" + value + "\"");
      o.steps = n;
    } else if (arg == "--screenshot") {
      if (!next() || value.empty()) return fail("--screenshot needs a PNG file name");
      o.screenshot = value;
    } else if (arg == "--view") {
      if (!next() || (value != "3d" && value != "xray" && value != "biplane"))
        return fail("--view needs one of 3d, xray, biplane, got \"" + value + "\"");
      o.view = value;
    } else if (arg == "--size") {
      const size_t x = next() ? value.find('x') : std::string::npos;
      long w = 0, h = 0;
      if (x == std::string::npos || !parseLong(std::string_view(value).substr(0, x), w) ||
          !parseLong(std::string_view(value).substr(x + 1), h) || w < 16 || h < 16 || w > 16384 || h > 16384)
        return fail("--size needs WIDTHxHEIGHT in pixels, each in [16, 16384], got \"" + value + "\"");
      o.width = int(w), o.height = int(h);
    } else if (arg.size() > 1 && arg[0] == '-') {
      return fail("unknown option \"" + args[i] + "\" for run");
    } else if (o.scene.empty()) {
      o.scene = arg;
    } else {
      return fail("run takes one scene file, got \"" + o.scene + "\" and \"" + arg + "\"");
    }
  }
  if (o.scene.empty()) return fail("run needs a scene file, e.g. coilsim run scenes/default.json");
  if (o.durationS && o.steps) return fail("give --duration or --steps, not both");
  return true;
}

}  // namespace

int runCli(int argc, char** argv) {
  std::vector<std::string> args(argv + std::min(argc, 1), argv + argc);
  if (args.empty()) {
    printUsage(stderr);
    return kExitUsage;
  }
  const std::string command = args.front();
  if (command == "help" || command == "--help" || command == "-h") {
    if (args.size() > 1) return usageError("help takes no arguments");
    printUsage(stdout);
    return kExitOk;
  }
  if (command == "--version" || command == "version") {
    std::printf("coilsim %s\n", COILSIM_VERSION);
    return kExitOk;
  }
  if (command == "bench") return runBench(std::vector<std::string>(args.begin() + 1, args.end()));
  if (command == "mesh") return app::runMeshCommand(std::vector<std::string>(args.begin() + 1, args.end()));
  if (command == "phantom") return app::runPhantomCommand(std::vector<std::string>(args.begin() + 1, args.end()));
  if (command == "plan") return app::runPlan(std::vector<std::string>(args.begin() + 1, args.end()));
  if (command == "plan-merge") return app::runPlanMerge(std::vector<std::string>(args.begin() + 1, args.end()));
  if (command == "validate") return app::runValidate(std::vector<std::string>(args.begin() + 1, args.end()));
  if (command == "diagnose") return app::runDiagnose(std::vector<std::string>(args.begin() + 1, args.end()));
  if (command == "practice") return app::runPractice(std::vector<std::string>(args.begin() + 1, args.end()));
  if (command == "case") return app::runCaseCommand(std::vector<std::string>(args.begin() + 1, args.end()));
  // `coilsim SCENE ...` is `coilsim run SCENE ...`.
  if (command == "run") args.erase(args.begin());
  else if (command.size() > 1 && command[0] == '-' && !isRunOption(command))
    return usageError("unknown command or option \"" + command + "\"");
  app::RunOptions options;
  if (!parseRunArgs(args, options)) return kExitUsage;
  return app::runScene(options);
}

}  // namespace coilsim
