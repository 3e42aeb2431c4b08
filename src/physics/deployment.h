#pragma once
// Coil deployment out of a catheter tip (Dequidt et al. 2008): a pusher
// advances the coil's proximal end; the coil leaves the catheter at its tip,
// clamped there in position and direction, with its material normal d1 on
// the catheter's reference normal turned by the transmitted twist (exactly
// as coil-measurement/1 defines the tip boundary condition).
//
// Discretisation: one chain rod holds the catheter's nodes 0..T (T = 0 for
// the rigid straight tip: a single held node; for the flexible catheter the
// proximal nodes are held, the tip region is free, node T is the tip) and
// then the coil's material nodes that are outside. Coil material nodes
// j = 0..N sit at material coordinate u_j = L - j h (j = 0 proximal, j = N
// the distal tip). With deployed length l, node j is outside when
// l - u_j >= h/2 or so: the first coil beam, from the tip node T to the
// first outside node k, is a partial beam of rest length delta = l - u_k kept
// in [h/2, 3h/2) (a node is inserted at the tip when delta reaches 3h/2 and
// withdrawn when it falls below h/2), so no beam ever becomes short and
// stiff. Its rest shape is the coil's between u = l and u_k, so material
// coordinate, mass and rest shape stay consistent while the coil slides.
//
// Inside a flexible catheter the coil is the paper's composite model
// (physics/catheter.h): each catheter element that holds coil material
// (at arc distance d behind the tip lies u = l + d) adds the coil's
// stiffness and mass, and its rest rotation blends the catheter's with the
// coil's there; these are rewritten as the coil slides. Inside the rigid
// tip, and behind the catheter's base, the coil is not simulated. After
// detach the coil becomes a free rod of its own; the chain keeps the
// catheter (the tip node alone for the rigid tip).
#include <string>
#include <vector>

#include "physics/catheter.h"
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
  Placement tip;          // catheter tip at rest: position, exit direction, reference normal (d1 at zero twist)
  double catheterOuterRadius = 0.3e-3;  // m, for drawing the rigid catheter (catheter.outerRadius for a flexible one)
  double catheterDrawLength = 0.02;     // m of rigid catheter drawn behind the tip
  CatheterDef catheter;                 // flexible, pre-shaped catheter (catheter.flexible) or the rigid tip
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

struct DeploymentState {
  double deployed = 0;      // l, m
  double twist = 0;         // rad, about the exit direction
  double tipOffset = 0;     // m the catheter tip has been retracted along -direction
  bool detached = false;
  int firstOutside = 0;     // k: first coil material node in the chain (N + 1: none)
  Vec3 tipStart = Vec3::Zero();  // where the catheter tip was at the start, m
  Vec3 exitStart = Vec3::UnitX();  // its exit direction then
};

// The catheter tip as a clinician sees it.
struct CatheterTip {
  double kickback = 0;   // m the tip has moved back along its initial exit direction (retraction excluded)
  double angle = 0;      // rad between the tip's exit direction and the held base's axis now
  double restAngle = 0;  // rad, the same in the catheter's rest shape (the pre-shaped angle)
};
CatheterTip catheterTip(const Deployment& dep, const State& state, const DeploymentState& ds);

// Copies the chain's catheter nodes into the drawn catheter rod (a flexible
// catheter only; the drawn rod is held where they were at the last call).
void syncCatheterDrawing(const Deployment& dep, State& state);

// Appends the chain rod, the free (detached) coil rod and a drawn catheter
// to `def`; returns the constants. Throws std::invalid_argument naming the
// field on bad input (non-positive length, initial deployment beyond L,
// catheter bends longer than its free length...).
Deployment addDeployment(const DeploymentDef& d, ModelDef& def);

// Places the flexible catheter in its unloaded composite shape and the
// initially deployed part in its rest shape at the tip.
DeploymentState initDeployment(const Deployment& dep, const Model& model, State& state, double deployed, double twist);

// Slides the coil to deployed length `deployed` (clamped to [0, L]) and tip
// twist `twist`: inserts or withdraws nodes at the tip, rewrites the partial
// beam and node masses. Must be called between steps.
void setDeployment(const Deployment& dep, const Model& model, State& state, DeploymentState& ds, double deployed,
                   double twist);

// setDeployment for a static continuation: the coil outside also slides
// along its present centre line by the length pushed (the material at arc s
// from the tip goes where the arc s + delta was, beyond the distal end
// along its rest shape), as a slow push moves it. setDeployment alone
// leaves the nodes where they were and squeezes the pushed length into the
// first beam (a 2 mm push is a 100 N imbalance on a 0.2 mm wire), which a
// Newton iteration must then carry through every loop; with contacts each
// of its steps is held back where loops could pass through each other.
void slideDeployment(const Deployment& dep, const Model& model, State& state, DeploymentState& ds, double deployed,
                     double twist);

// The frame the coil has at the tip: the tip node's frame turned by the twist.
Quat coilFrameAtTip(const Deployment& dep, const RodState& chain, double twist);

// Moves the catheter back by `offset` m along its held base's axis (the
// exit direction for the rigid tip; the pusher holds the coil, so the
// deployed length grows by the same amount).
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
