#pragma once
// Contact detection at the start of a step: fills each rod's contact lists
// (physics/contact/contact_state.h), carries friction memory over from the
// last step and reports the normal force per node. The response is in
// response.h; the effects in physics/effects/*_contact.cpp tie them together.
#include <optional>
#include <string>

#include "physics/contact/response.h"
#include "physics/failure.h"
#include "physics/model.h"
#include "physics/state.h"

namespace coilsim {

// The wall's penalty starts this fraction of the wire radius outside the
// wire (a contact offset, as PhysX and Bullet keep one): a wire resting
// against the wall is then in the implicit solve before it touches, so a jolt
// within one step (a node inserted at the catheter tip shakes the whole coil)
// meets the wall's stiffness instead of going 15-18 um into it. The coil
// looks 5 % thicker to the wall: 7.5 um on a 0.15 mm wire.
inline constexpr double kWallSkin = 0.05;

// Capsules (segment, radius = the nodes' outer radius) against every
// obstacle's triangles, through its collision tree. One contact per segment
// and obstacle: the nearest triangle feature within radius + margin, its
// normal the direction from that feature to the centre line (so contacts on
// edges and vertices push the right way) and its side from the triangle
// normal: the free side is inside the closed surface (vessel lumen,
// aneurysm sac), so a coil in a sac is pushed inwards. A segment that was
// in contact and is now wholly beyond the wall (which no overlap query
// reports) is found by a wider nearest-feature search and pushed back.
// The search reaches what the segment sweeps in the step (margin + h |v|).
// Faces near the segment that fold towards the free side of the nearest
// face (a concave wall seen from the lumen, e.g. the inside of a sac) add
// their own planes: a node sliding off the nearest face's plane would
// otherwise go through the next face within the step (the plane of a face
// 0.6 mm away is 50 um off a 7 mm sphere). Faces that form a ridge into the
// free space do not, since their planes would cut it. At most 3 per segment.
// And each node of a segment in contact is bounded by the plane of its own
// nearest feature (a contact pressing that node only, ContactPoint::node)
// unless the segment's planes agree with it near the node: a plane tangent
// at the segment's nearest point can be 36 um off a 7 mm sac at the far
// node, and a free end node has no other segment.
// Catheter rods are rigid and skip wall contact.
// `law.stiffness` is per length; each rod presses with wallStiffness(law.stiffness, rigidityScale, rod).
void detectWallContacts(const Model& model, State& state, double h, double margin, const ContactLaw& law,
                        double rigidityScale);

// The wall's penalty stiffness per length for `rod`: `stiffness` (N/m per
// m), or `rigidityScale` (1/m^3) times the wire's bending rigidity over its
// radius, EI / r, when that is more. What a wire presses on a wall scales
// with EI in a given geometry (its elastic forces do; so does the load at
// which a wire pushed end-on buckles, pi^2 EI / (4 l^2)), and the
// penetration, load / stiffness, must stay a fraction of r: so the
// stiffness scales with EI / r (the measurements behind this:
// docs/contact.md, "The wall's stiffness scales with the wire"). Below
// `stiffness` (soft coils) the loads that matter are jolts (a node inserted
// at the catheter tip shakes the coil), not the wire's elasticity.
double wallStiffness(double stiffness, double rigidityScale, const RodModel& rod);

// Capsule pairs through a uniform grid over all segments (O(n) for a coil,
// not O(n^2)). sameRod: non-adjacent segments of one rod (self-contact);
// otherwise segments of different rods (coil-coil, coil-catheter). Rods
// that are inactive take no part; pairs of two catheters are skipped, and so
// are segments that share an end (a deploying coil leaves the catheter tip).
// `catheterLaw` is used when one side is a catheter.
void detectRodContacts(const Model& model, State& state, double h, bool sameRod, double margin, const ContactLaw& law,
                       const ContactLaw& catheterLaw);

// A pair contact that was not in a step's implicit solve (apart at the start
// and its start velocity not carrying it into touch) but which the step's
// own motion carried deeper than this fraction of r1 + r2 was missed: the
// linearisation did not know it. (A coil tip whipping off a loop reaches
// 0.1-0.3 m/s within one step from rest: 100-300 um, where the start
// velocity predicted nothing; see docs/contact.md.)
inline constexpr double kMissedContact = 0.05;

// After a step: the deepest segment pair that went deeper than
// kMissedContact into another segment without having been in the step's
// contacts (sameRod: self contacts, else between rods), as a MissedContact
// Failure naming the rod and beam (segment) and the other, with the depth
// and that tolerance (m); nothing if none did. The step is then taken again
// in substeps (Effect::endStep), each with its own detection. Costs a pass
// over the contact lists, or a grid scan when some node moved more than
// about margin / 2 in the step.
std::optional<Failure> checkRodContacts(const Model& model, const State& state, bool sameRod, double margin,
                             double radiusScale = 1);

// For a static Newton update dx (one position change per active node of rod
// `rod`): the largest fraction in (0, 1] of it after which no segment of the
// rod has come closer than half its present centre-line distance to a
// non-adjacent segment of its own (sameRod) or to a segment of another rod
// (held still meanwhile). A segment moves at most as far as its farther
// node, so centre lines never cross within the update: a full Newton step
// can carry a sagging loop through the wire it is about to land on, and no
// penalty brings it back from the far side.
// Pairs count as touching at radiusScale (r1 + r2) (ContactLaw); none when it is 0.
double safeStaticFraction(const State& state, int rod, std::span<const Vec3> dx, bool sameRod, double radiusScale = 1);

// After a step: the segment that went deepest beyond what the step's
// contact planes allowed, by more than kMissedContact of its radius, into a
// wall, as a MissedContact Failure naming the rod, beam (segment) and
// obstacle, with that excess depth and the tolerance (m); nothing if none. A
// plane is the wall's tangent at detection; a node sliding fast along a
// curved wall leaves it (1 mm along a 7 mm sphere is 0.14 mm deep, and a
// frictionless coil tip skating at 1 m/s does that within one step). A
// plane bounds only the nodes it pressed from the step's start; a node that
// one of the step's Newton iterates carried in (ContactPoint::pressed) is
// judged by where the iterations left it. Only segments with a node that
// moved farther than its nearest wall outside the step's solve (at most
// `margin`) are queried: a node at rest against a wall, listed but not
// closing, that a jolt moves in within the step (up to the margin deep) is
// caught too.
// heldOnly: the wall is held by constraints (ContactLaw::rigid), so a
// plane bounds a node only if the step's solve held the node on it (its
// multiplier); a plane the node rode along unheld is judged as one outside
// the solve.
std::optional<Failure> checkWallContacts(const Model& model, const State& state, double margin, bool heldOnly);

}  // namespace coilsim
