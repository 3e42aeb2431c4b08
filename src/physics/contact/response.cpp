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

}  // namespace

NormalEval evalNormal(const ContactPoint& c, const RodState& rod, const ContactLaw& law) {
  NormalEval e;
  const Vec3& xa = rod.x[c.segment];
  const Vec3& xb = rod.x[c.segment + 1];
  if (!c.line) {
    const double pen = c.radius - c.normal.dot(along(rod.x, c, c.s) - c.anchor);
    if (pen <= 0) return e;
    e.touching = true;
    e.force = law.stiffness * pen;
    e.stiffness = law.stiffness;
    e.wa = 1 - c.s, e.wb = c.s;
    return e;
  }
  // Line contact: the penetration below the wall's tangent plane is linear
  // along the segment. The segment acts like the length of rod it spans:
  // force k L pen_max (a segment lying on the wall carries k per length,
  // exactly as its two half-nodes would; one hitting the wall end-on is not
  // softer for touching at a single point), shared between the nodes by the
  // centroid of the penetrating part (its first moments, exact by 2-point
  // Gauss on the linear profile).
  const double pa = c.radius - c.normal.dot(xa - c.anchor), pb = c.radius - c.normal.dot(xb - c.anchor);
  if (pa <= 0 && pb <= 0) return e;
  double s0 = 0, s1 = 1;
  if (pa <= 0) s0 = pa / (pa - pb);
  if (pb <= 0) s1 = pa / (pa - pb);
  const double half = 0.5 * (s1 - s0), mid = 0.5 * (s0 + s1);
  double ma = 0, mb = 0;
  for (const double g : {-1 / std::sqrt(3.0), 1 / std::sqrt(3.0)}) {
    const double s = mid + half * g, pen = pa + (pb - pa) * s;
    ma += (1 - s) * pen, mb += s * pen;
  }
  e.touching = true;
  e.stiffness = law.stiffness * (xb - xa).norm();
  e.force = e.stiffness * std::max(pa, pb);
  e.wa = ma + mb > 0 ? ma / (ma + mb) : (pa >= pb ? 1.0 : 0.0);
  e.wb = 1 - e.wa;
  return e;
}

void updateContact(ContactPoint& c, const ContactPoint* previous, const RodState& rod, const ContactLaw& law, double h) {
  const NormalEval n = evalNormal(c, rod, law);
  c.normalForce = n.force;
  if (n.touching && c.line) c.s = n.wb;  // the force centroid carries the friction
  c.at = along(rod.x, c, c.s);
  const double mu = std::max(law.frictionStatic, law.frictionDynamic);
  if (!n.touching || mu <= 0 || !previous) {
    c.slip.setZero();
    c.sliding = false;
    return;
  }
  // The stick spring stretched by last step's tangential motion, in the new tangent plane.
  const Mat3 tangent = Mat3::Identity() - c.normal * c.normal.transpose();
  c.slip = tangent * (previous->slip + h * relativeVelocity(c, rod, c.s));
  const double kt = law.frictionStiffnessRatio * n.stiffness, trial = kt * c.slip.norm();
  const double limit = (previous->sliding ? law.frictionDynamic : law.frictionStatic) * n.force;
  c.sliding = trial > limit;
  if (c.sliding) c.slip *= law.frictionDynamic * n.force / trial;
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

void applyContacts(std::span<const ContactPoint> contacts, const RodState& rod, const ContactLaw& law, RodForces& out) {
  for (const ContactPoint& c : contacts) {
    const NormalEval n = evalNormal(c, rod, law);
    if (!n.touching) continue;
    const int a = c.segment, b = c.segment + 1;
    const Vec3 vrel = relativeVelocity(c, rod, n.wb);
    const double damping = 2 * law.dampingRatio * std::sqrt(n.stiffness * nodeMass(c, rod, n.wa, n.wb));
    // Damping may slow a separation but never pulls the rod onto the wall.
    const double fn = std::max(0.0, n.force - damping * c.normal.dot(vrel));
    Vec3 f = fn * c.normal;
    const Mat3 nn = c.normal * c.normal.transpose();
    Mat3 k = law.implicitScale * n.stiffness * nn, d = law.implicitScale * damping * nn;
    if (law.frictionStatic > 0 || law.frictionDynamic > 0) {
      // The stick spring at the current positions (later Newton iterations
      // see the step's motion), capped by Coulomb's cone.
      const Mat3 tangent = Mat3::Identity() - nn;
      const double kt = law.frictionStiffnessRatio * n.stiffness;
      const Vec3 trial = c.slip + tangent * (along(rod.x, c, c.s) - c.at);
      const double limit = (c.sliding ? law.frictionDynamic : law.frictionStatic) * n.force, spring = kt * trial.norm();
      if (spring <= limit * (1 + 1e-9)) {
        // Sticking: the spring and its damping are implicit.
        const double dt = 2 * law.dampingRatio * std::sqrt(kt * nodeMass(c, rod, n.wa, n.wb));
        f -= kt * trial + dt * (tangent * vrel);
        k += law.implicitScale * kt * tangent;
        d += law.implicitScale * dt * tangent;
      } else {
        // Sliding: a force of constant size; only its direction is stiff.
        const Vec3 dir = trial / trial.norm();
        f -= limit * dir;
        k += law.implicitScale * (limit / trial.norm()) * (tangent - dir * dir.transpose());
      }
    }
    out.force[a].head<3>() += n.wa * f;
    out.force[b].head<3>() += n.wb * f;
    out.stiffness[a].topLeftCorner<3, 3>() += n.wa * k;
    out.stiffness[b].topLeftCorner<3, 3>() += n.wb * k;
    out.damping[a].topLeftCorner<3, 3>() += n.wa * d;
    out.damping[b].topLeftCorner<3, 3>() += n.wb * d;
    out.touchedMatrix = true;
  }
}

double reportContacts(std::span<const ContactPoint> contacts, const RodState& rod, const ContactLaw& law,
                      std::vector<double>& nodeForce) {
  nodeForce.assign(rod.x.size(), 0.0);
  double deepest = 0;
  for (const ContactPoint& c : contacts) {
    deepest = std::max(deepest, -c.gap);
    const NormalEval n = evalNormal(c, rod, law);
    nodeForce[c.segment] += n.wa * n.force;
    nodeForce[c.segment + 1] += n.wb * n.force;
  }
  return deepest;
}

}  // namespace coilsim
