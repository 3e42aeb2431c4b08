#pragma once
// The collision tree of one obstacle: an FCL bounding-volume hierarchy of
// axis-aligned boxes over its triangles, built once when the Model is
// compiled and shared (immutable) by every State. FCL builds the tree; the
// queries below walk it themselves with box tests, because FCL's collide()
// runs GJK per triangle (slow for thousands of capsules per step) and does
// not report a segment that lies wholly inside a closed mesh.
#include <memory>
#include <vector>

#include "physics/math.h"
#include "physics/triangle_mesh.h"

namespace coilsim {

class ObstacleTree {
 public:
  // Throws PhysicsError (physics/failure.h) naming the mesh if a triangle indexes a
  // missing vertex or a vertex is not finite.
  explicit ObstacleTree(std::shared_ptr<const TriangleMesh> mesh);
  ~ObstacleTree();
  ObstacleTree(const ObstacleTree&) = delete;
  ObstacleTree& operator=(const ObstacleTree&) = delete;

  const TriangleMesh& mesh() const { return *mesh_; }
  // Unit normal of triangle t, pointing out of the closed surface (the
  // winding is counter-clockwise seen from outside).
  const Vec3& normal(int t) const { return normals_[t]; }
  // Triangles whose box overlaps [lo, hi], appended to `out`.
  void overlapping(const Vec3& lo, const Vec3& hi, std::vector<int>& stack, std::vector<int>& out) const;

 private:
  struct Impl;
  std::shared_ptr<const TriangleMesh> mesh_;
  std::vector<Vec3> normals_;  // (ntriangle)
  std::unique_ptr<Impl> impl_;
};

// One tree per obstacle (in the order of Model::obstacles).
std::vector<std::shared_ptr<const ObstacleTree>> buildObstacleTrees(const std::vector<Obstacle>& obstacles);

}  // namespace coilsim
