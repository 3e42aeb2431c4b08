#pragma once
// What the renderer draws, as plain data (the core never draws): tubes along
// rod centre lines with per-node colours, triangle meshes, marked points with
// optional vectors. Positions are SI (metres), like everything in the core.
#include <string>
#include <vector>

#include "physics/math.h"

namespace coilsim {

struct Model;
struct State;

using Colour = Eigen::Vector4f;  // linear RGBA in [0, 1]

enum class RodRole { Coil, Catheter, Wire };

struct DrawTube {
  std::string name;
  RodRole role = RodRole::Coil;
  double radius = 0;             // m
  std::vector<Vec3> centre;      // (nnode) centre line
  std::vector<Quat> frames;      // (nnode) material frames (for twist stripes)
  std::vector<Colour> colours;   // (nnode) per-node colour (stress, error, contact...)
};

struct DrawMesh {
  std::string name;
  std::vector<Vec3> vertices;           // m
  std::vector<Eigen::Vector3i> triangles;
  Colour colour = Colour(0.8f, 0.3f, 0.3f, 0.35f);
};

struct DrawPoint {
  Vec3 position = Vec3::Zero();
  Vec3 vector = Vec3::Zero();  // e.g. a contact force, drawn as an arrow if non-zero (m after scaling)
  Colour colour = Colour(1, 1, 0, 1);
};

struct DrawData {
  std::vector<DrawTube> tubes;
  std::vector<DrawMesh> meshes;
  std::vector<DrawPoint> points;
};

// Default colours per role; stress colouring is left to callers.
Colour defaultColour(RodRole role);

// Fills `out.tubes` from the state's rods and `out.meshes` (resized to the
// obstacle count) from the model's obstacles, semi-transparent, reusing
// storage. Points, and any further meshes appended after this call, are left
// for the layers that own them (contacts, validation).
void fillDrawData(const Model& model, const State& state, DrawData& out);

}  // namespace coilsim
