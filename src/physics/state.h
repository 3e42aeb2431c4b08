#pragma once
// The State: what changes each step (poses, velocities, constraint targets,
// counters, warnings) plus scratch arrays sized once by makeState(). Many
// States may share one Model (fitting, finite differences, replay).
#include <string>
#include <vector>

#include "physics/block_tridiagonal.h"
#include "physics/contact/contact_state.h"
#include "physics/contact/scratch.h"
#include "physics/contact/wall_load.h"
#include "physics/model.h"
#include "physics/math.h"
#include "physics/unilateral.h"
#include "physics/wall_spring.h"

namespace coilsim {

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
  std::vector<Vec6> stiffnessTimesVelocity;  // (nnode) (h b + h^2) K velocity, dynamics.cpp
  std::vector<Vec3> x0;          // (nnode) start-of-step copy, for restore
  std::vector<Quat> q0;
  std::vector<Vec3> v0, w0;
  std::vector<Pose> targets0;    // constraint targets at the start of the step
  std::vector<unsigned> fixedMask;  // (nnode) constrained DOFs (of active nodes)
  std::vector<Vec6> fixedValue;     // (nnode) prescribed increments of constrained DOFs
  UnilateralScratch unilateral;     // the effects' node constraints and their solve (wall contact)
  // Pair contacts coupled across rods (physics/pair_coupling.h): whether
  // this assembly asks the effects for their couplings, and what they gave.
  bool pairsCoupled = false;
  std::vector<PairCoupling> pairs;
  std::vector<WallSpring> wallSprings;  // the wall nodes' springs of the same assembly
};

struct RodState {
  // The chain as it is now. Normally the Model's rod unchanged; a deployment
  // rewrites these as coil material slides out of the catheter (composite
  // elements, the partial element at the tip, nodes appearing there), so
  // they are state, not model. Arrays keep their size; only the first
  // `activeNodes` nodes (and activeNodes - 1 beams) take part in a step.
  bool active = true;
  int activeNodes = 0;
  std::vector<BeamRest> beams;  // (nnode-1) element constants
  std::vector<NodeProps> nodes; // (nnode)

  std::vector<Vec3> x;  // (nnode) positions, m
  std::vector<Quat> q;  // (nnode) material frames
  std::vector<Vec3> v;  // (nnode) velocities, m/s
  std::vector<Vec3> w;  // (nnode) angular velocities, rad/s, global
  std::vector<Pose> targets;  // (constraints) where each constraint holds its node
  RodContacts contact;        // contacts found this step and contact forces per node
  RodWorkspace work;
  // Sleeping (physics/sleep.h): frozen, not integrated, its wall and self
  // contacts kept from before; stillTime: how long it has been still (s).
  bool asleep = false;
  double stillTime = 0;
};

// What the sleep rule remembers across steps (physics/sleep.h).
struct SleepRecord {
  std::vector<double> seen;  // the model's effects, gravity, damping and time step at the last step
  long sleeps = 0, wakes = 0;  // rods put to sleep and woken so far
};

struct StepStats {
  long steps = 0;
  long newtonIterations = 0;
  double lastStepSeconds = 0;   // wall time of the last step
  double totalStepSeconds = 0;  // wall time of all steps
  double maxStepSeconds = 0;
  // Deepest wall penetration seen at the start of a step (contact
  // detection), in m and as a fraction of the wire radius there; a penalty
  // too soft for the coil shows here (dynamics.cpp warns once past 10 %).
  double maxWallPenetration = 0, maxWallPenetrationOfRadius = 0;
  // The sustained wall load (physics/contact/wall_load.h), updated after every step taken.
  WallLoad wallLoad;
  PairSolveStats pairSolve;  // the coupled pair contacts' solves (physics/pair_coupling.h)
};

struct State {
  double time = 0;  // s
  std::vector<RodState> rods;
  DeviceState device;  // the deployment's (Model::device), when the run has one
  StepStats stats;
  long blowups = 0;                   // steps refused because the result was not healthy
  long substepped = 0;                // steps that were healthy only in substeps (dynamics.cpp)
  std::vector<std::string> warnings;  // each reported once
  SleepRecord sleep;
  // Contact detection's scratch; mutable because the end-of-step checks and
  // the static update limits query the wall from a const State.
  mutable ContactScratch contactScratch;
  PairSolveScratch pairSolve;  // the coupled solve's scratch (physics/pair_coupling.h)
};

// A State at rest in the model's rest shape, constraint targets at the rest
// poses, every scratch array sized for the model; with a device, the coil
// deployed to its initial length and twist (resetDevice).
State makeState(const Model& model);

// Adds `message` to state.warnings unless it is there already.
void warnOnce(State& state, const std::string& message);

}  // namespace coilsim
