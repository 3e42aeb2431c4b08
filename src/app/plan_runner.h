#pragma once
// plan's candidates on several threads, with progress on a terminal (mm of
// coil deployed of all the runs' coils, rate, ETA; which coil of which
// sequence a run deploys, how far, and its simulated time) and a clean stop:
// after SIGINT or SIGTERM no new candidate starts.
#include <string>
#include <vector>

#include "planning/plan.h"

namespace coilsim::app {

// Runs `candidates` on up to `jobs` threads (planning::runCandidate each);
// returns the results of those that ran, in the candidates' order. Fewer
// than asked only when a stop was requested (app/stop_signal.h); `ran` then
// says which.
std::vector<planning::CandidateResult> runCandidatesShowingProgress(const planning::PlanSetup& setup,
                                                                    const std::vector<planning::Candidate>& candidates,
                                                                    int jobs, const std::string& label,
                                                                    std::vector<bool>* ran = nullptr);

}  // namespace coilsim::app
