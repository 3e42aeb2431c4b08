#include "app/plan_runner.h"

#include <algorithm>
#include <atomic>
#include <optional>
#include <thread>

#include "app/progress.h"
#include "app/stop_signal.h"

namespace coilsim::app {

using planning::Candidate;
using planning::CandidateResult;

std::vector<CandidateResult> runCandidatesShowingProgress(const planning::PlanSetup& setup,
                                                          const std::vector<Candidate>& candidates, int jobs,
                                                          const std::string& label, std::vector<bool>* ran) {
  std::vector<std::optional<CandidateResult>> results(candidates.size());
  std::atomic<size_t> next{0}, done{0};
  Progress progress("plan " + label, double(candidates.size()), "runs");
  const int n = std::max(1, std::min<int>(jobs, int(candidates.size())));
  const int detectionThreads = planning::detectionThreadsFor(n);
  auto worker = [&] {
    for (size_t i = next++; i < candidates.size() && !stopRequested(); i = next++) {
      const Candidate& c = candidates[i];
      const std::string what = c.coils.size() > 1
                                   ? "sequence of " + std::to_string(c.coils.size()) + " coils " + c.name()
                                   : "coil " + c.name();
      progress.note("run " + std::to_string(i + 1) + " of " + std::to_string(candidates.size()) + ": deploying " +
                    what + " (" + c.variant + ")");
      results[i] = planning::runCandidate(setup, c, {}, detectionThreads);
      progress.update(double(++done), "finished " + c.name() + " (" + c.variant + ")");
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
