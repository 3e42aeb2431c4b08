#pragma once
// Reproduces the stages of a measurement with coilsim's model and the same
// boundary conditions: the coil clamped at the catheter tip (position, exit
// direction, d1 on the reference normal turned by the stage's twist), pushed
// out of a rigid straight catheter.
//  - A static stage is reached by continuation along the deployment: the
//    coil is pushed from zero in increments of at most `pushIncrement`, each
//    followed by a static equilibrium (solveStatic), as the bench pushed
//    slowly. Stages with the same twist continue from one another in order
//    of deployed length.
//  - A stage with a push history is integrated in time (implicit Euler)
//    following it, from a static equilibrium at its first sample, up to the
//    capture time.
// Identification evaluates many nearby parameter sets: `warmStart` then
// starts each static stage from the equilibrium of the previous evaluation
// (continuation in the parameters along the same equilibrium branch) instead
// of pushing again from zero; a final report always pushes from zero.
#include <optional>
#include <string>
#include <vector>

#include "physics/effect.h"
#include "physics/failure.h"
#include "validation/measurement.h"

namespace coilsim::validation {

// The model's parameters, SI: what identification may change.
struct ModelParams {
  RodSpec coil;  // the measurement's coil; a fit changes its rod quantities (validation/params.cpp, kRodFits)
  std::vector<EffectUse> effects;  // switched on beyond gravity, with their values

  // The file's coil (Young's modulus 10 GPa when the file gives none); effects none.
  static ModelParams nominal(const Measurement& m);
  EffectUse* effect(std::string_view name);
  const EffectUse* effect(std::string_view name) const;
};

struct SimOptions {
  double spacing = 2e-3;        // target beam length, m (the coil gets round(L / spacing) beams)
  double pushIncrement = 2e-3;  // largest push between two static equilibria, m
  double timeStep = 1e-3;       // s, dynamic stages
};

// One stage simulated, or why it could not be: the Failure physics gave (a
// model it would not build, a static push that did not converge, naming how
// far the coil was pushed, a dynamic step refused at the push history's
// time, a non-finite node), never a string of its own.
struct StageSim {
  std::optional<Failure> failure;  // nothing: simulated
  std::vector<Vec3> x;       // (nodes) positions from the tip outward, m
  std::vector<double> s;     // (nodes) arc length from the tip, m
  bool ok() const { return !failure; }
  // The line a report shows: describe() of the failure, "" when simulated.
  std::string message() const { return failure ? describe(*failure) : std::string(); }
};

class StageSimulator {
 public:
  StageSimulator(const Measurement& m, const SimOptions& options = {});
  // One result per stage, in file order.
  std::vector<StageSim> run(const ModelParams& p, bool warmStart = false);
  const SimOptions& options() const { return options_; }
  int beams() const { return beams_; }

 private:
  struct Cache {
    bool valid = false;
    std::vector<Vec3> x;
    std::vector<Quat> q;
  };
  Measurement m_;
  SimOptions options_;
  int beams_ = 0;
  std::vector<Cache> cache_;  // (stages) last equilibrium, for warm starts
};

}  // namespace coilsim::validation
