#include <algorithm>
#include <cmath>

#include "physics/contact/detect.h"
#include "physics/contact/geometry.h"
#include "physics/contact/obstacle_tree.h"

namespace coilsim {
namespace {

struct Nearest {
  SegmentTriangle hit;
  int triangle = -1;
};

// The nearest triangle feature to segment [a, b] among those whose boxes
// overlap the segment's box grown by `reach`.
Nearest nearestFeature(const ObstacleTree& tree, const Vec3& a, const Vec3& b, double reach, std::vector<int>& stack,
                       std::vector<int>& candidates) {
  const Vec3 grow = Vec3::Constant(reach);
  candidates.clear();
  tree.overlapping(a.cwiseMin(b) - grow, a.cwiseMax(b) + grow, stack, candidates);
  Nearest best;
  const TriangleMesh& m = tree.mesh();
  for (const int t : candidates) {
    const Eigen::Vector3i& f = m.triangles[t];
    const SegmentTriangle h = closestSegmentTriangle(a, b, m.vertices[f[0]], m.vertices[f[1]], m.vertices[f[2]]);
    if (best.triangle < 0 || h.distance < best.hit.distance) best = {h, t};
  }
  return best;
}

// A contact from the nearest feature: normal from the feature to the centre
// line, flipped (and the gap negative) when the centre line is outside.
ContactPoint makeContact(const ObstacleTree& tree, const Nearest& n, int segment, int obstacle, double radius) {
  ContactPoint c;
  c.segment = segment;
  c.other = obstacle;
  c.line = true;
  c.s = n.hit.s;
  c.radius = radius;
  c.anchor = n.hit.onTriangle;
  const Vec3 away = n.hit.onSegment - n.hit.onTriangle;
  const Vec3& outward = tree.normal(n.triangle);
  const bool outside = away.dot(outward) > 0;
  if (n.hit.distance > 1e-12 * radius) {
    c.normal = (outside ? -1.0 : 1.0) * away / n.hit.distance;
  } else {
    c.normal = -outward;  // centre line on the surface: push inwards
  }
  c.gap = (outside ? -n.hit.distance : n.hit.distance) - radius;
  return c;
}

}  // namespace

void detectWallContacts(const Model& model, State& state, double margin, const ContactLaw& law) {
  static thread_local std::vector<int> stack, candidates;
  for (size_t k = 0; k < state.rods.size(); ++k) {
    RodState& r = state.rods[k];
    RodContacts& rc = r.contact;
    std::swap(rc.wall, rc.previous);
    rc.wall.clear();
    if (r.active && model.rods[k].role != RodRole::Catheter) {
      for (int e = 0; e + 1 < r.activeNodes; ++e) {
        const Vec3 &a = r.x[e], &b = r.x[e + 1];
        const double radius = 0.5 * (r.nodes[e].radius + r.nodes[e + 1].radius);
        for (size_t o = 0; o < model.obstacles.size(); ++o) {
          if (!model.obstacles[o].contact || o >= model.obstacleTrees.size()) continue;
          const ObstacleTree& tree = *model.obstacleTrees[o];
          Nearest n = nearestFeature(tree, a, b, radius + margin, stack, candidates);
          if (n.triangle < 0 || n.hit.distance > radius + margin) {
            // Nothing near: either free, or pushed wholly through the wall
            // since the last step. Only the second needs the wider search.
            ContactPoint probe;
            probe.segment = e, probe.other = int(o);
            if (!findPrevious(rc.previous, probe, r)) continue;
            n = nearestFeature(tree, a, b, 4 * radius + margin, stack, candidates);
            if (n.triangle < 0) continue;
          }
          ContactPoint c = makeContact(tree, n, e, int(o), radius);
          if (c.gap > margin) continue;
          updateContact(c, findPrevious(rc.previous, c, r), r, law, model.timeStep);
          rc.wall.push_back(c);
        }
      }
    }
    rc.wallPenetration = reportContacts(rc.wall, r, law, rc.wallForce);
  }
}

}  // namespace coilsim
