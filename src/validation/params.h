#pragma once
// Parameters identification may fit. Rod quantities under their scene keys,
// with unit, SI factor and physical bounds from physics/rod_quantities.h:
// young_modulus_gpa, poisson_ratio, loop_diameter_mm, pitch_mm (the old
// names young_modulus, loop_diameter and pitch are accepted too). Effect
// parameters: "<effect>.<param>" with the effect's own ParamSpec (e.g.
// drag.viscosity_pa_s); the effect must be switched on.
#include <optional>
#include <string>
#include <vector>

#include "physics/rod_quantities.h"
#include "validation/simulate.h"

namespace coilsim::validation {

// What is physically plausible for a parameter before any data: a nominal
// value and a band (SI). For the coil's Young's modulus the nominal is the
// file's and the band -50 %/+100 % around it: a wound platinum(-tungsten)
// coil's stiffness-equivalent modulus is not a handbook constant (bulk
// platinum 168 GPa, Pt-8W about 200 GPa; the winding makes the wire-
// equivalent E of a coil a fraction of that and varies by maker), so the
// datasheet value is the anchor and a fit that needs half or twice of it
// says something else is wrong. Effect parameters take theirs from the
// effect's FitSpec (physics: tube moduli, lengths, densities).
struct Prior {
  bool known = false;
  double nominal = 0, low = 0, high = 0;  // SI, low <= nominal <= high
};

struct FitParam {
  std::string name;
  std::string unit;   // edge unit, for reports
  double toSI = 1;    // SI = edge * toSI
  double lo = 0, hi = 0;  // bounds, SI
  bool logScale = false;  // optimised in log(value): positive with wide bounds
  Prior prior;
};

// Where `value` lies relative to `f`'s plausible band: 0 at the nominal, +-1
// at the band's edges (in log for log-scale parameters), beyond 1 outside.
double priorDeviation(const FitParam& f, double value);

// The parameter called `name` for model `p`, or nullopt with `why` set
// (unknown name, effect not switched on, no rest shape with that parameter).
std::optional<FitParam> describeParam(const std::string& name, const ModelParams& p, const Measurement& m,
                                      std::string& why);
// The value (SI) of a parameter describeParam accepts; throws
// std::invalid_argument naming an unknown one.
double getParam(const ModelParams& p, const std::string& name);
void setParam(ModelParams& p, const std::string& name, double si);

// The scene key a fit name stands for (young_modulus -> young_modulus_gpa);
// any other name unchanged. Two names fit the same parameter when these agree.
std::string canonicalFitName(const std::string& name);
// The fit name of the coil's Young's modulus, which diagnosis and joint fits
// always fit: its declared scene key.
inline std::string youngModulusFit() { return std::string(rodq::kYoungModulus.spec.name); }
// True for either name of the coil's Young's modulus (the old one too).
inline bool isYoungModulus(const std::string& name) { return canonicalFitName(name) == youngModulusFit(); }
// One line for a user who typed an old fit name, else empty.
std::string oldFitNameNote(const std::string& name);
// The rod quantities identification can fit, in help order.
std::vector<const rodq::Quantity*> rodFitQuantities();

// What an effect may read of the measurement's setup (the medium).
SetupHint setupHint(const Measurement& m);

// The effect `name` switched on with the values the measurement implies
// (Diagnosable::fromSetup: buoyancy the medium's density, drag its
// viscosity) and those it is held at in validation (Diagnosable::held),
// otherwise its defaults. Throws std::invalid_argument naming
// an unknown effect and listing the known ones.
EffectUse effectFromFile(const std::string& name, const Measurement& m);

// True for an effect that replaces the rigid clamp at the tip by its own
// spring (Diagnosable::releasesClamp): the model builder then frees the tip node.
bool releasesClamp(const EffectUse& use);

// "a,b,c" -> {"a", "b", "c"} (empty items dropped).
std::vector<std::string> splitList(const std::string& list);

}  // namespace coilsim::validation
