#pragma once
// The State: what changes each step (poses, velocities, constraint targets,
// counters, warnings) plus scratch arrays sized once by makeState(). Many
// States may share one Model (fitting, finite differences, replay).
#include <string>
#include <vector>

#include "physics/block_tridiagonal.h"
#include "physics/math.h"

namespace coilsim {

struct Model;

struct Pose {
  Vec3 position = Vec3::Zero();
  Quat rotation = Quat::Identity();
};

// Scratch for one rod, allocated once; contents are meaningless between steps.
struct RodWorkspace {
  std::vector<Vec6> force;       // (nnode) total generalised force
  std::vector<Mat6> effectK;     // (nnode) effect stiffness diagonal blocks
  std::vector<Mat6> effectD;     // (nnode) effect damping diagonal blocks
  bool effectsTouchedMatrix = false;  // some effect wrote effectK/effectD this assembly
  BlockTridiagonal stiffness;    // elastic tangent K (nnode blocks)
  BlockTridiagonal system;       // implicit matrix
  BlockTridiagonalSolver solver;
  std::vector<Vec6> rhs;         // (nnode)
  std::vector<Vec6> velocity;    // (nnode) generalised velocity packed (v, w)
  std::vector<Vec3> x0;          // (nnode) start-of-step copy, for restore
  std::vector<Quat> q0;
  std::vector<Vec3> v0, w0;
  std::vector<unsigned> fixedMask;  // (nnode) constrained DOFs
  std::vector<Vec6> fixedValue;     // (nnode) prescribed increments of constrained DOFs
};

struct RodState {
  std::vector<Vec3> x;  // (nnode) positions, m
  std::vector<Quat> q;  // (nnode) material frames
  std::vector<Vec3> v;  // (nnode) velocities, m/s
  std::vector<Vec3> w;  // (nnode) angular velocities, rad/s, global
  std::vector<Pose> targets;  // (constraints) where each constraint holds its node
  RodWorkspace work;
};

struct StepStats {
  long steps = 0;
  long newtonIterations = 0;
  double lastStepSeconds = 0;   // wall time of the last step
  double totalStepSeconds = 0;  // wall time of all steps
  double maxStepSeconds = 0;
};

struct State {
  double time = 0;  // s
  std::vector<RodState> rods;
  StepStats stats;
  long blowups = 0;                   // steps refused because the result was not healthy
  std::vector<std::string> warnings;  // each reported once
};

// A State at rest in the model's rest shape, constraint targets at the rest
// poses, every scratch array sized for the model.
State makeState(const Model& model);

// Adds `message` to state.warnings unless it is there already.
void warnOnce(State& state, const std::string& message);

}  // namespace coilsim
