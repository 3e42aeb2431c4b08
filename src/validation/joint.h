#pragma once
// Several measurements of the same coil (same material, other setups: in air
// and in water, another catheter position, another twist). The coil's
// parameters are fitted once for all files, each file keeping its own setup
// (medium, gravity, tip, and the values its setup implies for effects such
// as buoyancy and drag).
//
// A parameter that must differ between files to fit them is the sign of a
// missing effect: each file is fitted alone too, and letting the parameter
// take one value per file must not remove much of the joint residual. The
// test is the candidates' (diagnose.h): an F test at 99.9 % on the drop
// from the joint fit to the separate ones (p = files - 1 extra values per
// parameter), the removed RMS per node above the noise, and at least 25 %
// of the joint residual. Then the setup-driven effects (those whose values
// come from the file's medium: buoyancy, drag) are switched on in every
// file at their setup's values and the joint fit repeated: the one that
// removes the difference is named. A coil in air and in water separates
// buoyancy from E, which no single static file can.
#include <optional>
#include <string>
#include <vector>

#include "validation/identify.h"

namespace coilsim::validation {

struct JointFile {
  StageSimulator* sim = nullptr;
  const Comparison* cmp = nullptr;
  ModelParams start;  // the file's nominal model (and effects switched on from its setup)
};

struct ParameterSpread {
  std::string param, unit;
  double toSI = 1;
  std::vector<double> perFile, sigmaPerFile;  // SI, each file fitted alone
  double joint = 0;
  double explainedFraction = 0;  // of the joint residual, removed by letting it differ
  bool mustDiffer = false;       // significant by the test above
};

struct JointEffect {
  std::string effect;
  FitResult fit;                  // joint fit with the effect on in every file
  double explainedFraction = 0;   // of the joint baseline residual
  bool significant = false;
  std::vector<double> perFileAfter;  // the spread's parameter fitted per file with the effect on, SI
  bool removesSpread = false;     // the per-file values then agree (not significant any more)
};

struct JointDiagnosis {
  bool ok = false;
  std::string message;
  std::optional<Failure> failure;        // when a simulation is why it failed: that fit's FitResult::failure
  std::vector<std::string> fit;          // shared parameter names
  FitResult joint;                       // shared fit, all files
  std::vector<FitResult> separate;       // (files) each alone
  std::vector<ParameterSpread> spread;   // (fit) per parameter
  std::vector<JointEffect> effects;      // setup-driven effects tried, best first
  std::string verdict;
};

// Fits `fit` jointly and per file; when a parameter must differ, tries the
// setup-driven effects. `progress` gets one line per phase (may be empty).
JointDiagnosis diagnoseJoint(const std::vector<JointFile>& files, const std::vector<std::string>& fit,
                             const std::function<void(const std::string&)>& progress);

}  // namespace coilsim::validation
