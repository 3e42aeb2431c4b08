#pragma once
// The contact set of a step that solves its pair contacts coupled
// (physics/pair_coupling.h), decided within the step.
//
// Detection lists every pair within reach; the step's solve holds those
// touching at its start or closing at its start velocities. A coupled step
// moves a packing in its rows' null space, which the lumped diagonal's
// drag held still, and so carries nodes into neighbours left just apart:
// a pair entering 2 um deep stores k pen^2 / 2 (1e5 pJ at 50 N/mm) that
// no force paid for, and the next step gives it back as motion; the wall's
// nodes likewise. So each pair (and wall node) the solve carried into touch
// from outside it is marked entered (ContactPoint::entered) on both sides'
// lists, and the step is taken again from its start with it in the solve
// under the affine law, so that it lands where it presses.
#include <span>
#include <vector>

namespace coilsim {

struct RodState;

// Clears the marks of an earlier solve (a retaken step's first substep
// keeps the interval's lists).
void clearEnteredContacts(std::vector<RodState>& rods);

// Marks entered each pair of the stepped rods' self and rod contact lists
// (and each wall contact's node) that was apart at the step's start
// (work.x0) and not closing, and touches at the rods' current positions,
// and unmarks each marked one that ends apart again (its affine force
// pulled); marks released each pair, on both sides' lists, and each wall
// node whose spring the solve held (PairCoupling, physics/wall_spring.h)
// but whose solved force pulled its sides together (a closing contact
// that the solve turned away, held by its stiffness as if glued), and
// takes back in one let go that ended deeper than it started; returns how
// many marks changed.
int reviseContactSet(std::vector<RodState>& rods, std::span<const char> stepped);

// Sets each pair contact's anchor and other-side velocity (ContactPoint::
// anchor, otherVelocity) of the stepped rods to the other side's current
// iterate. Detection leaves them at the other side's start, which is all a
// lumped step (each side holding the other there) or a coupled step's first
// Newton iterate needs; a later iterate of a coupled step has moved both
// sides, and its force must be evaluated where both are, or the step's
// Newton iterations do not converge to its implicit equations (the other
// side's motion would count twice: once in the coupling rows, once more as
// penetration of a still anchor).
void followOtherSides(std::vector<RodState>& rods, std::span<const char> stepped);

// Each stepped rod's coil-coil and self contact forces per node
// (RodContacts::selfForce, rodForce) as the step's solve applied them, in
// place of detection's penalty at the step's start: each coupling's normal
// law k (pen - springFrom) - c (approach) at the step's end positions and
// velocities, at least 0. The solve holds a closing or held contact by
// its stiffness alone, with no penetration at detection, so the penalty
// at the start says 0 for a coil pressed on a packing; this is the force
// that stopped it (the step's momentum change, to the linearisation).
void reportSolvedPairForces(std::vector<RodState>& rods, std::span<const char> stepped);

// Each stepped rod's wall force per node (RodContacts::wallForce) as the
// same step's solve applied it: each wall node's spring of the last Newton
// iterate (physics/wall_spring.h), its force there carried to the step's
// end positions and velocities by the stiffness and damping the solve's
// matrix held, at least 0. Detection's penalty at the step's start says 0
// for a node the solve holds by its stiffness alone (closing, held), which
// in a packing at rest is a third of what its wall carries.
void reportSolvedWallForces(std::vector<RodState>& rods, std::span<const char> stepped);

}  // namespace coilsim
