#pragma once
// The Model: everything that does not change during a run (rest shape,
// stiffness, mass, constraints, effects and their parameter values). Build it
// with compileModel() from a ModelDef; several States may share one Model.
#include <array>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "physics/device.h"
#include "physics/draw_data.h"
#include "physics/effect.h"
#include "physics/element.h"
#include "physics/math.h"
#include "physics/rest_shape.h"
#include "physics/section.h"
#include "physics/sleep.h"
#include "physics/triangle_mesh.h"

namespace coilsim {

class ObstacleTree;  // physics/contact/obstacle_tree.h

// Degrees of freedom of a node, as bits: ux uy uz (global), rx ry rz (global).
enum DofMask : unsigned { kFreeDofs = 0, kTranslation = 0b000111, kRotation = 0b111000, kAllDofs = 0b111111 };

// Holds some DOFs of one node at a target pose. The target starts at the
// node's rest pose and moves with constant (angular) velocity unless a
// controller writes State targets itself: that is how push and twist drive it.
struct Constraint {
  int node = 0;
  unsigned mask = kAllDofs;          // clamped = kAllDofs, pinned = kTranslation
  Vec3 velocity = Vec3::Zero();      // m/s, prescribed motion of the target
  Vec3 angularVelocity = Vec3::Zero();  // rad/s, global axes
};

struct NodalLoad {
  int node = 0;
  Vec3 force = Vec3::Zero();   // N, global
  Vec3 moment = Vec3::Zero();  // N m, global
};

// What a user specifies for one rod (already in SI, already checked).
struct RodDef {
  std::string name = "rod";
  RodRole role = RodRole::Coil;
  double length = 0;  // m
  int beams = 0;
  RestCurve rest;     // canonical or placed curve with beams+1 samples
  Placement placement;  // applied to `rest` by compileModel
  Material material;
  Section section;
  std::vector<Constraint> constraints;
  std::vector<NodalLoad> loads;
};

struct RodModel {
  std::string name;
  RodRole role = RodRole::Coil;
  int nnode = 0;
  Material material;
  Section section;
  std::vector<Vec3> restPoints;    // (nnode) placed rest centre line
  std::vector<Quat> restFrames;    // (nnode) placed rest material frames
  std::vector<BeamRest> beams;     // (nnode-1)
  std::vector<double> nodeMass;    // (nnode) lumped mass, kg
  std::vector<Vec3> nodeInertia;   // (nnode) rotational inertia in the material frame (t, d1, d2), kg m^2
  std::vector<double> nodeLength;  // (nnode) length of rod each node stands for (half of each neighbour)
  std::vector<Constraint> constraints;
  std::vector<NodalLoad> loads;
  int nbeam() const { return nnode - 1; }
};

struct Damping {
  double massCoeff = 0;       // Rayleigh alpha, 1/s
  double stiffnessCoeff = 0;  // Rayleigh beta, s
};

// Limits beyond which a step counts as a numerical blow-up.
struct HealthLimits {
  double maxSpeed = 50.0;         // m/s: no coil moves this fast
  double maxAngularSpeed = 1e6;   // rad/s
  double maxAxialStrain = 0.5;    // a beam stretched or crushed by half
};

struct ModelDef {
  std::vector<RodDef> rods;
  Vec3 gravity = Vec3(0, 0, -9.81);  // m/s^2
  Damping damping;
  double timeStep = 1e-3;            // s
  int newtonIterations = 1;          // per dynamic step (1 = linearly implicit Euler)
  // Self and rod contacts solved with both sides moving (physics/pair_coupling.h),
  // off by default: on, plans and practice runs move (coils the lumped
  // drag held in a sac can leave it; docs/contact.md, "The coupled solve
  // switched on"). Off: each side holds the other at its start (the lumped
  // diagonal).
  bool coupledPairs = false;
  HealthLimits health;
  std::vector<EffectUse> effects;    // gravity is one of them
  std::vector<Obstacle> obstacles;   // walls the rods may touch (contact effects read them)
  SleepSettings sleep;               // off unless asked for (physics/sleep.h)
  // A coil deployed through a catheter: compileModel appends its rods (the
  // chain, the detached coil, the drawn catheter) after `rods`.
  std::optional<DeploymentDef> device;
};

struct Model {
  std::vector<RodModel> rods;
  Vec3 gravity = Vec3::Zero();
  Damping damping;
  double timeStep = 1e-3;
  int newtonIterations = 1;
  bool coupledPairs = false;
  HealthLimits health;
  std::vector<EffectUse> effects;
  std::vector<Obstacle> obstacles;
  SleepSettings sleep;
  std::vector<std::shared_ptr<const ObstacleTree>> obstacleTrees;  // (obstacles) collision trees, built by compileModel
  std::optional<Deployment> device;  // the deployment's constants, when the run has one
};

// Builds element constants, lumped masses and placed rest shapes, and the
// device's rods and constants (def.device). Throws PhysicsError (physics/failure.h)
// naming the rod (or the deployment) and the quantity on a non-positive or
// non-finite input, or a constraint/load on a missing node.
Model compileModel(const ModelDef& def);

// The effect use called `name`, or nullptr.
const EffectUse* findEffect(const Model& model, std::string_view name);
EffectUse* findEffect(Model& model, std::string_view name);

}  // namespace coilsim
