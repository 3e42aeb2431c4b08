#include "app/plan_runner.h"

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <mutex>
#include <optional>
#include <thread>

#include "app/progress.h"
#include "app/stop_signal.h"
#include "io/units.h"

namespace coilsim::app {

using planning::Candidate;
using planning::CandidateResult;

namespace {

std::string oneDecimal(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.1f", v);
  return b;
}

// What a run is deploying now: "run 1 of 2, sequence goal, coil 2 of 6 filling-helical-5x150: 23.0 of
// 150 mm, 45.2 s simulated (0.21 s per s)".
std::string runNote(size_t run, size_t runs, const Candidate& c, const planning::RunProgress& p, double wall) {
  std::string n = "run " + std::to_string(run + 1) + " of " + std::to_string(runs) + ", ";
  if (!c.sequence.empty()) n += "sequence " + c.sequence + ", ";
  n += "coil " + std::to_string(p.coil + 1) + " of " + std::to_string(p.coils) + " " + p.coilName + ": " +
       oneDecimal(units::mToMm(p.deployed)) + " of " + oneDecimal(units::mToMm(p.coilLength)) + " mm, " +
       oneDecimal(p.time) + " s simulated";
  if (wall > 0) n += " (" + oneDecimal(p.time / wall) + " s per s)";
  return n;
}

}  // namespace

std::vector<CandidateResult> runCandidatesShowingProgress(const planning::PlanSetup& setup,
                                                          const std::vector<Candidate>& candidates, int jobs,
                                                          const std::string& label, std::vector<bool>* ran) {
  std::vector<std::optional<CandidateResult>> results(candidates.size());
  std::atomic<size_t> next{0};
  // The whole job in mm of coil, each run's share as far as it got: the rate and ETA are per mm deployed.
  double total = 0;
  std::vector<double> doneMm(candidates.size(), 0.0);
  for (const Candidate& c : candidates)
    for (const io::CoilSpec& coil : c.coils) total += coil.lengthMm;
  std::mutex doneMutex;
  Progress progress("plan " + label, total, "mm deployed");
  const int n = std::max(1, std::min<int>(jobs, int(candidates.size())));
  const int detectionThreads = planning::detectionThreadsFor(n);
  // Sets run i's share and redraws; returns the sum of the shares.
  auto report = [&](size_t i, double mm, const std::string& note) {
    double sum = 0;
    {
      std::lock_guard lock(doneMutex);
      doneMm[i] = mm;
      for (const double d : doneMm) sum += d;
    }
    progress.update(sum, note);
  };
  auto worker = [&] {
    for (size_t i = next++; i < candidates.size() && !stopRequested(); i = next++) {
      const Candidate& c = candidates[i];
      const std::string what = c.coils.size() > 1
                                   ? "sequence of " + std::to_string(c.coils.size()) + " coils " + c.name()
                                   : "coil " + c.name();
      progress.note("run " + std::to_string(i + 1) + " of " + std::to_string(candidates.size()) + ": deploying " +
                    what + " (" + c.variant + ")");
      const double start = progress.seconds();
      const planning::RunProgressCallback tell = [&](const planning::RunProgress& p) {
        report(i, units::mToMm(p.deployedBefore + p.deployed),
               runNote(i, candidates.size(), c, p, progress.seconds() - start));
      };
      results[i] = planning::runCandidate(setup, c, {}, detectionThreads, Progress::shown() ? tell : nullptr);
      double whole = 0;
      for (const io::CoilSpec& coil : c.coils) whole += coil.lengthMm;
      report(i, whole, "finished run " + std::to_string(i + 1) + ": " + c.name() + " (" + c.variant + ")");
    }
  };
  std::vector<std::thread> threads;
  for (int k = 1; k < n; ++k) threads.emplace_back(worker);
  worker();
  for (std::thread& t : threads) t.join();
  progress.finish();
  std::vector<CandidateResult> out;
  if (ran) ran->assign(candidates.size(), false);
  for (size_t i = 0; i < results.size(); ++i)
    if (results[i]) {
      out.push_back(std::move(*results[i]));
      if (ran) (*ran)[i] = true;
    }
  return out;
}

}  // namespace coilsim::app
