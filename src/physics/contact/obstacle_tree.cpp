#include "physics/contact/obstacle_tree.h"

#include <algorithm>
#include <cmath>
#include <string>

#include <fcl/geometry/bvh/BVH_model.h>
#include <fcl/math/bv/AABB.h>

#include "physics/failure.h"

namespace coilsim {

struct ObstacleTree::Impl {
  fcl::BVHModel<fcl::AABBd> bvh;
};

ObstacleTree::ObstacleTree(std::shared_ptr<const TriangleMesh> mesh) : mesh_(std::move(mesh)), impl_(new Impl) {
  if (!mesh_) throw PhysicsError(badDefinition("obstacle tree", "no mesh"));
  const TriangleMesh& m = *mesh_;
  const int nv = int(m.vertices.size());
  for (const Vec3& v : m.vertices)
    if (!v.allFinite()) throw PhysicsError(badDefinition("mesh '" + m.name + "'", "a vertex is not finite"));
  std::vector<fcl::Vector3d> vertices(m.vertices.begin(), m.vertices.end());
  std::vector<fcl::Triangle> triangles;
  triangles.reserve(m.triangles.size());
  normals_.reserve(m.triangles.size());
  for (size_t t = 0; t < m.triangles.size(); ++t) {
    const Eigen::Vector3i& f = m.triangles[t];
    for (int k = 0; k < 3; ++k)
      if (f[k] < 0 || f[k] >= nv)
        throw PhysicsError(badDefinition("mesh '" + m.name + "'", "triangle " + std::to_string(t) +
                                                                          " uses missing vertex " + std::to_string(f[k])));
    triangles.emplace_back(f[0], f[1], f[2]);
    const Vec3 n = (m.vertices[f[1]] - m.vertices[f[0]]).cross(m.vertices[f[2]] - m.vertices[f[0]]);
    // A degenerate triangle keeps a zero normal: it never decides a side.
    normals_.push_back(n.norm() > 0 ? Vec3(n.normalized()) : Vec3(Vec3::Zero()));
  }
  fcl::BVHModel<fcl::AABBd>& bvh = impl_->bvh;
  if (bvh.beginModel(int(triangles.size()), nv) != fcl::BVH_OK || bvh.addSubModel(vertices, triangles) != fcl::BVH_OK ||
      bvh.endModel() != fcl::BVH_OK)
    throw PhysicsError(badDefinition("mesh '" + m.name + "'", "FCL could not build its bounding-volume tree"));
  // The leaves' own boxes, so that a cached walk filters by exactly the
  // comparisons the walk makes.
  boxLo_.assign(triangles.size(), Vec3::Zero());
  boxHi_.assign(triangles.size(), Vec3::Zero());
  for (int i = 0; i < bvh.getNumBVs(); ++i) {
    const auto& node = bvh.getBV(i);
    if (!node.isLeaf()) continue;
    boxLo_[node.primitiveId()] = node.bv.min_;
    boxHi_[node.primitiveId()] = node.bv.max_;
  }
  centroids_.reserve(triangles.size());
  spheres_.reserve(triangles.size());
  for (const Eigen::Vector3i& f : m.triangles) {
    const Vec3 c = (m.vertices[f[0]] + m.vertices[f[1]] + m.vertices[f[2]]) / 3;
    centroids_.push_back(c);
    spheres_.push_back(std::max({(m.vertices[f[0]] - c).norm(), (m.vertices[f[1]] - c).norm(), (m.vertices[f[2]] - c).norm()}));
  }
}

ObstacleTree::~ObstacleTree() = default;

void ObstacleTree::overlapping(const Vec3& lo, const Vec3& hi, std::vector<int>& stack, std::vector<int>& out) const {
  const fcl::BVHModel<fcl::AABBd>& bvh = impl_->bvh;
  stack.clear();
  stack.push_back(0);
  while (!stack.empty()) {
    const int id = stack.back();
    stack.pop_back();
    const auto& node = bvh.getBV(id);
    const fcl::AABBd& box = node.bv;
    if ((box.min_.array() > hi.array()).any() || (box.max_.array() < lo.array()).any()) continue;
    if (node.isLeaf()) {
      out.push_back(node.primitiveId());
    } else {
      stack.push_back(node.leftChild());
      stack.push_back(node.rightChild());
    }
  }
}

void ObstacleTree::overlapping(const Vec3& lo, const Vec3& hi, double slack, TriangleCache& cache, std::vector<int>& stack,
                               std::vector<int>& out) const {
  // (Written so that a non-finite box is never taken as within the cache's.)
  const bool within = cache.valid && (lo.array() >= cache.lo.array()).all() && (hi.array() <= cache.hi.array()).all();
  if (!within) {
    cache.lo = lo.array() - slack;
    cache.hi = hi.array() + slack;
    cache.triangles.clear();
    overlapping(cache.lo, cache.hi, stack, cache.triangles);
    cache.valid = true;
  }
  for (const int t : cache.triangles)
    if (!((boxLo_[t].array() > hi.array()).any() || (boxHi_[t].array() < lo.array()).any())) out.push_back(t);
}

double ObstacleTree::distanceBound(int t, const Vec3& a, const Vec3& b) const {
  // Split a point's offset from the triangle into the part along the
  // normal and the part in its plane: the first is at least the lower end's
  // height over the plane (0 if the segment crosses it), the second at
  // least the distance of the segment's shadow on the plane from the disc
  // around the centroid through the farthest vertex, which holds the
  // triangle. Tight under a segment lying over a flat wall, where only the
  // triangles its shadow meets are left to measure.
  const Vec3& c = centroids_[t];
  const Vec3& n = normals_[t];  // zero for a degenerate triangle: the sphere's bound
  const double ha = n.dot(a - c), hb = n.dot(b - c);
  const double height = ha * hb > 0 ? std::min(std::abs(ha), std::abs(hb)) : 0.0;
  const Vec3 pa = a - ha * n, ab = (b - hb * n) - pa;
  const double length2 = ab.squaredNorm();
  const double s = length2 > 0 ? std::clamp((c - pa).dot(ab) / length2, 0.0, 1.0) : 0.0;
  const double across = std::max(0.0, (pa + s * ab - c).norm() - spheres_[t]);
  // Round-off in these few operations is about 1e-16 of the coordinates
  // (metres); the bound is made a millionth of the disc and a picometre
  // smaller.
  return std::sqrt(height * height + across * across) - 1e-6 * spheres_[t] - 1e-12;
}

std::vector<std::shared_ptr<const ObstacleTree>> buildObstacleTrees(const std::vector<Obstacle>& obstacles) {
  std::vector<std::shared_ptr<const ObstacleTree>> trees;
  for (const Obstacle& o : obstacles) trees.push_back(std::make_shared<const ObstacleTree>(o.mesh));
  return trees;
}

}  // namespace coilsim
