// `coilsim experiment injection` (see experiment_cmd.h).
#include "app/experiment_cmd.h"

#include <chrono>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "app/exit_codes.h"
#include "io/units.h"
#include "planning/wire_injection.h"

namespace coilsim::app {
namespace {

// "0,0.1,0.3" as numbers; throws UsageError naming the option.
std::vector<double> numbers(const ParsedArgs& p, const char* option, std::vector<double> fallback) {
  const auto text = p.text(option);
  if (!text) return fallback;
  std::vector<double> out;
  size_t at = 0;
  while (at <= text->size()) {
    const size_t comma = std::min(text->find(',', at), text->size());
    double v = 0;
    const std::string item = text->substr(at, comma - at);
    if (!parseNumber(item, v))
      throw UsageError(std::string(option) + " needs numbers separated by commas, got \"" + item + "\"");
    out.push_back(v);
    at = comma + 1;
  }
  return out;
}

}  // namespace

int runExperiment(const ParsedArgs& p) {
  planning::WireInjectionSpec base;
  std::vector<double> ratios, frictions, turns;
  try {
    if (p.operands.front() != "injection")
      throw UsageError("knows one experiment, injection, got \"" + p.operands.front() + "\"");
    ratios = numbers(p, "--cavity-ratio", {20});
    frictions = numbers(p, "--friction", {0, 0.1, 0.3});
    if (auto v = p.number("--packing")) base.targetPacking = *v;
    turns = numbers(p, "--turns", {0});
    // Out-of-range values are refused here, before any run starts.
    for (double ratio : ratios)
      for (double mu : frictions)
        for (double t : turns) {
          planning::WireInjectionSpec s = base;
          s.cavityRatio = ratio, s.friction = mu, s.turnsPerDiameter = t;
          try {
            (void)planning::wireInjectionModel(s);
          } catch (const std::invalid_argument& e) {
            char run[96];
            std::snprintf(run, sizeof run, "the run of D/d %g, mu %g, turns %g: ", ratio, mu, t);
            throw UsageError(run + std::string(e.what()));
          }
        }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "coilsim experiment: %s\n", e.what());
    return kExitUsage;
  }
  std::vector<planning::WireInjectionSpec> specs;
  for (double ratio : ratios)
    for (double mu : frictions)
      for (double t : turns) {
        specs.push_back(base);
        specs.back().cavityRatio = ratio, specs.back().friction = mu, specs.back().turnsPerDiameter = t;
      }
  std::vector<planning::WireInjectionResult> results(specs.size());
  std::vector<double> seconds(specs.size());
  // Runs are independent: --jobs of them at once.
  const size_t jobs = size_t(p.integer("--jobs").value_or(1));
  for (size_t first = 0; first < specs.size(); first += jobs) {
    std::vector<std::thread> threads;
    for (size_t i = first; i < std::min(specs.size(), first + jobs); ++i)
      threads.emplace_back([&, i] {
        const auto start = std::chrono::steady_clock::now();
        results[i] = planning::runWireInjection(specs[i]);
        seconds[i] = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      });
    for (std::thread& t : threads) t.join();
  }
  std::printf("Wire injected into a rigid sphere (Stoop et al. 2011): straight wire d = %.3f mm (B = 0.001827 N mm^2), "
              "pushed at %.0f mm/s in %.0f mm strokes, to packing %.3f or a push force of %.0f B/R^2; "
              "winding order W: 1 a spool, 0 a tangle.\n\n",
              units::mToMm(base.wireDiameter), units::mToMm(base.pushSpeed), units::mToMm(base.stroke),
              base.targetPacking, base.jamForceRatio);
  std::printf("| D/d | mu | turns per D | injected mm | packing | stopped by | W | max push force F R^2/B | "
              "wall penetration / r | wall time |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|\n");
  int exit = kExitOk;
  for (size_t i = 0; i < specs.size(); ++i) {
    const auto& s = specs[i];
    const auto& r = results[i];
    const char* stop = !r.ok ? "refused step" : r.jammed ? "force" : "packing";
    std::printf("| %.0f | %.2f | %.1f | %.1f | %.4f | %s | %.3f | %.1f | %.3f | %.0f s |\n", s.cavityRatio,
                s.friction, s.turnsPerDiameter, units::mToMm(r.injected), r.packing, stop, r.order,
                r.maxForce / r.forceScale, r.maxWallPenetrationOfRadius, seconds[i]);
    if (!r.ok) {
      std::fprintf(stderr, "coilsim experiment: D/d %.0f, mu %.2f: %s\n", s.cavityRatio, s.friction, r.error.c_str());
      exit = kExitFailure;
    }
  }
  return exit;
}

}  // namespace coilsim::app
