#include <algorithm>
#include <cmath>
#include <limits>

#include "physics/contact/detect.h"
#include "physics/contact/detect_nearest.h"
#include "physics/contact/geometry.h"
#include "physics/contact/obstacle_tree.h"

namespace coilsim {
namespace {

// A node's own nearest wall gets a plane of its own unless one of the
// segment's planes agrees with it within this fraction of the wire radius
// (half the end-of-step check's tolerance, kMissedContact).
constexpr double kNodePlane = 0.5 * kMissedContact;

// How far beyond its reach each wall query looks, so that a segment found
// clear can skip the next queries until it has moved that far (m).
constexpr double kLookAhead = 0.5e-3;

// The outward direction that decides the side of the nearest feature: the
// face normal for a face, the angle-weighted pseudo-normal of the faces
// sharing it for an edge or a vertex (Baerentzen and Aanaes, IEEE TVCG
// 2005). One triangle's normal can be wrong at a sharp ridge: where the sac
// meets its vessel at the neck the wall is a sliver 0.2 mm thick, and
// segments inside the sac near that rim were taken as 0.35-0.41 mm beyond
// the wall and thrown with 35-49 N.
// `found` are the closest points of the query that found n.
Vec3 pseudoNormal(const ObstacleTree& tree, const NearestTriangle& n, const std::vector<int>& candidates,
                  const std::vector<SegmentTriangle>& found, double radius) {
  const double tol = 1e-9 * radius;
  const TriangleMesh& m = tree.mesh();
  Vec3 sum = Vec3::Zero();
  for (size_t k = 0; k < candidates.size(); ++k) {
    if (!(found[k].distance <= n.hit.distance + tol) || (found[k].onTriangle - n.hit.onTriangle).norm() > tol) continue;
    const Eigen::Vector3i& f = m.triangles[candidates[k]];
    double weight = M_PI;  // an edge: both faces alike
    for (int i = 0; i < 3; ++i) {
      const Vec3& v = m.vertices[f[i]];
      if ((v - n.hit.onTriangle).norm() > tol) continue;
      const Vec3 e1 = m.vertices[f[(i + 1) % 3]] - v, e2 = m.vertices[f[(i + 2) % 3]] - v;
      weight = std::atan2(e1.cross(e2).norm(), e1.dot(e2));  // a vertex: the face's angle there
    }
    sum += weight * tree.normal(candidates[k]);
  }
  return sum.squaredNorm() > 0 ? Vec3(sum.normalized()) : tree.normal(n.triangle);
}

// The nearest feature of the wall to node x of the segment whose query
// found `segment` and left `candidates` and `hits` (s: 0 for its node a, 1
// for b), with the closest points in `nodeHits`. A triangle is no nearer
// to the node than to the segment, so with the segment's nearest triangle
// measured first, only those the segment found about as near are measured
// (for a node on a wall, the few under it).
NearestTriangle nearestToNode(const ObstacleTree& tree, const Vec3& x, double s, const NearestTriangle& segment, double reach,
                      ContactScratch& scratch) {
  const std::vector<int>& candidates = scratch.candidates;
  const std::vector<SegmentTriangle>& hits = scratch.hits;
  const std::vector<double>& boxGap2 = scratch.boxGap2;
  std::vector<SegmentTriangle>& nodeHits = scratch.nodeHits;
  const TriangleMesh& m = tree.mesh();
  nodeHits.resize(candidates.size());
  const auto measure = [&](size_t k) -> const SegmentTriangle& {
    const Eigen::Vector3i& f = m.triangles[candidates[k]];
    SegmentTriangle& h = nodeHits[k];
    h.s = s, h.onSegment = x, h.onTriangle = closestPointTriangle(x, m.vertices[f[0]], m.vertices[f[1]], m.vertices[f[2]]);
    h.distance = (x - h.onTriangle).norm();
    return h;
  };
  NearestTriangle best{measure(segment.candidate), segment.triangle, segment.candidate};
  for (size_t k = 0; k < candidates.size(); ++k) {
    if (k == segment.candidate) continue;
    // (Not a triangle that shares the nearest feature: its distance may
    // differ from the segment's in the last bit, and the side would then
    // be decided without it, the wrong way at a sharp edge.)
    // Nor one farther than the reach: the caller wants the node's wall only within it.
    const double bound = std::min(best.hit.distance, reach) + 1e-9 * reach;
    if (std::isnan(hits[k].distance) ? boxGap2[k] > bound * bound : hits[k].distance > bound) {
      nodeHits[k].distance = std::numeric_limits<double>::quiet_NaN();
      continue;
    }
    if (measure(k).distance < best.hit.distance) best = {nodeHits[k], candidates[k], k};
  }
  return best;
}

// A contact from the nearest feature: normal from the feature to the centre
// line, flipped (and the gap negative) when the centre line is outside.
// `candidates` and `found` are those of the query that found n.
ContactPoint makeContact(const ObstacleTree& tree, const NearestTriangle& n, const std::vector<int>& candidates,
                         const std::vector<SegmentTriangle>& found, int segment, int obstacle, double radius) {
  ContactPoint c;
  c.segment = segment;
  c.other = obstacle;
  c.line = true;
  c.s = n.hit.s;
  c.radius = radius;
  c.anchor = n.hit.onTriangle;
  const Vec3 away = n.hit.onSegment - n.hit.onTriangle;
  const Vec3 outward = pseudoNormal(tree, n, candidates, found, radius);
  const bool outside = away.dot(outward) > 0;
  if (n.hit.distance > 1e-12 * radius) {
    c.normal = (outside ? -1.0 : 1.0) * away / n.hit.distance;
  } else {
    c.normal = -outward;  // centre line on the surface: push inwards
  }
  c.gap = (outside ? -n.hit.distance : n.hit.distance) - radius;
  return c;
}

// The wall contacts of segment e of rod r, appended to `out` (the rod's
// contacts of the segments before it in this part of the detection). Reads
// and writes only segment e's own entries of the rod's coherence arrays, so
// two threads may detect disjoint segments of one rod.
void detectSegment(const Model& model, RodState& r, int e, double h, double margin, const ContactLaw& law, bool coherent,
                   ContactScratch& scratch, std::vector<ContactPoint>& out) {
  RodContacts& rc = r.contact;
  const std::vector<int>& candidates = scratch.candidates;
  const std::vector<SegmentTriangle>& hits = scratch.hits;
  const std::vector<SegmentTriangle>& nodeHits = scratch.nodeHits;
  const Vec3 &a = r.x[e], &b = r.x[e + 1];
  const double radius = (1 + kWallSkin) * 0.5 * (r.nodes[e].radius + r.nodes[e + 1].radius);
  // What the segment can sweep in this step at its start velocity: a
  // contact it would reach must be in this step's implicit solve.
  const double sweep = margin + h * std::max(r.v[e].norm(), r.v[e + 1].norm());
  const double reach = radius + sweep;
  // Temporal coherence: no triangle lay within wallClear of the
  // segment where it was; if it has moved less than that minus its
  // reach, none is within reach now (exact, so nothing is missed).
  if (coherent && rc.wallClear[e] > 0) {
    const double moved = std::max((a - rc.wallClearAt[2 * e]).norm(), (b - rc.wallClearAt[2 * e + 1]).norm());
    if (moved + reach < rc.wallClear[e]) return;
  }
  double clear = INFINITY;
  const size_t before = out.size();
  for (size_t o = 0; o < model.obstacles.size(); ++o) {
    if (!model.obstacles[o].contact || o >= model.obstacleTrees.size()) continue;
    const ObstacleTree& tree = *model.obstacleTrees[o];
    // First within the reach alone, from last step's nearest
    // triangle: a segment on the wall finds it among a third of the
    // candidates. What follows only uses triangles within the reach,
    // so it comes out as from the wider query (docs/contact.md).
    int& hint = rc.wallHint[e * model.obstacles.size() + o];
    TriangleCache* cache = coherent ? &rc.wallCache[e * model.obstacles.size() + o] : nullptr;
    NearestTriangle n;
    if (coherent) n = nearestWallFeature(tree, a, b, reach, scratch, reach + kLookAhead, hint, cache);
    if (n.triangle < 0 || n.hit.distance > reach) {
      // Queried beyond the reach, so the clearance found lasts a while.
      n = nearestWallFeature(tree, a, b, reach + kLookAhead, scratch, reach + kLookAhead, -1, cache);
    }
    hint = n.triangle;
    clear = std::min(clear, n.triangle < 0 ? reach + kLookAhead : n.hit.distance);
    if (n.triangle < 0 || n.hit.distance > reach) {
      // Nothing near: either free, or pushed wholly through the wall
      // since the last step. Only the second needs the wider search.
      ContactPoint probe;
      probe.segment = e, probe.other = int(o);
      if (!findPrevious(rc.previous, probe, r)) continue;
      n = nearestWallFeature(tree, a, b, 4 * radius + margin, scratch, 4 * radius + margin, -1, cache);
      if (n.triangle < 0) continue;
    }
    const size_t listed = out.size();
    ContactPoint c = makeContact(tree, n, candidates, hits, e, int(o), radius);
    if (!markClosing(c, r, h) && c.gap > margin) continue;
    updateContact(c, findPrevious(rc.previous, c, r), r, law, h);
    out.push_back(c);
    // Concave neighbours: faces on the free side of the nearest face's
    // plane (the wall folds towards the lumen) bound the free space too;
    // their planes keep a node sliding off the nearest face from going
    // through the next one within the step (detect.h).
    const TriangleMesh& m = tree.mesh();
    const Vec3& nA = tree.normal(n.triangle);
    const Vec3& vA = m.vertices[m.triangles[n.triangle][0]];
    int extra = 0;
    for (size_t ci = 0; ci < candidates.size(); ++ci) {
      const int t = candidates[ci];
      if (t == n.triangle || extra >= 3) continue;
      // (A triangle whose box is farther than the reach is too: its
      // hit would be skipped below, so it is not measured.)
      if (std::isnan(hits[ci].distance) && scratch.boxGap2[ci] > reach * reach) continue;
      const Vec3& nt = tree.normal(t);
      if (nt.dot(nA) > 0.99999 || nt.dot(nA) < 0.5) continue;
      const auto& f = m.triangles[t];
      const Vec3 centroid = (m.vertices[f[0]] + m.vertices[f[1]] + m.vertices[f[2]]) / 3;
      if (nA.dot(centroid - vA) >= 0) continue;  // a ridge into the free space: its plane would cut it
      const SegmentTriangle hit = std::isnan(hits[ci].distance)
                                      ? closestSegmentTriangle(a, b, m.vertices[f[0]], m.vertices[f[1]], m.vertices[f[2]])
                                      : hits[ci];
      if (hit.distance > reach) continue;
      ContactPoint q;
      q.segment = e, q.other = int(o), q.line = true, q.s = 0.5, q.radius = radius;
      q.normal = -nt;
      q.anchor = m.vertices[f[0]];
      q.gap = std::min(q.normal.dot(a - q.anchor), q.normal.dot(b - q.anchor)) - radius;
      // The plane is that face's only where the segment lies over it.
      // Past its edges (a saddle, such as the fillet where a sac meets
      // its vessel, is concave one way and convex the other) the plane
      // cuts into the free space and claimed 0.04-0.39 mm penetrations
      // of a face the capsule does not touch, with forces of 2-23 N.
      // Such a plane is moved out to the face's true distance: it stays
      // a barrier for the step's motion and pushes on nothing.
      if (q.gap < 0 && hit.distance > radius) {
        q.anchor -= (hit.distance - radius - q.gap) * q.normal;
        q.gap = hit.distance - radius;
      }
      // Nor may it claim more than the segment's true penetration, the
      // nearest feature's (c.gap, sided by its pseudo-normal): where the
      // face is within the skin of one node (so kept above) its plane
      // can still cut the free space at the other node, and claimed
      // 50-120 um of a node resting on a neck fillet 8 um clear of
      // the mesh.
      if (q.gap < c.gap) {
        q.anchor -= (c.gap - q.gap) * q.normal;
        q.gap = c.gap;
      }
      if (!markClosing(q, r, h) && q.gap > margin) continue;
      updateContact(q, findPrevious(rc.previous, q, r), r, law, h);
      out.push_back(q);
      ++extra;
    }
    // Each node's own wall. The planes above are tangent near the
    // segment's nearest point; on a curved wall they lie up to
    // L^2 / 2R off at the far node (36 um for a 0.5 mm segment in a
    // 7 mm sac), a free end node has no other segment whose planes
    // would bound it, and a node sliding along a plane tilted from
    // the wall under it goes in by the slide times the tilt (a soft
    // coil's free tip did, docs/contact.md). A node gets the plane of its own nearest
    // feature, pressing that node only, unless a listed plane agrees
    // with it within kNodePlane over the slide the end-of-step check
    // lets pass unchecked (the margin and its tolerance).
    const double slide = margin + kMissedContact * radius;
    for (int j = 0; j < 2; ++j) {
      // The segment's nearest point is this node: the same feature.
      if (n.hit.s == j) continue;
      const Vec3& x = j ? b : a;
      const NearestTriangle own = nearestToNode(tree, x, j, n, reach, scratch);
      if (own.triangle < 0 || own.hit.distance > reach) continue;
      ContactPoint p = makeContact(tree, own, candidates, nodeHits, e, int(o), radius);
      bool covered = false;
      for (size_t i = listed; i < out.size() && !covered; ++i) {
        const ContactPoint& q = out[i];
        const double lessThanOwn = -p.gap - (q.radius - q.normal.dot(x - q.anchor));
        covered = lessThanOwn + slide * q.normal.cross(p.normal).norm() <= kNodePlane * radius;
      }
      if (covered) continue;
      p.node = j;
      if (!markClosing(p, r, h) && p.gap > margin) continue;
      updateContact(p, findPrevious(rc.previous, p, r), r, law, h);
      out.push_back(p);
    }
  }
  const bool free = out.size() == before && clear > reach;
  rc.wallClear[e] = free ? std::min(clear, reach + kLookAhead) : 0.0;
  rc.wallClearAt[2 * e] = a, rc.wallClearAt[2 * e + 1] = b;
}

}  // namespace

double wallStiffness(double stiffness, double rigidityScale, const RodModel& rod) {
  const double r = rod.section.radius;
  if (!(rigidityScale > 0) || !(r > 0)) return stiffness;
  const double rigidity = rod.material.youngModulus * std::min(rod.section.iy, rod.section.iz);
  return std::max(stiffness, rigidityScale * rigidity / r);
}

void detectWallContacts(const Model& model, State& state, double h, double margin, const ContactLaw& wallLaw,
                        double rigidityScale) {
  ContactScratch& scratch = state.contactScratch;
  const bool coherent = scratch.coherentWall;
  const size_t rods = state.rods.size();
  std::vector<ContactLaw> laws(rods, wallLaw);
  int segments = 0;
  for (size_t k = 0; k < rods; ++k) {
    RodState& r = state.rods[k];
    laws[k].stiffness = wallStiffness(wallLaw.stiffness, rigidityScale, model.rods[k]);
    RodContacts& rc = r.contact;
    // A sleeping rod keeps its last contacts and forces (physics/sleep.h).
    if (r.asleep) continue;
    std::swap(rc.wall, rc.previous);
    rc.wall.clear();
    if (!r.active || model.rods[k].role == RodRole::Catheter) continue;
    if (rc.wallClearNodes != r.activeNodes) {
      rc.wallClear.assign(std::max(0, r.activeNodes - 1), 0.0);
      rc.wallClearAt.assign(2 * rc.wallClear.size(), Vec3::Zero());
      rc.wallClearNodes = r.activeNodes;
    }
    // A hint is only a guess (a node inserted at the catheter tip
    // renumbers the segments behind it), so it is kept across renumbering.
    rc.wallHint.resize(rc.wallClear.size() * model.obstacles.size(), -1);
    // So is a cached walk of the tree: it is used only for boxes within its own.
    rc.wallCache.resize(rc.wallHint.size());
    segments += std::max(0, r.activeNodes - 1);
  }
  // Two parts of the segments in (rod, segment) order, the first half and
  // the second; each rod's list is then the first part's contacts followed
  // by the second's, which is the order of one pass.
  const bool split = scratch.threads.splits(segments);
  const int half = split ? segments / 2 : segments;
  scratch.threads.run(split, scratch, [&](int part, ContactScratch& s) {
    std::vector<std::vector<ContactPoint>>& found = scratch.parts[part].wall;
    if (split) found.resize(rods);
    int index = 0;  // of the first segment of rod k in (rod, segment) order
    const int from = part ? half : 0, to = part ? segments : half;
    for (size_t k = 0; k < rods && index < to; ++k) {
      RodState& r = state.rods[k];
      if (!r.active || r.asleep || model.rods[k].role == RodRole::Catheter) continue;
      const int n = std::max(0, r.activeNodes - 1);
      std::vector<ContactPoint>& out = split ? found[k] : r.contact.wall;
      if (split) out.clear();
      for (int e = std::max(0, from - index); e < n && index + e < to; ++e)
        detectSegment(model, r, e, h, margin, laws[k], coherent, s, out);
      index += n;
    }
  });
  for (size_t k = 0; k < rods; ++k) {
    RodState& r = state.rods[k];
    RodContacts& rc = r.contact;
    if (r.asleep) continue;
    if (split && r.active && model.rods[k].role != RodRole::Catheter) {
      std::swap(rc.wall, scratch.parts[0].wall[k]);
      const std::vector<ContactPoint>& second = scratch.parts[1].wall[k];
      rc.wall.insert(rc.wall.end(), second.begin(), second.end());
    }
    reportContacts(rc.wall, r, laws[k], rc.wallForce);
    // The wire's own penetration: the contacts' gaps are the skinned capsule's.
    rc.wallPenetration = 0;
    for (const ContactPoint& c : rc.wall)
      rc.wallPenetration = std::max(rc.wallPenetration, -c.gap - c.radius * kWallSkin / (1 + kWallSkin));
    rc.wallPenetrationPeak = std::max(rc.wallPenetrationPeak, rc.wallPenetration);
  }
}

std::optional<Failure> checkWallContacts(const Model& model, const State& state, double margin, bool heldOnly) {
  ContactScratch& scratch = state.contactScratch;
  const std::vector<int>& candidates = scratch.candidates;
  const std::vector<SegmentTriangle>& hits = scratch.hits;
  std::optional<Failure> missed;
  double worst = 0;
  for (size_t k = 0; k < state.rods.size(); ++k) {
    const RodState& r = state.rods[k];
    if (!r.active || r.asleep || model.rods[k].role == RodRole::Catheter || r.work.x0.size() < size_t(r.activeNodes))
      continue;  // (a sleeping rod has not moved)
    const std::vector<ContactPoint>& list = r.contact.wall;
    for (int e = 0; e + 1 < r.activeNodes; ++e) {
      const Vec3 &a = r.x[e], &b = r.x[e + 1];
      const double radius = (1 + kWallSkin) * 0.5 * (r.nodes[e].radius + r.nodes[e + 1].radius);
      // Per node, how deep the step's own contact planes (those in its
      // implicit solve) let it go, and how near the others were. A plane
      // bounds the nodes it pressed from the step's start (penetrating or
      // closing then); a node that an iterate carried in
      // (ContactPoint::pressed) is outside the step's linearisation, and its
      // depth is what the iterations left, not the penalty's balance. A wall
      // not listed was more than the margin away, a listed plane out of the
      // node's solve as far as the node was from it at the start. A node
      // that moved less than that (plus the tolerance) cannot have gone in;
      // sliding along the planes in the solve takes more than the margin to
      // leave them by the tolerance on a 7 mm sphere (0.23 mm).
      double known[2] = {0, 0}, nearestOut[2] = {margin, margin};
      const auto first = std::lower_bound(list.begin(), list.end(), e,
                                          [](const ContactPoint& c, int seg) { return c.segment < seg; });
      for (auto c = first; c != list.end() && c->segment == e; ++c)
        for (int j = 0; j < 2; ++j) {
          if (c->node >= 0 && c->node != j) continue;
          const double start = c->radius - c->normal.dot(r.work.x0[e + j] - c->anchor);
          const bool inSolve = heldOnly ? c->multiplier[j] > 0
                                        : c->entered[j] != Entry::Released &&
                                              (start > 0 || c->closing[j] || c->entered[j] != Entry::No);
          if (inSolve)
            known[j] = std::max(known[j], c->radius - c->normal.dot(r.x[e + j] - c->anchor));
          else
            nearestOut[j] = std::min(nearestOut[j], std::max(0.0, -start));
        }
      const double tolerance = kMissedContact * radius;
      if ((a - r.work.x0[e]).norm() <= nearestOut[0] + tolerance && (b - r.work.x0[e + 1]).norm() <= nearestOut[1] + tolerance)
        continue;
      for (size_t o = 0; o < model.obstacles.size(); ++o) {
        if (!model.obstacles[o].contact || o >= model.obstacleTrees.size()) continue;
        const ObstacleTree& tree = *model.obstacleTrees[o];
        const NearestTriangle n = nearestWallFeature(tree, a, b, 2 * radius, scratch, 2 * radius);
        if (n.triangle < 0) continue;
        // The planes' penetration is linear along the segment: at the
        // deepest point s they allow (1 - s) known_a + s known_b.
        const double depth = -makeContact(tree, n, candidates, hits, e, int(o), radius).gap;
        const double allowed = (1 - n.hit.s) * known[0] + n.hit.s * known[1];
        if (depth - allowed <= tolerance || depth - allowed <= worst) continue;
        worst = depth - allowed;
        missed = badRod(model.rods[k].name, "went " + std::to_string(int(std::lround(depth * 1e6))) +
                                                " um into obstacle '" + model.obstacles[o].name + "' within the step, " +
                                                std::to_string(int(std::lround(worst * 1e6))) +
                                                " um deeper than its contact planes allowed");
        missed->kind = FailureKind::MissedContact;
        missed->beam = e;
        missed->quantity = "depth beyond the contact planes";
        missed->value = worst, missed->limit = tolerance;
      }
    }
  }
  return missed;
}

}  // namespace coilsim
