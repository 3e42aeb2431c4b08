#pragma once
// Contact response shared by the wall, self and rod contact effects.
//
// Model: penalty contact with its implicit stiffness and damping on the
// diagonal 6x6 blocks, plus regularised Coulomb friction.
//  - Normal, walls (line contacts): the wall is the tangent plane of the
//    nearest triangle feature (anchor, normal). Each node of the segment is
//    pressed into that plane with k L / 2 times its own penetration (k per
//    length of rod, L the segment length), so a segment lying on the wall
//    carries k per length exactly, a node shared by two touching segments
//    carries k times its Voronoi length, and the force on a node depends on
//    that node only: the diagonal stiffness block IS the exact Jacobian (a
//    law coupling the two nodes would need blocks the diagonal cannot hold;
//    docs/contact.md). A contact with
//    ContactPoint::node >= 0 is a node's own nearest plane and presses that
//    node only (detect.h). A node that a Newton iterate carried into its
//    plane stays in the step's solve like a closing one (pressed).
//  - Normal, segment pairs (self and rod contacts, point contacts): k times
//    the penetration at the closest points, shared (1 - s, s); the diagonal
//    gets the row sums k (1 - s), k s, which bound the rank-one Jacobian from
//    above, so the lumping only adds numerical damping.
//  - Damping c = 2 zeta sqrt(k m) along the normal (per node for walls).
//    k n n^T and c n n^T go into the implicit matrix, which is what keeps a
//    stiff penalty from jittering at 1 ms steps.
//  - Speculative contacts: a linearly implicit step only resists what is in
//    its matrix, so a contact that does not touch at the start of the step
//    is invisible to it, and a fast loop (0.6 m/s is four wire radii per
//    1 ms step) would tunnel into the wall before the next step saw it
//    (measured in docs/contact.md). Detection therefore searches the swept reach (margin + h |v|) and marks
//    a contact `closing` when the start-of-step velocity would carry it into
//    touch within the step; a closing node that does not touch yet gets the
//    penalty's stiffness but no force (a barrier at its start position), so
//    the implicit solve stops its approach. (The affine alternative,
//    f = k * penetration also while apart, lands the node on the wall but
//    pulls with k times the gap when the prediction is wrong: it fed energy
//    into the coil.) Walls also keep a skin (kWallSkin in detect.h) and the
//    planes of concave neighbour faces (detect.h).
//  - Walls in a dynamic step may instead be a unilateral constraint per
//    node and plane (ContactLaw::rigid, physics/unilateral.h), solved in
//    the same O(n) band: the penalty's largest load during a push followed
//    its stiffness (a strike bounces on a spring the step meets only at its
//    start). Friction under it is capped by the multiplier of the same
//    solve (physics/node_friction.h). Not the default: docs/contact.md
//    says what still fails with it.
//  - What the diagonal blocks cannot hold: the coupling between the two
//    segments of a self or rod contact (distant nodes: outside the block
//    tridiagonal band). Each side treats the other as moving with its
//    start-of-step velocity; doubling the stiffness and damping on the
//    diagonal (implicitScale = 2) makes each side take half of the closing
//    motion, which is exact for two equal masses and stable for any stiffness.
//  - Friction: a tangential spring k_t = ratio * k anchored where the contact
//    started sticking (slip vector in ContactPoint), capped at mu_s Fn to
//    start sliding and mu_d Fn while sliding (Coulomb with static and dynamic
//    coefficients; the hysteresis stops stick-slip chatter). Stick or slide
//    is decided on the slip the step will have at its start velocity. While
//    sticking the spring and a tangential damping are implicit. While
//    sliding the force is the secant of Coulomb's law through that predicted
//    slip, sigma = mu_d Fn / |slip ahead|, implicit too: exactly mu_d Fn if
//    the step slips as predicted, less if the solve stops the node, so it
//    can never reverse the motion. (A constant mu_d Fn is explicit along the
//    slip; on a 0.4 mg node mu Fn h / m is metres per second, and it drove a
//    coil loop to snap at 1.6 m/s.) When the slip accelerates, the secant
//    overestimates friction by a h / v: 1 % on the inclined-plane test. The
//    regularisation allows a creep of at most mu_s Fn / k_t (micrometres).
//  - Forces act on the centre line (no moment from the contact offset r):
//    coil rolling is not modelled.
#include <algorithm>
#include <span>
#include <vector>

#include "physics/contact/contact_state.h"
#include "physics/effect.h"

namespace coilsim {

struct RodState;

struct ContactLaw {
  double stiffness = 0;        // N/m per contact, or N/m per m of rod for line contacts
  double dampingRatio = 1;     // of critical, for the node mass
  double frictionStatic = 0, frictionDynamic = 0;
  double frictionStiffnessRatio = 0.5;  // k_t / k
  double implicitScale = 1;    // 2 when the other side moves too (see above)
  // Pairs: the contact distance over r1 + r2. A wound coil's outer radius
  // is larger than the radius of the solid wire that has its stiffness.
  double radiusScale = 1;
  // Walls (line contacts) in a dynamic step: each node held by a unilateral
  // constraint against its planes instead of the penalty (physics/
  // unilateral.h; docs/contact.md, "Why a constraint per node against the
  // wall"); the normal force is the constraint's multiplier, and
  // `stiffness` only sets the friction's stick spring. Static solves keep
  // the smoothed penalty.
  bool rigid = false;
};

struct NormalEval {
  double fa = 0, fb = 0;     // elastic normal force on node a and b, N (negative: a closing contact still apart)
  double ka = 0, kb = 0;     // their diagonal stiffness d f / d approach, N/m
  bool touching = false;     // active in this step (penetrating or closing)
  double force() const { return std::max(0.0, fa) + std::max(0.0, fb); }  // pushing force, N
  double wb() const {  // where the pushing force acts on the segment, in [0, 1]
    const double f = force();
    return f > 0 ? std::max(0.0, fb) / f : (ka + kb > 0 ? kb / (ka + kb) : 0.5);
  }
};

// Penetration of node a (end = 0) or b (end = 1) of line contact c below
// its plane, at positions x, m (< 0: apart).
double nodePenetration(const ContactPoint& c, const std::vector<Vec3>& x, int end);

// Normal penalty of contact c at the rod's current positions (a rigid line
// contact: its multipliers, with the penalty's stiffness for friction).
NormalEval evalNormal(const ContactPoint& c, const RodState& rod, const ContactLaw& law);

// Sets c.closing from the rod's (and the other surface's) velocities at the
// start of a step of length h; returns whether any part of c touches or closes.
bool markClosing(ContactPoint& c, const RodState& rod, double h);

// Updates c's friction memory from the matched contact of the last step
// (or none), the rod's velocities and step h; sets c.normalForce.
void updateContact(ContactPoint& c, const ContactPoint* previous, const RodState& rod, const ContactLaw& law, double h);

// The last step's contact of `list` (sorted by segment) that continues `c`:
// same other body, segment within one (nodes are inserted at a deploying
// tip), nearest contact point; nullptr if none.
const ContactPoint* findPrevious(std::span<const ContactPoint> list, const ContactPoint& c, const RodState& rod);

// Adds the forces, stiffness and damping of `contacts` to the arrays of the
// context's rod for a step of length ctx.timeStep. In a static solve
// (ctx.solve, with out.coupling set) the
// contacts act without friction or damping and give their exact stiffness
// for fixed contact points and normal, -d f_i / d x_j = k w_i w_j n n^T
// (w = (1 - s, s) on this segment, -(1 - t, t) on the other), coupling the
// other segment's nodes too when `sameRod` (self-contact: both sides move in
// the same solve; another rod is held while this one is solved).
void applyContacts(std::span<const ContactPoint> contacts, const EffectContext& ctx, const ContactLaw& law,
                   RodForces& out, bool sameRod = false);

// Sums c.normalForce onto the nodes (per-node report) and returns the largest
// penetration among `contacts`.
double reportContacts(std::span<const ContactPoint> contacts, const RodState& rod, const ContactLaw& law,
                      std::vector<double>& nodeForce);

}  // namespace coilsim
