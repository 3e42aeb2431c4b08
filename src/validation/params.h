#pragma once
// Parameters identification may fit, declared once: name, edge unit, bounds.
// Model parameters: young_modulus (GPa), poisson_ratio, loop_diameter (mm),
// pitch (mm). Effect parameters: "<effect>.<param>" with the effect's own
// ParamSpec (e.g. drag.viscosity_pa_s); the effect must be switched on.
#include <optional>
#include <string>
#include <vector>

#include "validation/simulate.h"

namespace coilsim::validation {

struct FitParam {
  std::string name;
  std::string unit;   // edge unit, for reports
  double toSI = 1;    // SI = edge * toSI
  double lo = 0, hi = 0;  // bounds, SI
  bool logScale = false;  // optimised in log(value): positive with wide bounds
};

// The parameter called `name` for model `p`, or nullopt with `why` set
// (unknown name, effect not switched on, no rest shape with that parameter).
std::optional<FitParam> describeParam(const std::string& name, const ModelParams& p, const Measurement& m,
                                      std::string& why);
double getParam(const ModelParams& p, const std::string& name);
void setParam(ModelParams& p, const std::string& name, double si);

// What an effect may read of the measurement's setup (the medium).
SetupHint setupHint(const Measurement& m);

// The effect `name` switched on with the values the measurement implies
// (Diagnosable::fromSetup: buoyancy the medium's density, drag its
// viscosity), otherwise its defaults. Throws std::invalid_argument naming
// an unknown effect and listing the known ones.
EffectUse effectFromFile(const std::string& name, const Measurement& m);

// True for an effect that replaces the rigid clamp at the tip by its own
// spring (Diagnosable::releasesClamp): the model builder then frees the tip node.
bool releasesClamp(const EffectUse& use);

// "a,b,c" -> {"a", "b", "c"} (empty items dropped).
std::vector<std::string> splitList(const std::string& list);

}  // namespace coilsim::validation
