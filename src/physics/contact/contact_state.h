#pragma once
// What the contact effects remember between steps, per rod: the contacts
// found at the start of the step (with their friction memory) and the
// contact forces per node, for wall-load warnings, planning and drawing.
// Detection fills these in Effect::beginStep; apply() only reads them.
#include <vector>

#include "physics/contact/triangle_cache.h"
#include "physics/math.h"
#include "physics/node_friction.h"

namespace coilsim {

enum class ContactKind { Wall, Self, Rod };

// How a contact that a step's solve carried into touch is held when the
// step is taken again (ContactPoint::entered); Released: one the step's
// solve held and found pulling, which the step taken again leaves out.
enum class Entry : unsigned char { No, Affine, Held, Released };

// One contact of a segment (nodes a, a + 1) of this rod with a wall or another segment.
struct ContactPoint {
  int segment = 0;            // node a = segment, node b = segment + 1
  int other = 0;              // obstacle index (wall) or rod index (self, rod)
  int otherSegment = -1;      // segment of the other rod (-1 for walls)
  bool line = false;          // wall: line contact along the segment; else a point at s
  int node = -1;              // line contacts: -1 presses both nodes; 0 or 1 only node a or b (that node's own wall)
  double s = 0;               // point on the segment, in [0, 1] (line: force centroid)
  double otherS = 0;          // pair contacts: the point on the other segment, in [0, 1]
  Vec3 normal = Vec3::UnitZ();  // unit, the direction this rod is pushed
  Vec3 anchor = Vec3::Zero();   // a point of the other surface (wall plane point or other centre-line point)
  double radius = 0;          // clearance the centre line keeps from `anchor` plane (r or r1 + r2)
  double gap = 0;             // clearance at detection, m (< 0: penetration)
  Vec3 otherVelocity = Vec3::Zero();  // velocity of the other surface point at detection
  double otherMass = 0;        // pair contacts: the other side's mass at its point, kg (the coupled solve's damping)
  double normalForce = 0;     // penalty normal force at detection, N
  // Whether the start-of-step relative velocity carries the contact into
  // touch before the step ends (line contacts: per node a, b; point
  // contacts: closing[0]). Such a contact is active in this step's implicit
  // solve even though it does not touch yet (speculative contact; see
  // response.h).
  bool closing[2] = {false, false};
  // Line contacts: whether one of this step's Newton iterates has carried
  // node a, b into the plane although it was neither pressed nor closing at
  // the start. The node then stays in the solve for the step's remaining
  // iterates, like a closing one (response.cpp, applyContacts); the wall's
  // end-of-step check still counts it as outside the step's linearisation.
  // Mutable: set through the const contact lists the effects read.
  mutable bool pressed[2] = {false, false};
  // Whether a solve of this step carried the pair (point contacts:
  // entered[0]) or node a, b (line contacts) into touch from outside the
  // solve, apart and not closing at the start (a step that solves its pair
  // contacts coupled decides its contact set within the step,
  // physics/pair_contact_set.h), and how the step taken again holds it.
  // Affine: f = k pen, negative while still apart, for a contact that
  // started within a hair of touch (the step's own solve has found that it
  // closes, so it lands where it presses, and the force reported is the one
  // that holds it). Held: a barrier at its start position, as a closing
  // contact, for one that started further apart (k times a micrometre gap
  // is tens of mN pulling across a linearisation that does not follow it).
  // Released (wall nodes): in the solve (pressing, closing or held) but
  // its solved force pulled the node onto the wall; a wall only pushes, so
  // the step taken again leaves the node out of the solve.
  Entry entered[2] = {Entry::No, Entry::No};
  // Line contacts held as constraints (ContactLaw::rigid): the multiplier,
  // the force the wall exerts on node a, b, N: from the last step's
  // matching contact at detection, then from each of the step's solves.
  mutable double multiplier[2] = {0, 0};
  // Friction memory: elastic tangential displacement of the regularised
  // Coulomb spring (the stick point is contact point - slip) and whether the
  // contact slides (dynamic coefficient) or sticks (static).
  Vec3 slip = Vec3::Zero();
  bool sliding = false;
  Vec3 at = Vec3::Zero();     // the contact point on this rod at detection (slip grows from here within a step)
};

struct RodContacts {
  std::vector<ContactPoint> wall, self, rod;  // this step's contacts, sorted by segment
  std::vector<ContactPoint> previous;         // scratch: last step's wall list while matching
  std::vector<double> wallForce;  // (nnode) normal force from walls per node, N
  std::vector<double> selfForce;  // (nnode) normal force from self-contact per node, N
  std::vector<double> rodForce;   // (nnode) normal force from other rods per node, N
  // Walls held by constraints (ContactLaw::rigid): each node's friction as
  // the last step's solve left it, and as this step's solves leave it (the
  // wall's detection moves the second into the first; a retaken step
  // starts again from the first). Per node, not per contact: a node's
  // contacts change from step to step, its friction does not.
  std::vector<NodeFrictionMemory> wallFrictionBefore;         // (nnode)
  mutable std::vector<NodeFrictionMemory> wallFrictionAfter;  // (nnode) written through the const State the effects see
  int wallFrictionNodes = -1;  // the active nodes when wallFrictionAfter was written
  double wallPenetration = 0;     // deepest wall penetration of the wire (not its skin) at the last detection, m (>= 0)
  // The deepest wallPenetration of the detections since the step's record
  // took it (dynamics.cpp): a step retaken in substeps detects again in
  // each, and its first detection (the state the last step left) counts too.
  double wallPenetrationPeak = 0;
  // Temporal coherence of the wall search: per segment, a distance within
  // which no wall triangle lay at its last full query (0: none known), and
  // its two end points then. Valid while the rod keeps `wallClearNodes`
  // active nodes (a deployment inserting a node renumbers the segments).
  std::vector<double> wallClear;  // (nnode - 1)
  std::vector<Vec3> wallClearAt;  // (2 (nnode - 1))
  int wallClearNodes = -1;
  // Per segment and obstacle, the triangle nearest to it at its last query
  // (-1: none): where the next query starts. Only a guess, never trusted.
  std::vector<int> wallHint;  // ((nnode - 1) x nobstacle)
  // Per segment and obstacle, its last walk of the collision tree: its
  // queries filter these triangles while their boxes stay within it.
  std::vector<TriangleCache> wallCache;  // ((nnode - 1) x nobstacle)
};

}  // namespace coilsim
