#pragma once
// A triangle surface (aneurysm wall, vessel, phantom) as the core sees it:
// plain arrays in metres. Loading (assimp), checking and generating meshes
// live outside the core; contact and drawing read this.
#include <memory>
#include <string>
#include <vector>

#include "physics/math.h"

namespace coilsim {

struct TriangleMesh {
  std::string name;
  std::vector<Vec3> vertices;               // (nvertex) m
  std::vector<Eigen::Vector3i> triangles;   // (ntriangle) vertex indices, counter-clockwise seen from outside
};

// A surface the rods may touch, as a Model holds it.
struct Obstacle {
  std::string name;
  std::shared_ptr<const TriangleMesh> mesh;  // shared: several Models (fits, plans) may use one mesh
  double friction = 0.3;                      // Coulomb coefficient rod-wall
  bool contact = true;                        // false: drawn only
};

}  // namespace coilsim
