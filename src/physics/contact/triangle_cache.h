#pragma once
// What one walk of an obstacle's collision tree found for a box: the
// triangles whose boxes overlap it, in the tree's order. A segment that
// moves a little between steps asks for boxes inside the last one, and
// ObstacleTree::overlapping filters these instead of walking the tree again.
#include <vector>

#include "physics/math.h"

namespace coilsim {

struct TriangleCache {
  bool valid = false;
  Vec3 lo = Vec3::Zero(), hi = Vec3::Zero();  // the box walked, m
  std::vector<int> triangles;                 // those overlapping it, in the tree's order
};

}  // namespace coilsim
