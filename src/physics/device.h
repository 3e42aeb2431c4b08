#pragma once
// The device of a deployment run, split as the rest of a run is: what a run
// does not change (the coil, the catheter, the device's limits: Deployment,
// kept in Model::device) and what it does (deployed length, twist, catheter
// retraction, detached, the motions commanded and not yet finished:
// DeviceState, kept in State::device). Commands are inputs of the run, set
// on the State between steps by command() (physics/run.h), as MuJoCo's ctrl
// is set between two mj_step calls.
//
// Discretisation (Dequidt et al. 2008): a pusher advances the coil's
// proximal end; the coil leaves the catheter at its tip, clamped there in
// position and direction, with its material normal d1 on the catheter's
// reference normal turned by the transmitted twist (exactly as
// coil-measurement/1 defines the tip boundary condition). One chain rod holds
// the catheter's nodes 0..T (T = 0 for the rigid straight tip: a single held
// node; for the flexible catheter the proximal nodes are held, the tip region
// is free, node T is the tip) and then the coil's material nodes that are
// outside. Coil material nodes j = 0..N sit at material coordinate
// u_j = L - j h (j = 0 proximal, j = N the distal tip). With deployed length
// l, the first coil beam, from the tip node T to the first outside node k,
// is a partial beam of rest length delta = l - u_k kept in [h/2, 3h/2) (a
// node is inserted at the tip when delta reaches 3h/2 and withdrawn when it
// falls below h/2), so no beam ever becomes short and stiff. Its rest shape
// is the coil's between u = l and u_k, so material coordinate, mass and rest
// shape stay consistent while the coil slides.
//
// Inside a flexible catheter the coil is the paper's composite model
// (physics/catheter.h): each catheter element that holds coil material adds
// the coil's stiffness and mass, and its rest rotation blends the catheter's
// with the coil's there; these are rewritten in the State as the coil
// slides. Inside the rigid tip, and behind the catheter's base, the coil is
// not simulated. After detach the coil becomes a free rod of its own; the
// chain keeps the catheter (the tip node alone for the rigid tip).
#include <cmath>
#include <string>
#include <vector>

#include "physics/catheter.h"
#include "physics/element.h"
#include "physics/math.h"
#include "physics/rest_shape.h"
#include "physics/rod_spec.h"
#include "physics/section.h"

namespace coilsim {

// What a user specifies for a deployment (SI, checked by compileModel).
struct DeploymentDef {
  std::string coilName = "coil";
  RodSpec coil;           // length, rest shape (from the proximal end, u = L, to the distal tip, u = 0), material, section
  int coilBeams = 0;      // N; the material spacing is h = L / N
  Placement tip;          // catheter tip at rest: position, exit direction, reference normal (d1 at zero twist)
  double catheterOuterRadius = 0.3e-3;  // m, for drawing the rigid catheter (catheter.outerRadius for a flexible one)
  double catheterDrawLength = 0.02;     // m of rigid catheter drawn behind the tip
  CatheterDef catheter;                 // flexible, pre-shaped catheter (catheter.flexible) or the rigid tip
  double initialDeployed = 0;           // m of coil outside at the start
  double initialTwist = 0;              // rad
  double maxPushSpeed = 0.05;           // m/s: faster pushes are refused (a hand does not push 5 cm/s)
  double maxTwistRate = 4 * M_PI;       // rad/s
  // false: the rigid tip does not hold the coil's tip node; an effect that
  // models a compliant catheter holds it instead (the constraint stays,
  // holding no DOF, so the chain still counts as held for the static solver).
  bool tipClamped = true;
};

// Constants of a deployment (part of what a run does not change).
struct Deployment {
  int chainRod = -1, freeRod = -1, catheterRod = -1;  // indices in Model::rods
  double coilLength = 0, spacing = 0;
  int coilBeams = 0;
  std::vector<Vec3> restX;  // (N+1) coil rest points, canonical, j = 0 proximal
  std::vector<Quat> restF;  // (N+1) coil rest frames
  Material material;
  Section section;
  Placement tip;
  double maxPushSpeed = 0, maxTwistRate = 0;
  double initialDeployed = 0, initialTwist = 0;  // where makeState() puts the device, m and rad
  // The catheter part of the chain: nodes 0..tipNode (tipNode = 0: rigid tip).
  int tipNode = 0;
  CatheterDef catheter;
  Section catheterSection;
  Vec3 retractDirection = Vec3::UnitX();  // the held base's axis: retraction pulls back along it
  std::vector<double> catheterArc;        // (T+1) arc length of each catheter node from the base, m
  std::vector<Quat> catheterRel;          // (T) rest rotation of node e+1 in node e's frame
  std::vector<double> catheterChord;      // (T) rest chord length of element e
  std::vector<BeamRest> catheterBeams;    // (T) element constants of the catheter alone
  std::vector<NodeProps> catheterNodes;   // (T+1) the catheter's own lumped node properties
  bool flexible() const { return tipNode > 0; }
  // Rest pose of the coil at fractional material index j in [0, N]
  // (cubic Hermite positions, slerped frames).
  void restPose(double j, Vec3& x, Quat& f) const;
};

// The device as a clinician drives it: push and pull the coil at a speed, by
// a distance; twist at a rate, by an angle; detach; retract the catheter.
struct DeviceCommand {
  enum class Kind { Push, Pull, Twist, Stop, Detach, Retract };
  Kind kind = Kind::Stop;
  double rate = 0;    // m/s for push / pull / retract, rad/s for twist (signed: + right-hand about the exit direction)
  double amount = 0;  // m or rad to move; 0 = keep going until stopped or a limit is reached
};

struct TimedCommand {
  double time = 0;  // s
  DeviceCommand command;
};

// The motions under way: set by command(), advanced and ended by advance().
struct DeviceMotion {
  double pushRate = 0, pushLeft = 0;      // m/s (signed), m (<0: unlimited)
  double twistRate = 0, twistLeft = 0;    // rad/s (signed), rad
  double retractRate = 0, retractLeft = 0;
  bool pendingDetach = false;
  double caughtFor = 0;  // s a pull has strained the coil at the tip beyond what a free coil takes (run.cpp)
  bool moving() const { return pushRate != 0 || twistRate != 0 || retractRate != 0; }
};

// What a run changes of the device.
struct DeviceState {
  double deployed = 0;      // l, m
  double twist = 0;         // rad, about the exit direction
  double tipOffset = 0;     // m the catheter tip has been retracted along -direction
  bool detached = false;
  Vec3 releasedAt = Vec3::Zero();  // where the catheter tip was when the coil was detached, m
  int firstOutside = 0;     // k: first coil material node in the chain (N + 1: none)
  Vec3 tipStart = Vec3::Zero();    // where the catheter tip was at the start, m
  Vec3 exitStart = Vec3::UnitX();  // its exit direction then
  DeviceMotion motion;
  std::vector<std::string> notes;  // limits reached, detach done or refused ("coil fully deployed"), for UI and logs
};

}  // namespace coilsim
