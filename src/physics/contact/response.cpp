#include "physics/contact/response.h"

#include <algorithm>
#include <cmath>

#include "physics/state.h"

namespace coilsim {
namespace {

// Point of the segment at parameter s.
Vec3 along(const std::vector<Vec3>& x, const ContactPoint& c, double s) {
  return (1 - s) * x[c.segment] + s * x[c.segment + 1];
}

// Velocity of this rod's contact point relative to the other surface.
Vec3 relativeVelocity(const ContactPoint& c, const RodState& rod, double s) {
  return along(rod.v, c, s) - c.otherVelocity;
}

double nodeMass(const ContactPoint& c, const RodState& rod, double wa, double wb) {
  return wa * rod.nodes[c.segment].mass + wb * rod.nodes[c.segment + 1].mass;
}

// A point contact's penetration at the rod's current positions, against its anchor.
double pointPenetration(const ContactPoint& c, const RodState& rod) {
  return c.radius - c.normal.dot(along(rod.x, c, c.s) - c.anchor);
}

}  // namespace

double nodePenetration(const ContactPoint& c, const std::vector<Vec3>& x, int end) {
  return c.radius - c.normal.dot(x[c.segment + end] - c.anchor);
}

NormalEval evalNormal(const ContactPoint& c, const RodState& rod, const ContactLaw& law) {
  NormalEval e;
  if (!c.line) {
    const double pen = pointPenetration(c, rod);
    if (c.entered[0] == Entry::Released || (pen <= 0 && !c.closing[0] && c.entered[0] == Entry::No)) return e;
    e.touching = true;
    const double f = pen > 0 || c.entered[0] == Entry::Affine ? law.stiffness * pen : 0.0;
    e.fa = (1 - c.s) * f, e.fb = c.s * f;
    e.ka = (1 - c.s) * law.stiffness, e.kb = c.s * law.stiffness;
    return e;
  }
  // Line contact: each node against the plane with half the segment's length.
  const double half = 0.5 * law.stiffness * (rod.x[c.segment + 1] - rod.x[c.segment]).norm();
  if (law.rigid) {
    // Held by constraints: the force is the last solve's multiplier.
    if (c.node != 1 && c.multiplier[0] > 0) e.fa = c.multiplier[0], e.ka = half;
    if (c.node != 0 && c.multiplier[1] > 0) e.fb = c.multiplier[1], e.kb = half;
    e.touching = e.ka > 0 || e.kb > 0;
    return e;
  }
  const double pa = nodePenetration(c, rod.x, 0), pb = nodePenetration(c, rod.x, 1);
  if (c.node != 1 && c.entered[0] != Entry::Released && (pa > 0 || c.closing[0] || c.pressed[0] || c.entered[0] != Entry::No))
    e.fa = half * (c.entered[0] == Entry::Affine ? pa : std::max(0.0, pa)), e.ka = half;
  if (c.node != 0 && c.entered[1] != Entry::Released && (pb > 0 || c.closing[1] || c.pressed[1] || c.entered[1] != Entry::No))
    e.fb = half * (c.entered[1] == Entry::Affine ? pb : std::max(0.0, pb)), e.kb = half;
  e.touching = e.ka > 0 || e.kb > 0;
  return e;
}

bool markClosing(ContactPoint& c, const RodState& rod, double h) {
  if (!c.line) {
    const double pen = pointPenetration(c, rod);
    c.closing[0] = pen - h * c.normal.dot(relativeVelocity(c, rod, c.s)) > 0;
    c.closing[1] = false;
    return pen > 0 || c.closing[0];
  }
  bool any = false;
  for (int end = 0; end < 2; ++end) {
    if (c.node >= 0 && c.node != end) continue;
    const double pen = nodePenetration(c, rod.x, end);
    c.closing[end] = pen - h * c.normal.dot(rod.v[c.segment + end] - c.otherVelocity) > 0;
    any = any || pen > 0 || c.closing[end];
  }
  return any;
}

namespace {

// A wall held by constraints: the force and friction are the step's solve's
// (physics/unilateral.h; friction's memory is per node, RodContacts). Until
// it runs, the last step's multipliers stand in for what is reported at
// detection (same segment: same nodes).
void updateRigidContact(ContactPoint& c, const ContactPoint* previous, const RodState& rod, const ContactLaw& law) {
  if (previous) {
    const bool same = previous->segment == c.segment;
    const double total = previous->multiplier[0] + previous->multiplier[1];
    for (int end = 0; end < 2; ++end)
      c.multiplier[end] = same ? previous->multiplier[end] : (c.node < 0 ? 0.5 : c.node == end ? 1.0 : 0.0) * total;
  }
  const NormalEval n = evalNormal(c, rod, law);
  c.normalForce = n.force();
  if (n.touching) c.s = n.wb();
  c.at = along(rod.x, c, c.s);
  c.slip.setZero();  // the contact's own spring is the penalty's; held nodes keep theirs in `held`
  c.sliding = false;
}

}  // namespace

void updateContact(ContactPoint& c, const ContactPoint* previous, const RodState& rod, const ContactLaw& law, double h) {
  if (law.rigid && c.line) {
    updateRigidContact(c, previous, rod, law);
    return;
  }
  const NormalEval n = evalNormal(c, rod, law);
  c.normalForce = n.force();
  if (n.touching && c.line) c.s = n.wb();  // the force centroid carries the friction
  c.at = along(rod.x, c, c.s);
  const double mu = std::max(law.frictionStatic, law.frictionDynamic);
  if (c.normalForce <= 0 || mu <= 0 || !previous) {
    c.slip.setZero();
    c.sliding = false;
    return;
  }
  // The stick spring stretched by last step's tangential motion, in the new tangent plane.
  const Mat3 tangent = Mat3::Identity() - c.normal * c.normal.transpose();
  c.slip = tangent * (previous->slip + h * relativeVelocity(c, rod, c.s));
  const double kt = law.frictionStiffnessRatio * (n.ka + n.kb), trial = kt * c.slip.norm();
  const double limit = (previous->sliding ? law.frictionDynamic : law.frictionStatic) * c.normalForce;
  c.sliding = trial > limit;
  if (c.sliding) c.slip *= law.frictionDynamic * c.normalForce / trial;
}

const ContactPoint* findPrevious(std::span<const ContactPoint> list, const ContactPoint& c, const RodState& rod) {
  const auto first = std::lower_bound(list.begin(), list.end(), c.segment - 1,
                                      [](const ContactPoint& p, int seg) { return p.segment < seg; });
  const ContactPoint* best = nullptr;
  double bestDistance = 0;
  const Vec3 here = along(rod.x, c, c.s);
  for (auto it = first; it != list.end() && it->segment <= c.segment + 1; ++it) {
    if (it->other != c.other) continue;
    if (c.otherSegment >= 0 && std::abs(it->otherSegment - c.otherSegment) > 1) continue;
    const double d = (along(rod.x, *it, it->s) - here).squaredNorm();
    if (!best || d < bestDistance) best = &*it, bestDistance = d;
  }
  return best;
}

namespace {

// A static solve: no friction, no damping, and the penalty smoothed over
// a length delta = kStaticSmoothing (r1 + r2): f = k delta ln(1 + exp(d /
// delta)) for a depth d, stiffness k / (1 + exp(-d / delta)). With the
// penalty's kink a Newton iteration on loops resting on one another cycles
// for ever: a pair pressing is pushed out to just apart, where its
// linearisation has no stiffness and the next step sags back through it
// (several pairs of nearly parallel segments take turns). Smoothed, a pair
// just apart keeps its stiffness. At rest under a load F a pair sits at
// depth delta ln(exp(F / (k delta)) - 1): the hard law's F / k for F >> k
// delta, apart by about delta ln(k delta / F) for F << k delta (0.9 um for
// the 0.1 mm wire resting under gravity in tests/physics/
// statics_contact_test.cpp).
// Point contacts give their exact Jacobian for fixed s, t and normal (the
// normal's own turning adds (d / distance) k (1 - n n^T), a few per cent of
// it: Newton converges linearly at that rate near the end).
constexpr double kStaticSmoothing = 1e-3;

struct Smoothed {
  double force = 0, stiffness = 0;  // per unit of penalty stiffness: m and 1
};

Smoothed smoothed(double depth, double delta) {
  if (!(delta > 0)) return depth > 0 ? Smoothed{depth, 1.0} : Smoothed{};
  const double x = depth / delta;
  if (x > 30) return {depth, 1.0};
  if (x < -30) return {};
  return {delta * std::log1p(std::exp(x)), 1.0 / (1.0 + std::exp(-x))};
}

void applyStatic(std::span<const ContactPoint> contacts, const RodState& rod, const ContactLaw& law, bool sameRod,
                 RodForces& out) {
  for (const ContactPoint& c : contacts) {
    const double delta = kStaticSmoothing * c.radius;
    const Mat3 nn = c.normal * c.normal.transpose();
    if (c.line) {
      // Each node against its own plane, with half the segment's length: the diagonal block is exact.
      const double half = 0.5 * law.stiffness * (rod.x[c.segment + 1] - rod.x[c.segment]).norm();
      for (int end = 0; end < 2; ++end) {
        if (c.node >= 0 && c.node != end) continue;  // a node's own plane presses that node only
        const Smoothed p = smoothed(nodePenetration(c, rod.x, end), delta);
        if (p.stiffness <= 0) continue;
        out.force[c.segment + end].head<3>() += half * p.force * c.normal;
        out.stiffness[c.segment + end].topLeftCorner<3, 3>() += half * p.stiffness * nn;
        out.touchedMatrix = true;
      }
      continue;
    }
    const Smoothed p = smoothed(pointPenetration(c, rod), delta);
    if (p.stiffness <= 0) continue;
    out.touchedMatrix = true;
    const int nodes[4] = {c.segment, c.segment + 1, c.otherSegment, c.otherSegment + 1};
    const double w[4] = {1 - c.s, c.s, -(1 - c.otherS), -c.otherS};
    const int columns = sameRod ? 4 : 2;
    const double k = law.stiffness * p.stiffness;
    for (int i = 0; i < 2; ++i) {
      out.force[nodes[i]].head<3>() += law.stiffness * p.force * w[i] * c.normal;
      out.stiffness[nodes[i]].topLeftCorner<3, 3>() += k * w[i] * w[i] * nn;
      for (int j = 0; j < columns; ++j)
        if (j != i && w[i] * w[j] != 0) out.coupling->push_back({nodes[i], nodes[j], k * w[i] * w[j] * nn});
    }
  }
}

// Regularised Coulomb friction of contact c with normal evaluation n.
void addFriction(const ContactPoint& c, const NormalEval& n, const Mat3& nn, const RodState& rod, const ContactLaw& law,
                 double h, RodForces& out) {
  const double normalForce = n.force();
  if (normalForce <= 0) return;
  const int node[2] = {c.segment, c.segment + 1};
  // Friction: the stick spring at the force centroid, at the current
  // positions (later Newton iterations see the step's motion), capped by
  // Coulomb's cone; shared between the nodes like the normal force.
  const double wb = c.line ? n.wb() : c.s, wa = 1 - wb;
  const Mat3 tangent = Mat3::Identity() - nn;
  const double kt = law.frictionStiffnessRatio * (n.ka + n.kb);
  const Vec3 vrel = relativeVelocity(c, rod, wb);
  const Vec3 moved = tangent * (along(rod.x, c, c.s) - c.at);
  const Vec3 trial = c.slip + moved;
  // Stick or slide is decided on where the spring will be at the end of
  // the step: at the detection positions (the first Newton iteration) that
  // is the start velocity carried over the step; later iterations have
  // moved the nodes there already.
  const Vec3 ahead = moved.isZero(0.0) ? Vec3(trial + h * (tangent * vrel)) : trial;
  const double limit = (c.sliding ? law.frictionDynamic : law.frictionStatic) * normalForce;
  Vec3 f;
  Mat3 k, d = Mat3::Zero();
  if (kt * ahead.norm() <= limit * (1 + 1e-9)) {
    // Sticking: the spring and its damping are implicit.
    const double dt = 2 * law.dampingRatio * std::sqrt(kt * nodeMass(c, rod, wa, wb));
    f = -kt * trial - dt * (tangent * vrel);
    k = law.implicitScale * kt * tangent;
    d = law.implicitScale * dt * tangent;
  } else {
    // Sliding: the secant of Coulomb's law through the step's slip, a
    // softer spring sigma = mu_d Fn / |slip ahead| from the stick point,
    // which gives exactly mu_d Fn if the step slips as predicted and less
    // if the solve stops the node. A constant mu_d Fn instead is explicit
    // along the slip: on a 0.4 mg node it reverses a 5 mm/s slip within
    // one step (mu Fn h / m is 0.5 m/s) and the contact chatters into a
    // blow-up (and a direction-only stiffness of mu Fn / |elastic slip|
    // across it made a stiff anchor, as strong as the stick spring).
    const double slide = law.frictionDynamic * normalForce;
    const double sigma = slide / ahead.norm();
    f = -sigma * trial;
    k = law.implicitScale * sigma * tangent;
  }
  out.force[node[0]].head<3>() += wa * f;
  out.force[node[1]].head<3>() += wb * f;
  out.stiffness[node[0]].topLeftCorner<3, 3>() += wa * k;
  out.stiffness[node[1]].topLeftCorner<3, 3>() += wb * k;
  out.damping[node[0]].topLeftCorner<3, 3>() += wa * d;
  out.damping[node[1]].topLeftCorner<3, 3>() += wb * d;
}

// Whether pair contact c of `contacts` (sorted by segment) repeats another
// at a joint: a point at a node is the closest point of both segments that
// meet there, so detection lists it twice (s = 1 on one segment, s = 0 on
// the next; likewise on the other side). Solved coupled the two give
// identical rows, the contact's force and stiffness twice over; the one at
// the next segment's start is kept. (The lumped law counts it twice too;
// changing that would move every shipped scene's result.)
bool jointDuplicate(std::span<const ContactPoint> contacts, const ContactPoint& c) {
  const bool atEnd = c.s == 1.0, otherAtEnd = c.otherS == 1.0;
  if (!atEnd && !otherAtEnd) return false;
  const auto first = std::lower_bound(contacts.begin(), contacts.end(), c.segment,
                                      [](const ContactPoint& p, int seg) { return p.segment < seg; });
  for (auto it = first; it != contacts.end() && it->segment <= c.segment + 1; ++it) {
    if (it->other != c.other) continue;
    if (atEnd && it->segment == c.segment + 1 && it->s == 0.0 && it->otherSegment == c.otherSegment) return true;
    if (otherAtEnd && it->segment == c.segment && it->otherSegment == c.otherSegment + 1 && it->otherS == 0.0)
      return true;
  }
  return false;
}

// A pair contact (self or rod) whose two sides are solved together
// (physics/pair_coupling.h): the same normal force as applyContacts gives,
// and its coupling instead of the lumped diagonal. Friction stays lumped
// (each side holding the other at its start).
void applyCoupledPair(const ContactPoint& c, const NormalEval& n, const RodState& rod, const ContactLaw& law, double h,
                      RodForces& out) {
  // One damping coefficient for both sides, from the mean of their masses
  // at the contact point (for equal masses the lumped law's 2 zeta
  // sqrt(k m)), so that the damping forces are equal and opposite. With
  // each side's own mass (the lumped law's) they differ where the masses do
  // (a rod's end node has half the mass), and the difference is a net force
  // on the pair that its coupling row does not resist: it moves both sides
  // together against their mass alone, a 0.5 mg node by metres per second
  // within a step. (The reduced mass, the relative motion's own critical
  // damping, damps half as much and leaves a dense packing moving.)
  const double mean = 0.5 * (nodeMass(c, rod, 1 - c.s, c.s) + c.otherMass);
  const double pointDamping = 2 * law.dampingRatio * std::sqrt(law.stiffness * mean);
  const double approach = c.normal.dot(relativeVelocity(c, rod, c.s));
  const int node[2] = {c.segment, c.segment + 1};
  const double fe[2] = {n.fa, n.fb}, ke[2] = {n.ka, n.kb};
  for (int end = 0; end < 2; ++end) {
    if (ke[end] <= 0) continue;
    const double share = end ? c.s : 1 - c.s;
    double fn = fe[end] - share * pointDamping * approach;
    if (fe[end] > 0) fn = std::max(0.0, fn);
    out.force[node[end]].head<3>() += fn * c.normal;
  }
  PairCoupling p;
  p.otherRod = c.other;
  p.segment = c.segment, p.otherSegment = c.otherSegment;
  p.s = c.s, p.otherS = c.otherS;
  p.normal = c.normal;
  p.normalStiffness = law.stiffness, p.normalDamping = pointDamping;
  p.radius = c.radius;
  const double pen = pointPenetration(c, rod);
  p.springFrom = pen > 0 || c.entered[0] == Entry::Affine ? 0.0 : pen;
  out.pairs->push_back(p);
  if (law.frictionStatic > 0 || law.frictionDynamic > 0) {
    out.touchedMatrix = true;
    addFriction(c, n, c.normal * c.normal.transpose(), rod, law, h, out);
  }
}

}  // namespace

void applyContacts(std::span<const ContactPoint> contacts, const EffectContext& ctx, const ContactLaw& law,
                   RodForces& out, bool sameRod) {
  const RodState& rod = ctx.state;
  const double h = ctx.timeStep;
  if (ctx.solve == SolveKind::Static) {
    applyStatic(contacts, rod, law, sameRod, out);
    return;
  }
  for (const ContactPoint& c : contacts) {
    const NormalEval n = evalNormal(c, rod, law);
    if (law.rigid && c.line && out.constraints) {
      // Each node held against the plane by the solve (physics/unilateral.h),
      // its friction capped by the multiplier of the same solve: a stick
      // spring of ratio k times the length of rod the node stands for, as
      // the penalty's per node, with its critical damping.
      const std::vector<NodeFrictionMemory>& before = rod.contact.wallFrictionBefore;
      std::vector<NodeFrictionMemory>& after = rod.contact.wallFrictionAfter;
      for (int end = 0; end < 2; ++end) {
        if (c.node >= 0 && c.node != end) continue;
        const size_t i = size_t(c.segment + end);
        NodeConstraint k{int(i), c.normal, nodePenetration(c, rod.x, end), &c.multiplier[end], {}};
        if ((law.frictionStatic > 0 || law.frictionDynamic > 0) && i < after.size()) {
          const double kt = law.frictionStiffnessRatio * law.stiffness * rod.nodes[i].length;
          k.friction = {law.frictionStatic, law.frictionDynamic, kt,
                        2 * law.dampingRatio * std::sqrt(kt * rod.nodes[i].mass),
                        i < before.size() ? before[i] : NodeFrictionMemory{}, &after[i]};
        }
        out.constraints->push_back(k);
      }
      continue;
    }
    if (!n.touching) continue;
    if (out.pairs && !c.line) {
      if (!jointDuplicate(contacts, c)) applyCoupledPair(c, n, rod, law, h, out);
      continue;
    }
    const int node[2] = {c.segment, c.segment + 1};
    const double fe[2] = {n.fa, n.fb}, ke[2] = {n.ka, n.kb};
    // A wall node that this iterate found in the wall stays in the solve
    // for the rest of the step (no force while apart, as a closing node).
    // Otherwise the iterates alternate: carried in, pushed out to the
    // surface, left out of the solve there, carried in again (a soft coil's
    // tip jolted at rest against the wall ended 17 um in after the third).
    if (c.line)
      for (int end = 0; end < 2; ++end) c.pressed[end] = c.pressed[end] || fe[end] > 0;
    const Mat3 nn = c.normal * c.normal.transpose();
    // Normal spring and damper per node. Point contacts damp the contact
    // point's motion with the pair's mass; line contacts each node's own.
    const double pointDamping =
        c.line ? 0.0 : 2 * law.dampingRatio * std::sqrt(law.stiffness * nodeMass(c, rod, 1 - c.s, c.s));
    for (int end = 0; end < 2; ++end) {
      if (ke[end] <= 0) continue;
      const int i = node[end];
      const double share = end ? c.s : 1 - c.s;
      const double damping = c.line ? 2 * law.dampingRatio * std::sqrt(ke[end] * rod.nodes[i].mass) : share * pointDamping;
      const double approach = c.normal.dot(c.line ? Vec3(rod.v[i] - c.otherVelocity) : relativeVelocity(c, rod, c.s));
      double fn = fe[end] - damping * approach;
      // Damping may slow a separation but never pulls a penetrating rod onto
      // the wall. A closing contact still apart has no spring force, only
      // its stiffness, which stops the approach within the step.
      if (fe[end] > 0) fn = std::max(0.0, fn);
      out.force[i].head<3>() += fn * c.normal;
      out.stiffness[i].topLeftCorner<3, 3>() += law.implicitScale * ke[end] * nn;
      out.damping[i].topLeftCorner<3, 3>() += law.implicitScale * damping * nn;
      if (c.line && out.wallSprings)
        out.wallSprings->push_back({i, int(&c - contacts.data()), end, c.normal, c.anchor, c.otherVelocity, c.radius,
                                    nodePenetration(c, rod.x, end), approach, fn, law.implicitScale * ke[end],
                                    law.implicitScale * damping});
    }
    out.touchedMatrix = true;
    if (law.frictionStatic > 0 || law.frictionDynamic > 0) addFriction(c, n, nn, rod, law, h, out);
  }
}

double reportContacts(std::span<const ContactPoint> contacts, const RodState& rod, const ContactLaw& law,
                      std::vector<double>& nodeForce) {
  nodeForce.assign(rod.x.size(), 0.0);
  double deepest = 0;
  for (const ContactPoint& c : contacts) {
    deepest = std::max(deepest, -c.gap);
    const NormalEval n = evalNormal(c, rod, law);
    nodeForce[c.segment] += std::max(0.0, n.fa);
    nodeForce[c.segment + 1] += std::max(0.0, n.fb);
  }
  return deepest;
}

}  // namespace coilsim
