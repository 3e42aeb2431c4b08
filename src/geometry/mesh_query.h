#pragma once
// Point queries against a closed triangle surface, fast on large meshes
// through a bounding-volume hierarchy: inside or outside, closest point,
// signed distance. Used for penetration measurement, volume sampling and
// planning; the surface should be usable (see mesh_report.h).
#include <vector>

#include "physics/triangle_mesh.h"

namespace coilsim::geometry {

struct ClosestPoint {
  Vec3 point = Vec3::Zero();
  int triangle = -1;
  double distance = 0;  // unsigned
};

class MeshQuery {
 public:
  // Copies the surface and builds the hierarchy (O(n log n)).
  explicit MeshQuery(const TriangleMesh& mesh);

  // True when `p` is enclosed by the surface (ray parity; a ray that grazes
  // an edge or a vertex is replaced by another direction). Points on the
  // surface itself may go either way.
  bool inside(const Vec3& p) const;
  // The nearest point of the surface; triangle -1 for an empty mesh.
  ClosestPoint closest(const Vec3& p) const;
  // Distance to the surface, negative inside.
  double signedDistance(const Vec3& p) const;
  // Number of triangles a ray from `origin` along `direction` crosses, or -1
  // when it passes within numerical reach of an edge or vertex.
  int crossings(const Vec3& origin, const Vec3& direction) const;
  // The first triangle a ray from `origin` along `direction` meets (the
  // nearest crossing at t > 0), or -1 when it meets none. A ray through an
  // edge returns either triangle.
  int firstHit(const Vec3& origin, const Vec3& direction) const;

  const TriangleMesh& mesh() const { return mesh_; }

 private:
  struct Node {
    Eigen::AlignedBox3d box;
    int first = 0, count = 0;  // leaf: triangles order_[first, first+count)
    int left = -1, right = -1;
  };
  int build(int first, int count, std::vector<Vec3>& centres);
  // Calls visit(triangle, a, b, c) for each triangle in a leaf whose box the
  // ray meets; false from visit stops the walk (and is returned).
  template <class Visit>
  bool walkRay(const Vec3& origin, const Vec3& direction, Visit&& visit) const;

  TriangleMesh mesh_;
  std::vector<Node> nodes_;
  std::vector<int> order_;  // triangle indices, grouped by leaf
};

}  // namespace coilsim::geometry
