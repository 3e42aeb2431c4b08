#pragma once
// `coilsim validate` and the pieces `coilsim diagnose` shares with it
// (docs/validation.md): reading the measurement and the options, the
// per-stage JSON and Markdown tables, the pictures.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "validation/diagnose.h"
#include "validation/joint.h"

namespace coilsim::app {

// coilsim validate FILE [--effects a,b] [--fit young_modulus_gpa,...] --out DIR
//   [--spacing MM] [--push-increment MM] [--no-plots] [--quiet]
// Writes DIR/report.json, DIR/report.md and the PNGs. Returns 0, 1 if a
// stage cannot be simulated, 2 on a bad command line or measurement file.
int runValidate(const std::vector<std::string>& args);

// Shared with diagnose.
struct WorkbenchArgs {
  std::string file, out;           // file: the first of `files`
  std::vector<std::string> files;  // several measurements of the same coil (fitted jointly)
  std::vector<std::string> effects, fit;
  double spacingMm = 2.0, pushIncrementMm = 2.0;
  bool plots = true, quiet = false;
};

// Parses the options common to validate and diagnose (effects only when
// `allowEffects`); returns an error message or "".
std::string parseWorkbenchArgs(const std::vector<std::string>& args, bool allowEffects, WorkbenchArgs& a);

// The stage simulator's options from the command line's (mm there, SI here).
validation::SimOptions simOptionsOf(const WorkbenchArgs& a);

// Creates `dir` and its parents; false, after saying why (naming `command`
// and the directory), if it cannot.
bool makeOutputDirectory(const std::string& command, const std::string& dir);

// One JSON object per stage: name, node_error_mean, node_error_sd,
// stage_error, mean_displacement_mm, mean_distance_mm, and where the
// residual lies (components, thirds of the arc length, noise floor).
nlohmann::ordered_json stagesJson(const validation::Comparison& cmp, const std::vector<validation::StageComparison>& s);
// name -> {value, sigma, unit, prior: {nominal, plausible_low, plausible_high,
// deviation, plausible}} in edge units.
nlohmann::ordered_json fittedJson(const std::vector<validation::FittedValue>& fitted);
// The adequacy test, the prediction check and a joint diagnosis, as JSON and Markdown.
nlohmann::ordered_json adequacyJson(const validation::Adequacy& a);
nlohmann::ordered_json predictionJson(const validation::PredictionCheck& p);
nlohmann::ordered_json jointJson(const validation::JointDiagnosis& d, const std::vector<std::string>& files);
std::string adequacyMarkdown(const validation::Adequacy& a, const validation::PredictionCheck& p);
std::string jointMarkdown(const validation::JointDiagnosis& d, const std::vector<std::string>& files);
// The prior check of fitted values in words ("" when all are plausible).
std::string priorCheckText(const std::vector<validation::FittedValue>& fitted);
nlohmann::ordered_json fingerprintJson(const validation::Fingerprint& f);

// The per-stage Markdown table, before and (when `after` is not empty) after.
std::string stageTable(const validation::Measurement& m, const std::vector<validation::StageComparison>& before,
                       const std::vector<validation::StageComparison>& after);

// error_along_arc.png and overlay_stageN.png into `dir`; the names of the
// files written are appended to `written`, problems to `warnings`.
void writePlots(const std::string& dir, const validation::Measurement& m,
                const std::vector<validation::StageComparison>& stages, std::vector<std::string>& written,
                std::vector<std::string>& warnings);

// Expands "EFFECT" items of --fit into that effect's fitted parameters
// (the diagnose candidate's: buoyancy.medium_density_g_cm3, both tilts...).
std::vector<std::string> expandFitNames(const std::vector<std::string>& names, const validation::Measurement& m);

}  // namespace coilsim::app
