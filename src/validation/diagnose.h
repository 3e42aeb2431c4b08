#pragma once
// Which physical effect is missing? The baseline (the paper's model with
// young_modulus_gpa and the requested parameters fitted) leaves a residual r0.
// Each candidate effect, tested alone:
//  1. linearised screening: its parameters' sensitivities J_c (secant from
//     "off" to a typical value), stacked with the baseline Jacobian J_0,
//     predict how much of r0 a joint linear fit removes;
//  2. the best candidates (and any that the screening cannot judge) are
//     refitted in full (baseline parameters + the candidate's);
//  3. explained fraction = (RSS_0 - RSS_c) / RSS_0; significance against the
//     noise: the drop must pass an F test at 99.9 % (chi^2_p / p quantile,
//     m large), the removed RMS per node must exceed the point noise sigma
//     (a statistically certain but physically invisible gain is not a
//     finding: node residuals along a smoothed curve are strongly correlated,
//     so the F test alone overstates certainty), AND the candidate must
//     explain at least 25 % of the residual (trimming a residual that comes
//     from elsewhere, e.g. two rod models' differences, is not a finding).
// Priors: the baseline is fitted free, and its values are checked against
// their plausible bands (params.h); a value outside is reported as evidence
// that something is missing, and the ranking then starts from the
// regularised baseline (MAP), so that an effect the free fit absorbed into
// an implausible E can show. Every candidate refit is regularised.
// Forward selection: after the best significant candidate, the others are
// refitted with it in the model and judged on what they explain of its
// residual, by the same test; it stops when none is significant (or after
// maxEffects). Then the final model's adequacy (adequacy.h) and the
// prediction check.
// The fingerprint describes r0 so a user can reason about an effect not in
// the list: its split along gravity / along the coil / across, where along
// the arc length it concentrates, how it grows with the deployed length.
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "validation/adequacy.h"

namespace coilsim::validation {

// A candidate effect and which of its parameters are fitted, with the value
// meaning "effect off" and the typical value the screening differences to.
struct Candidate {
  std::string effect;
  std::vector<std::string> params;   // "effect.param"
  std::vector<double> offValue, typicalValue;  // SI, one per param
  std::vector<std::pair<std::string, double>> held;  // "param", SI: set when it is switched on (Diagnosable::held)
};

// The candidates the workbench knows for measurement `m` (buoyancy, drag,
// gravity_tilt, catheter_compliance, and self_contact when registered).
std::vector<Candidate> defaultCandidates(const Measurement& m);
// One candidate by name, for an effect defined elsewhere: its first
// parameter fitted from 0 (off) to its default value.
Candidate candidateFor(const std::string& effect, const Measurement& m);
// `p` with the candidate switched on at its off values.
ModelParams withCandidate(const ModelParams& p, const Candidate& c);

struct CandidateResult {
  std::string effect;
  double screenedFraction = 0;   // linear prediction
  double explainedFraction = 0;  // after the full refit (screening only: the prediction)
  bool refitted = false;
  bool significant = false;
  std::string note;              // e.g. "indistinguishable from young_modulus_gpa"
  FitResult fit;                 // when refitted: regularised (priors in force)
  FitResult freeFit;             // for a selected effect: the same fit without priors
  std::vector<double> stageErrorAfter;  // (stages) in file order
};

// One step of forward selection: the effect added to the model of the
// steps before, and what it explained of that model's residual.
struct SelectionStep {
  std::string effect;
  double explainedFraction = 0;  // of the previous model's residual
  CandidateResult result;        // the refit with every effect selected so far
};

struct Diagnosis {
  bool ok = false;
  std::string message;
  std::optional<Failure> failure;  // when a simulation is why it failed: the baseline fit's FitResult::failure
  FitResult baseline;                    // free fit of the baseline parameters
  FitResult regularisedBaseline;         // the same with priors in force (the reference for ranking)
  std::vector<StageComparison> baselineStages;
  // The prior check: the free baseline's values outside their plausible
  // band, and what that says ("" when all are plausible).
  std::vector<std::string> implausible;
  std::string priorVerdict;
  std::vector<CandidateResult> candidates;  // first round, best first
  std::vector<SelectionStep> selected;      // forward selection, in order
  Fingerprint fingerprint;
  std::string verdict;
  // Of the final model (baseline plus the selected effects).
  std::vector<StageComparison> finalStages;
  Adequacy adequacy;
  PredictionCheck prediction;
};

struct DiagnoseOptions {
  std::vector<std::string> fit = {youngModulusFit()};  // baseline parameters (Young's modulus always)
  std::vector<Candidate> candidates;                 // empty: defaultCandidates
  int refitTop = 3;
  int maxEffects = 3;        // forward selection stops after this many effects
  bool predict = true;       // the prediction check (one more fit)
  std::function<void(const std::string&)> progress;  // one line per phase
};

Diagnosis diagnose(StageSimulator& sim, const Comparison& cmp, const ModelParams& start, const DiagnoseOptions& o);

}  // namespace coilsim::validation
