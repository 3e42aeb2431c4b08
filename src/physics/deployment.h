#pragma once
// Coil deployment out of a catheter tip: building the device's rods and
// constants, and moving the coil through the tip between steps. What the
// device is and how it is discretised: physics/device.h. These functions
// act on the run's own device (Model::device, State::device); the model
// must have one.
#include <optional>
#include <string>

#include "physics/device.h"
#include "physics/failure.h"
#include "physics/model.h"
#include "physics/state.h"

namespace coilsim {

// The catheter tip as a clinician sees it.
struct CatheterTip {
  double kickback = 0;   // m the tip has moved back along its initial exit direction (retraction excluded)
  double angle = 0;      // rad between the tip's exit direction and the held base's axis now
  double restAngle = 0;  // rad, the same in the catheter's rest shape (the pre-shaped angle)
};
CatheterTip catheterTip(const Model& model, const State& state);

// Copies the chain's catheter nodes into the drawn catheter rod (a flexible
// catheter only; the drawn rod is held where they were at the last call).
void syncCatheterDrawing(const Model& model, State& state);

// Appends the chain rod, the free (detached) coil rod and a drawn catheter
// to `def`; returns the constants. compileModel calls it for ModelDef::device.
// Throws PhysicsError (physics/failure.h) naming the field on bad input (non-positive
// length, initial deployment beyond L, catheter bends longer than its free
// length...).
Deployment addDeployment(const DeploymentDef& d, ModelDef& def);

// Puts the device back to its start with `deployed` m out and `twist`: the
// flexible catheter in its unloaded composite shape, the deployed part in
// its rest shape at the tip, no motion under way, not detached.
void resetDevice(const Model& model, State& state, double deployed, double twist);

// Slides the coil to deployed length `deployed` (clamped to [0, L]) and tip
// twist `twist`: inserts or withdraws nodes at the tip, rewrites the partial
// beam and node masses. Must be called between steps; does nothing once
// detached.
void setDeployment(const Model& model, State& state, double deployed, double twist);

// setDeployment for a static continuation: the coil outside also slides
// along its present centre line by the length pushed (the material at arc s
// from the tip goes where the arc s + delta was, beyond the distal end
// along its rest shape), as a slow push moves it. setDeployment alone
// leaves the nodes where they were and squeezes the pushed length into the
// first beam (a 2 mm push is a 100 N imbalance on a 0.2 mm wire), which a
// Newton iteration must then carry through every loop; with contacts each
// of its steps is held back where loops could pass through each other.
void slideDeployment(const Model& model, State& state, double deployed, double twist);

// The frame the coil has at the tip: the tip node's frame turned by the twist.
Quat coilFrameAtTip(const Deployment& dep, const RodState& chain, double twist);

// The elastic force of the first beam outside the catheter on the tip node:
// what the coil does to the catheter, N (zero with nothing outside).
Vec3 coilForceOnTip(const Deployment& dep, const State& state);

// Moves the catheter back by `offset` m along its held base's axis (the
// exit direction for the rigid tip; the pusher holds the coil, so the
// deployed length grows by the same amount).
void setTipOffset(const Model& model, State& state, double offset);

// Releases the coil from the pusher: the free rod takes the chain's coil
// nodes (the proximal end where the tip node is), the chain keeps the tip.
// Returns nothing, or why it is refused (a DeviceRefusal: the coil not fully
// out, detached already), and then changes nothing. Front ends detach
// through command() (a pending detach that advance() carries out).
std::optional<Failure> detach(const Model& model, State& state);

// Coil arc length and mass as the state's node bookkeeping represents them
// now (outside part plus the part still inside), for conservation checks.
double representedCoilLength(const Model& model, const State& state);
double representedCoilMass(const Model& model, const State& state);

}  // namespace coilsim
