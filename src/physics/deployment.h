#pragma once
// Coil deployment out of a catheter tip (Dequidt et al. 2008): a pusher
// advances the coil's proximal end; the coil leaves the catheter at its tip,
// clamped there in position and direction, with its material normal d1 on
// the catheter's reference normal turned by the transmitted twist (exactly
// as coil-measurement/1 defines the tip boundary condition).
//
// Discretisation: one chain rod starts at the tip node (held at the tip
// pose) and continues with the coil's material nodes that are outside. Coil
// material nodes j = 0..N sit at material coordinate u_j = L - j h (j = 0
// proximal, j = N the distal tip). With deployed length l, node j is outside
// when l - u_j >= h/2 or so: the first beam, from the tip to the first
// outside node k, is a partial beam of rest length delta = l - u_k kept in
// [h/2, 3h/2) (a node is inserted at the tip when delta reaches 3h/2 and
// withdrawn when it falls below h/2), so no beam ever becomes short and
// stiff. Its rest shape is the coil's between u = l and u_k, so material
// coordinate, mass and rest shape stay consistent while the coil slides.
//
// Inside the catheter the coil is not simulated: the catheter is rigid and
// straight (a flexible catheter with the paper's composite rest shape is
// still to come; see the README). After detach the coil becomes a free rod
// of its own; the chain keeps only the tip node.
#include <string>
#include <vector>

#include "physics/model.h"
#include "physics/state.h"

namespace coilsim {

struct DeploymentDef {
  std::string coilName = "coil";
  double coilLength = 0;  // m
  int coilBeams = 0;      // N; the material spacing is h = L / N
  RestCurve coilRest;     // canonical, from the proximal end (u = L) to the distal tip (u = 0)
  Material coilMaterial;
  Section coilSection;
  Placement tip;          // catheter tip: position, exit direction, reference normal (d1 at zero twist)
  double catheterOuterRadius = 0.3e-3;  // m, for drawing the catheter
  double catheterDrawLength = 0.02;     // m of catheter drawn behind the tip
  double initialDeployed = 0;           // m of coil outside at the start
  double initialTwist = 0;              // rad
  double maxPushSpeed = 0.05;           // m/s: faster pushes are refused (a hand does not push 5 cm/s)
  double maxTwistRate = 4 * M_PI;       // rad/s
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
  // Rest pose of the coil at fractional material index j in [0, N]
  // (cubic Hermite positions, slerped frames).
  void restPose(double j, Vec3& x, Quat& f) const;
};

struct DeploymentState {
  double deployed = 0;      // l, m
  double twist = 0;         // rad, about the exit direction
  double tipOffset = 0;     // m the catheter tip has been retracted along -direction
  bool detached = false;
  int firstOutside = 0;     // k: first coil material node in the chain (N + 1: none)
};

// Appends the chain rod, the free (detached) coil rod and a drawn catheter
// to `def`; returns the constants. Throws std::invalid_argument naming the
// field on bad input (non-positive length, initial deployment beyond L...).
Deployment addDeployment(const DeploymentDef& d, ModelDef& def);

// Places the initially deployed part in its rest shape at the tip.
DeploymentState initDeployment(const Deployment& dep, const Model& model, State& state, double deployed, double twist);

// Slides the coil to deployed length `deployed` (clamped to [0, L]) and tip
// twist `twist`: inserts or withdraws nodes at the tip, rewrites the partial
// beam and node masses. Must be called between steps.
void setDeployment(const Deployment& dep, const Model& model, State& state, DeploymentState& ds, double deployed,
                   double twist);

// Moves the catheter tip back by `offset` m along its exit direction (the
// pusher holds the coil, so the deployed length grows by the same amount).
void setTipOffset(const Deployment& dep, State& state, DeploymentState& ds, double offset);

// Releases the coil from the pusher: the free rod takes the chain's coil
// nodes (the proximal end where the tip node is), the chain keeps the tip.
// Returns an empty string, or why it is refused (coil not fully out, done already).
std::string detach(const Deployment& dep, const Model& model, State& state, DeploymentState& ds);

// Coil arc length and mass as the state's node bookkeeping represents them
// now (outside part plus the part still inside), for conservation checks.
double representedCoilLength(const Deployment& dep, const State& state, const DeploymentState& ds);
double representedCoilMass(const Deployment& dep, const State& state, const DeploymentState& ds);

}  // namespace coilsim
