#include "physics/contact/obstacle_tree.h"

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

std::vector<std::shared_ptr<const ObstacleTree>> buildObstacleTrees(const std::vector<Obstacle>& obstacles) {
  std::vector<std::shared_ptr<const ObstacleTree>> trees;
  for (const Obstacle& o : obstacles) trees.push_back(std::make_shared<const ObstacleTree>(o.mesh));
  return trees;
}

}  // namespace coilsim
