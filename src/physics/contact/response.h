#pragma once
// Contact response shared by the wall, self and rod contact effects.
//
// Model: penalty contact with its implicit stiffness and damping on the
// diagonal 6x6 blocks, plus regularised Coulomb friction.
//  - Normal: f = k * penetration (point contacts, N/m) or, for walls, k per
//    length times the segment's length times its deepest penetration below
//    the wall's tangent plane, shared between the nodes by the centroid of
//    the penetrating part (line contacts, N/m per m): a segment lying along
//    the wall is carried by both nodes, not by whichever end a closest-point
//    query returns, and one hitting end-on is as stiff. Damping
//    c = 2 zeta sqrt(k m) along the normal.
//    k n n^T and c n n^T go into the implicit matrix (lumped by rows onto
//    the segment's two nodes), which is what keeps a stiff penalty from
//    jittering at 1 ms steps. Why penalty and not constraints on the
//    compliance (SOFA): it keeps the one O(n) block-tridiagonal solve per rod
//    and needs no second solve or LCP, and the measured penetration stays
//    far below the 10 % of the wire radius the tests require.
//  - What the diagonal blocks cannot hold: the coupling between the two
//    segments of a self or rod contact (distant nodes: outside the block
//    tridiagonal band). Each side treats the other as moving with its
//    start-of-step velocity; doubling the stiffness and damping on the
//    diagonal (implicitScale = 2) makes each side take half of the closing
//    motion, which is exact for two equal masses and stable for any stiffness.
//  - Friction: a tangential spring k_t = ratio * k anchored where the contact
//    started sticking (slip vector in ContactPoint), capped at mu_s Fn to
//    start sliding and mu_d Fn while sliding (Coulomb with static and dynamic
//    coefficients; the hysteresis stops stick-slip chatter). While sticking
//    its stiffness and a tangential damping are implicit; while sliding the
//    force is mu_d Fn against the slip and only its direction is stiff. The
//    regularisation allows a creep of at most mu_s Fn / k_t (micrometres)
//    before sliding. Friction on a 0.4 mg node is far stronger than its
//    inertia (mu Fn h / m is metres per second), so the cap must be found
//    inside the implicit solve: the spring is evaluated at the current
//    positions, and each further Newton iteration of the step
//    (Model::newtonIterations) re-decides stick or slide. With one iteration
//    a contact that starts to slide sticks for that step (stable, slightly
//    too much friction); use 3 when sliding speed matters.
//  - Forces act on the centre line (no moment from the contact offset r):
//    coil rolling is not modelled.
#include <span>

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
};

struct NormalEval {
  double force = 0;          // elastic normal force, N (>= 0)
  double wa = 0.5, wb = 0.5; // share of node a and b (sum 1 when in contact)
  double stiffness = 0;      // d force / d approach, N/m
  bool touching = false;
};

// Normal penalty of contact c at the rod's current positions.
NormalEval evalNormal(const ContactPoint& c, const RodState& rod, const ContactLaw& law);

// Updates c's friction memory from the matched contact of the last step
// (or none), the rod's velocities and step h; sets c.normalForce.
void updateContact(ContactPoint& c, const ContactPoint* previous, const RodState& rod, const ContactLaw& law, double h);

// The last step's contact of `list` (sorted by segment) that continues `c`:
// same other body, segment within one (nodes are inserted at a deploying
// tip), nearest contact point; nullptr if none.
const ContactPoint* findPrevious(std::span<const ContactPoint> list, const ContactPoint& c, const RodState& rod);

// Adds the forces, stiffness and damping of `contacts` to the rod's arrays.
void applyContacts(std::span<const ContactPoint> contacts, const RodState& rod, const ContactLaw& law, RodForces& out);

// Sums c.normalForce onto the nodes (per-node report) and returns the largest
// penetration among `contacts`.
double reportContacts(std::span<const ContactPoint> contacts, const RodState& rod, const ContactLaw& law,
                      std::vector<double>& nodeForce);

}  // namespace coilsim
