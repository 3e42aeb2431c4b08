#pragma once
// The force-limited pusher. A hand advances the coil at the speed it is
// asked to only while the axial force it must apply stays below a limit
// (Deployment::maxPushForce); above it the push stalls: the insertion slows
// so that the force stays at the limit, which is the resistance a clinician
// feels. Without it the prescribed insertion drove a jammed, practically
// inextensible coil (EA of thousands of newtons) into the wall with the
// wall's penalty as the only compliance in series, and the wall load grew
// with the penalty stiffness (docs/contact.md, "The pusher's force limit").
//
// How it is solved. moveDevice sets the chain for the whole commanded
// insertion d (the partial beam at the tip lengthened by d) and arms the
// pusher with the partial beam as it was before. In the chain's implicit
// step the right-hand side is affine in the inserted fraction s of d (only
// the partial beam's rest constants depend on it), so with the matrix
// factorized once the velocity change is dv(s) = dv(1) - (1 - s) y, y the
// response to the difference of the beam's forces, one more back
// substitution. The pusher's force at the end of the step, N(s), is the
// partial beam's axial force on the tip node along the exit direction;
// s = 1 when N(1) is within the limit (the step is then exactly the
// unlimited one), else the s in [-1, 1) at which N(s) equals the limit,
// N taken affine between s = 0 and s = 1 (a pusher that the coil pushes
// back harder than the limit yields, at most at the commanded speed).
// advance() then sets the deployed length to the insertion reached. A step
// that inserts or withdraws a node at the tip is not limited: the new node,
// placed on the chord of a curved beam, jolts the partial beam by itself
// (newtons for the stiff coils), which the limit would take for resistance
// and stall on for ever at that node.
#include "physics/model.h"
#include "physics/state.h"

namespace coilsim {

// After moveDevice has set the chain for l = deployedBefore + commanded:
// arms the pusher for this step when a push is under way (commanded > 0)
// and the coil has a partial beam outside the tip; disarms it otherwise.
void armPusher(const Model& model, State& state, double deployedBefore, double commanded, double rate,
               double leftBefore);

// In the implicit step of the chain rod, after the solve: chain.work.rhs
// holds the velocity change for the whole commanded insertion and
// chain.work.solver the step's factorized matrix (x0, q0 the poses at the
// start of the step, v, w this iterate's velocities, h the step). Replaces
// the velocity change by that of the insertion the limit allows and records
// the fraction and the pusher's force in `pusher`. Does nothing unless armed.
void limitPushInStep(const Deployment& dep, PusherState& pusher, RodState& chain, double h);

// After the step: sets the deployed length to what the pusher inserted
// (when it stalled), keeps the push going for what is left, notes a stall
// when it begins. A refused step leaves the device as moveDevice set it.
void finishPush(const Model& model, State& state, bool stepOk);

}  // namespace coilsim
