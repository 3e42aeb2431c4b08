#pragma once
// The collision tree of one obstacle: an FCL bounding-volume hierarchy of
// axis-aligned boxes over its triangles, built once when the Model is
// compiled and shared (immutable) by every State. FCL builds the tree; the
// queries below walk it themselves with box tests, because FCL's collide()
// runs GJK per triangle (slow for thousands of capsules per step) and does
// not report a segment that lies wholly inside a closed mesh.
#include <memory>
#include <vector>

#include "physics/contact/triangle_cache.h"
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
  // The same triangles in the same order, from `cache` when [lo, hi] lies
  // within its box: a triangle whose box overlaps [lo, hi] overlaps every
  // box around it, and the walk meets the leaves in one fixed order, so
  // filtering the triangles found for the larger box by their own boxes
  // gives exactly what a walk for [lo, hi] gives. Otherwise the tree is
  // walked for [lo, hi] grown by `slack` on every side, kept in `cache`.
  void overlapping(const Vec3& lo, const Vec3& hi, double slack, TriangleCache& cache, std::vector<int>& stack,
                   std::vector<int>& out) const;
  // A lower bound of the distance from any point of segment [a, b] to
  // triangle t: the segment's height over the triangle's plane and its
  // shadow's distance from the disc around the triangle's centroid through
  // its farthest vertex, made smaller by far more than round-off, so that a
  // query may skip the triangle when this exceeds what it has found.
  double distanceBound(int t, const Vec3& a, const Vec3& b) const;

 private:
  struct Impl;
  std::shared_ptr<const TriangleMesh> mesh_;
  std::vector<Vec3> normals_;  // (ntriangle)
  std::vector<Vec3> boxLo_, boxHi_;  // (ntriangle) each triangle's box as the tree's leaf holds it
  std::vector<Vec3> centroids_;      // (ntriangle)
  std::vector<double> spheres_;      // (ntriangle) distance from the centroid to the farthest vertex, m
  std::unique_ptr<Impl> impl_;
};

// One tree per obstacle (in the order of Model::obstacles).
std::vector<std::shared_ptr<const ObstacleTree>> buildObstacleTrees(const std::vector<Obstacle>& obstacles);

}  // namespace coilsim
