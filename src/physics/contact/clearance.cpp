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

}  // namespace coilsim
