// Writes the reference measurement files: for each scenario <name>.json
// (coil-measurement/1) and <name>.truth.json into the directory given,
// optionally only the scenarios named after it.
//   make_reference_measurements OUT_DIR [NAME...]
#include <chrono>
#include <cstdio>
#include <fstream>
#include <string>

#include "experiment.h"

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: %s OUT_DIR [NAME...]\n", argv[0]);
    return 2;
  }
  const std::string dir = argv[1];
  int failures = 0;
  for (const refrod::Scenario& sc : refrod::referenceScenarios()) {
    bool wanted = argc == 2;
    for (int i = 2; i < argc; ++i) wanted |= sc.name == argv[i];
    if (!wanted) continue;
    const auto t0 = std::chrono::steady_clock::now();
    try {
      const auto r = refrod::runExperiment(sc);
      // How far the hidden effects move the coil: the run without them.
      std::vector<double> effect(sc.stages.size(), 0.0);
      if (!sc.hidden.empty() && sc.hidden.front() != "none")
        effect = refrod::effectSizes(r, refrod::runExperiment(refrod::withoutHidden(sc)));
      for (const auto& [file, body] : {std::pair{dir + "/" + sc.name + ".json", refrod::measurementJson(sc, r)},
                                       std::pair{dir + "/" + sc.name + ".truth.json", refrod::truthJson(sc, r, effect)}}) {
        std::ofstream f(file, std::ios::binary);
        f << body;
        if (!f) throw std::runtime_error("cannot write " + file);
      }
    } catch (const std::exception& e) {
      std::fprintf(stderr, "%s: %s\n", sc.name.c_str(), e.what());
      ++failures;
      continue;
    }
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    std::printf("%-22s %.1f s\n", sc.name.c_str(), s);
  }
  return failures ? 1 : 0;
}
