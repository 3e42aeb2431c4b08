#pragma once
// One bench experiment made with the reference rod: what the file declares,
// the physics that truly acted (some of it hidden from the file's fields),
// and the simulated and sampled centre lines. Units in the field names.
#include <cstdint>
#include <string>
#include <vector>

#include "rod.h"
#include "solver.h"

namespace refrod {

struct StageDef {
  std::string name;
  double deployedMm = 0, twistDeg = 0;
  double sigmaMm = 0.05;
  int points = 40;
  std::vector<PushSample> history;  // SI (s, m, rad); empty for a static stage
  double captureS = 0;
};

// The free polymer tube that truly carries the coil beyond the guide.
struct TubeDef {
  double lengthMm = 0, outerDiameterMm = 0, innerDiameterMm = 0;
  double youngGpa = 0, poisson = 0.4, densityGcm3 = 0;
  int edges = 20;
};

struct Scenario {
  std::string name, description;
  uint64_t seed = 1;
  // Declared in the file.
  double lengthMm = 0, wireRadiusMm = 0, densityGcm3 = 21.45;
  double loopDiameterMm = 0, pitchMm = 0;
  bool rightHanded = true;
  double nominalYoungGpa = 0, poisson = 0.39;
  Vec3 gravity = Vec3(0, 0, -9.81);
  double mediumDensityGcm3 = 0.0012, mediumViscosityPas = 1.8e-5;
  Vec3 tipMm = Vec3::Zero(), direction = Vec3::UnitX(), referenceNormal = Vec3::UnitZ();
  std::vector<StageDef> stages;
  // The truth.
  double trueYoungGpa = 0;
  double tiltADeg = 0, tiltBDeg = 0;  // bench tilt, coilsim's gravity_tilt convention
  TubeDef tube;                       // lengthMm 0: rigid clamp at the tip
  std::vector<std::string> hidden;    // names of the hidden effects
  // Switches of the reference run (all physical, on): withoutHidden() turns
  // the hidden ones off to measure how much they move the coil.
  bool buoyancy = true, drag = true, contact = true;
  std::string trueModel;              // how to set a model to the truth, in words
  // Discretisation of the reference run.
  double edgeMm = 0.4, timeStepS = 2.5e-4;
};

// The ten scenarios of tests/data/reference (scenarios.cpp).
std::vector<Scenario> referenceScenarios();

// The tilted gravity g' = exp(a e1 + b e2) g (e1 the x axis made orthogonal
// to g, e2 = g^ x e1), the convention of coilsim's gravity_tilt effect.
Vec3 tiltedGravity(const Vec3& g, double aDeg, double bDeg);

// Resistive-force coefficients of Lighthill (1976) for a filament of radius r
// in a fluid of viscosity mu, with wavelength Lambda (here the loop's arc
// length pi D): c_n = 4 pi mu / (ln(0.18 Lambda / r) + 1/2),
// c_t = 2 pi mu / ln(0.18 Lambda / r), N s/m^2.
void lighthillDrag(double mu, double Lambda, double r, double& cn, double& ct);

// The rod model of the truth (SI).
RodSpec trueSpec(const Scenario& sc);

struct StageResult {
  std::vector<Vec3> nodesM;      // noise-free centre line at the nodes (m)
  std::vector<double> nodeS;     // their arc lengths (m)
  std::vector<Vec3> sampledMm;   // the measured points (mm, noisy, 3 decimals)
  int contactPairs = 0;          // edge pairs (far apart along the rod) closer than 2r
  double minGapMm = 0;           // smallest surface gap between such edges (mm)
  double maxSagMm = 0;           // largest node distance from the unloaded rest shape
  Vec3 exitMm = Vec3::Zero();    // where the coil truly leaves the catheter
  Vec3 exitDirection = Vec3::UnitX();
};

// Runs every stage (static stages by twist then length, each continuing the
// previous; a push stage from the static equilibrium at its first sample)
// and samples the measurements. Throws std::runtime_error naming the stage
// if a solve fails.
std::vector<StageResult> runExperiment(const Scenario& sc);

// The same experiment with its hidden effects switched off (the default
// model's physics with the true E).
Scenario withoutHidden(const Scenario& sc);

// Per stage, the largest distance (mm) between the true centre line and the
// one without the hidden effects, node by node: how visible they are.
std::vector<double> effectSizes(const std::vector<StageResult>& truth, const std::vector<StageResult>& without);

// The coil-measurement/1 file and the truth sidecar, as text.
std::string measurementJson(const Scenario& sc, const std::vector<StageResult>& r);
std::string truthJson(const Scenario& sc, const std::vector<StageResult>& r, const std::vector<double>& effectMm);

}  // namespace refrod
