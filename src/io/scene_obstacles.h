#pragma once
// The "obstacles" block of a scene: aneurysm and vessel surfaces read from
// mesh files (path relative to the scene), placed, and compiled into the
// core's Obstacles (metres). docs/scene-format.md, "Obstacles".
#include <string>
#include <vector>

#include "io/json_reader.h"
#include "physics/triangle_mesh.h"

namespace coilsim::io {

struct ObstacleSpec {
  std::string name;
  std::string mesh;       // as written in the scene
  std::string meshPath;   // resolved against the scene file's directory
  double scaleToMm = 1;   // file units -> mm
  Vec3 offsetMm = Vec3::Zero();
  Vec3 rotationDeg = Vec3::Zero();  // about x, then y, then z (fixed axes), before the offset
  double friction = 0.3;
  bool contact = true;
  std::string at;         // JSON path, for messages
};

// Reads the array under "obstacles"; `sceneFile` resolves relative mesh
// paths. Throws InputError naming the scene file and JSON path (unknown keys,
// ranges, duplicate names).
std::vector<ObstacleSpec> readObstacles(const JsonNode& node, const std::string& sceneFile);

// Loads, checks (closed, oriented; safe repairs) and places each mesh in SI.
// Throws InputError "scene: /obstacles/i/mesh: <mesh file>: <reason>".
std::vector<Obstacle> compileObstacles(const std::vector<ObstacleSpec>& specs, const std::string& sceneFile);

}  // namespace coilsim::io
