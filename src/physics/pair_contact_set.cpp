#include "physics/pair_contact_set.h"

#include <algorithm>

#include "physics/contact/response.h"
#include "physics/state.h"

namespace coilsim {
namespace {

// Point of segment `segment` of positions (or velocities) x at parameter s.
Vec3 pointOf(const std::vector<Vec3>& x, int segment, double s) {
  return (1 - s) * x[size_t(segment)] + s * x[size_t(segment) + 1];
}

// Penetration of pair contact c (a ContactPoint or its PairCoupling) at
// positions xs (the other side's at xo).
template <class Pair>
double pairPenetration(const Pair& c, const std::vector<Vec3>& xs, const std::vector<Vec3>& xo) {
  return c.radius - c.normal.dot(pointOf(xs, c.segment, c.s) - pointOf(xo, c.otherSegment, c.otherS));
}

// A contact that entered from at most this fraction of its contact
// distance apart is held by the affine law, one from further by a barrier
// (ContactPoint::entered): 0.25 um for two 0.254 mm wires, where k times
// the gap is 13 mN at 50 N/mm.
constexpr double kAffineGap = 1e-3;

// How a contact apart by -start at the step's start and by -end at its
// end (< 0: penetrating) is held in the step taken again. A barrier stays.
// An affine one that ends further apart than it started pulled: it is let
// go. One that ends between stays (let go, it would enter again, and the
// passes would alternate).
Entry revised(Entry was, double start, double end, double radius) {
  if (was == Entry::Held) return was;
  if (was == Entry::Affine) return end < start ? Entry::No : was;
  if (!(end > 0)) return Entry::No;
  return -start <= kAffineGap * radius ? Entry::Affine : Entry::Held;
}

// The normal force wall spring w applied to its node in the step's solve:
// its force at the iterate it was built at, carried to the rod's current
// positions and velocities by the stiffness and damping the matrix held
// (< 0: it pulled).
double solvedForce(const WallSpring& w, const RodState& r) {
  const size_t i = size_t(w.node);
  const double pen = w.radius - w.normal.dot(r.x[i] - w.anchor);
  const double approach = w.normal.dot(r.v[i] - w.otherVelocity);
  return w.force + w.stiffness * (pen - w.penetration) - w.damping * (approach - w.approach);
}

// The normal force pair coupling c of rod k applied in the step's solve, at
// the rods' current positions and velocities (< 0: it pulled).
double solvedForce(const PairCoupling& c, const std::vector<RodState>& rods, size_t k) {
  const RodState &r = rods[k], &o = rods[size_t(c.otherRod)];
  const double pen = pairPenetration(c, r.x, o.x);
  const double approach = c.normal.dot(pointOf(r.v, c.segment, c.s) - pointOf(o.v, c.otherSegment, c.otherS));
  return c.normalStiffness * (pen - c.springFrom) - c.normalDamping * approach;
}

// The contact of rod k's list that pair coupling c was built from.
ContactPoint* contactOf(std::vector<ContactPoint>& list, const PairCoupling& c) {
  auto it = std::lower_bound(list.begin(), list.end(), c.segment,
                             [](const ContactPoint& p, int seg) { return p.segment < seg; });
  for (; it != list.end() && it->segment == c.segment; ++it)
    if (it->other == c.otherRod && it->otherSegment == c.otherSegment && it->s == c.s && it->otherS == c.otherS)
      return &*it;
  return nullptr;
}

// The other side's contact of pair c (rod k's), in its sorted list.
ContactPoint* partner(std::vector<ContactPoint>& list, const ContactPoint& c, int k) {
  auto it = std::lower_bound(list.begin(), list.end(), c.otherSegment,
                             [](const ContactPoint& p, int seg) { return p.segment < seg; });
  for (; it != list.end() && it->segment == c.otherSegment; ++it)
    if (it->other == k && it->otherSegment == c.segment) return &*it;
  return nullptr;
}

}  // namespace

void followOtherSides(std::vector<RodState>& rods, std::span<const char> stepped) {
  for (size_t k = 0; k < rods.size(); ++k) {
    if (!stepped[k]) continue;
    for (auto* list : {&rods[k].contact.self, &rods[k].contact.rod})
      for (ContactPoint& c : *list) {
        const RodState& o = rods[size_t(c.other)];
        if (!stepped[size_t(c.other)]) continue;  // held where detection found it
        c.anchor = pointOf(o.x, c.otherSegment, c.otherS);
        c.otherVelocity = pointOf(o.v, c.otherSegment, c.otherS);
      }
  }
}

void clearEnteredContacts(std::vector<RodState>& rods) {
  for (RodState& r : rods)
    for (auto* list : {&r.contact.wall, &r.contact.self, &r.contact.rod})
      for (ContactPoint& c : *list) c.entered[0] = c.entered[1] = Entry::No;
}

int reviseContactSet(std::vector<RodState>& rods, std::span<const char> stepped) {
  int changed = 0;
  // A pair the solve held but whose solved force pulled its sides together
  // is let go, on both sides' lists, as the wall's nodes below.
  for (size_t k = 0; k < rods.size(); ++k) {
    if (!stepped[k]) continue;
    for (const PairCoupling& p : rods[k].work.pairs) {
      if (!(solvedForce(p, rods, k) < 0)) continue;
      const bool self = p.otherRod == int(k);
      ContactPoint* c = contactOf(self ? rods[k].contact.self : rods[k].contact.rod, p);
      if (!c || c->entered[0] == Entry::Released) continue;
      c->entered[0] = Entry::Released;
      std::vector<ContactPoint>& other = self ? rods[k].contact.self : rods[size_t(p.otherRod)].contact.rod;
      if (ContactPoint* d = partner(other, *c, int(k))) d->entered[0] = Entry::Released;
      ++changed;
    }
  }
  for (size_t k = 0; k < rods.size(); ++k) {
    if (!stepped[k]) continue;
    for (const bool self : {true, false}) {
      std::vector<ContactPoint>& list = self ? rods[k].contact.self : rods[k].contact.rod;
      for (ContactPoint& c : list) {
        const size_t j = size_t(c.other);
        // Each pair once: from its lower rod, or its lower segment.
        if (stepped[j] && (j == k ? c.otherSegment < c.segment : j < k)) continue;
        const RodState& o = rods[j];
        const std::vector<Vec3>& otherStart = stepped[j] ? o.work.x0 : o.x;
        const double start = pairPenetration(c, rods[k].work.x0, otherStart);
        std::vector<ContactPoint>& other = self ? rods[j].contact.self : rods[j].contact.rod;
        if (c.entered[0] == Entry::Released) {
          // Let go, it went deeper than it started: back in.
          if (pairPenetration(c, rods[k].x, o.x) > std::max(start, 0.0)) {
            c.entered[0] = start > 0 || c.closing[0] ? Entry::No : Entry::Held;
            if (ContactPoint* d = partner(other, c, int(k))) d->entered[0] = c.entered[0];
            ++changed;
          }
          continue;
        }
        if (c.closing[0]) continue;
        if (start > 0) continue;  // in the solve already
        const Entry now = revised(c.entered[0], start, pairPenetration(c, rods[k].x, o.x), c.radius);
        if (now == c.entered[0]) continue;
        c.entered[0] = now;
        if (ContactPoint* d = partner(other, c, int(k))) d->entered[0] = now;
        ++changed;
      }
    }
    // A wall node the solve held but pulled onto the wall is let go.
    std::vector<ContactPoint>& wall = rods[k].contact.wall;
    for (const WallSpring& w : rods[k].work.wallSprings) {
      if (size_t(w.contact) >= wall.size() || !(solvedForce(w, rods[k]) < 0)) continue;
      wall[size_t(w.contact)].entered[w.end] = Entry::Released;
      ++changed;
    }
    // The wall's nodes likewise (each against its own plane).
    for (ContactPoint& c : wall) {
      for (int end = 0; end < 2; ++end) {
        if (c.node >= 0 && c.node != end) continue;
        if (c.entered[end] == Entry::Released) {
          // Let go, it went deeper into the wall than it started: back in.
          const double start = nodePenetration(c, rods[k].work.x0, end);
          if (nodePenetration(c, rods[k].x, end) > std::max(start, 0.0)) {
            c.entered[end] = start > 0 || c.closing[end] ? Entry::No : Entry::Held;
            ++changed;
          }
          continue;
        }
        if (c.closing[end]) continue;
        const double start = nodePenetration(c, rods[k].work.x0, end);
        if (start > 0) continue;
        const double now = nodePenetration(c, rods[k].x, end);
        const Entry law = revised(c.entered[end], start, now, c.radius);
        if (law == c.entered[end]) continue;
        c.entered[end] = law;
        ++changed;
      }
    }
  }
  return changed;
}

void reportSolvedPairForces(std::vector<RodState>& rods, std::span<const char> stepped) {
  for (size_t k = 0; k < rods.size(); ++k) {
    RodState& r = rods[k];
    if (!stepped[k] || r.work.pairs.empty()) continue;
    r.contact.selfForce.assign(r.x.size(), 0.0);
    r.contact.rodForce.assign(r.x.size(), 0.0);
    for (const PairCoupling& c : r.work.pairs) {
      const double f = std::max(0.0, solvedForce(c, rods, k));
      std::vector<double>& out = c.otherRod == int(k) ? r.contact.selfForce : r.contact.rodForce;
      out[size_t(c.segment)] += (1 - c.s) * f;
      out[size_t(c.segment) + 1] += c.s * f;
    }
  }
}

void reportSolvedWallForces(std::vector<RodState>& rods, std::span<const char> stepped) {
  for (size_t k = 0; k < rods.size(); ++k) {
    RodState& r = rods[k];
    if (!stepped[k]) continue;
    r.contact.wallForce.assign(r.x.size(), 0.0);
    for (const WallSpring& w : r.work.wallSprings) r.contact.wallForce[size_t(w.node)] += std::max(0.0, solvedForce(w, r));
  }
}

}  // namespace coilsim
