// Point-to-wall distance through the obstacles' collision trees.
#include "physics/contact/clearance.h"

#include <algorithm>

#include "physics/contact/geometry.h"
#include "physics/contact/obstacle_tree.h"

namespace coilsim {

double wallClearance(const Model& model, const Vec3& p, double reach) {
  double best = reach;
  std::vector<int> stack, hits;
  const Vec3 box = Vec3::Constant(reach);
  for (size_t o = 0; o < model.obstacles.size() && o < model.obstacleTrees.size(); ++o) {
    if (!model.obstacles[o].contact || !model.obstacleTrees[o]) continue;
    const ObstacleTree& tree = *model.obstacleTrees[o];
    hits.clear();
    tree.overlapping(p - box, p + box, stack, hits);
    const TriangleMesh& m = tree.mesh();
    for (const int t : hits) {
      const auto& f = m.triangles[size_t(t)];
      const Vec3 q = closestPointTriangle(p, m.vertices[size_t(f[0])], m.vertices[size_t(f[1])], m.vertices[size_t(f[2])]);
      best = std::min(best, (q - p).norm());
    }
  }
  return best;
}

double pinnedWireDepth(const State& state, int rod, int node, const Vec3& move) {
  const RodState& r = state.rods[size_t(rod)];
  double deepest = 0;
  for (const std::vector<ContactPoint>* list : {&r.contact.self, &r.contact.rod})
    for (const ContactPoint& c : *list) {
      const double weight = c.segment == node ? 1 - c.s : c.segment + 1 == node ? c.s : 0.0;
      if (weight < 0.5 || !(c.radius > 0) || move.dot(c.normal) >= 0) continue;
      const RodState& o = state.rods[size_t(c.other)];
      if (c.otherSegment < 0 || c.otherSegment + 1 >= o.activeNodes || c.segment + 1 >= r.activeNodes) continue;
      const std::vector<double>& wall = o.contact.wallForce;
      if (size_t(c.otherSegment) + 1 >= wall.size() || !(wall[size_t(c.otherSegment)] > 0 || wall[size_t(c.otherSegment) + 1] > 0))
        continue;
      const Vec3 p = (1 - c.s) * r.x[size_t(c.segment)] + c.s * r.x[size_t(c.segment) + 1];
      const Vec3 q = (1 - c.otherS) * o.x[size_t(c.otherSegment)] + c.otherS * o.x[size_t(c.otherSegment) + 1];
      deepest = std::max(deepest, (c.radius - (p - q).dot(c.normal)) / c.radius);
    }
  return deepest;
}

}  // namespace coilsim
