#pragma once
// What a triangle surface is, topologically and geometrically, and the safe
// repairs that make a slightly untidy surface usable for contact and volumes.
#include <string>
#include <vector>

#include "physics/triangle_mesh.h"

namespace coilsim::geometry {

struct MeshReport {
  size_t vertices = 0, triangles = 0;
  Vec3 lower = Vec3::Zero(), upper = Vec3::Zero();  // axis-aligned bounds (mesh units)
  size_t edges = 0;                 // distinct undirected edges
  size_t boundaryEdges = 0;         // used by one triangle: holes
  size_t nonManifoldEdges = 0;      // used by three or more triangles
  size_t misorientedEdges = 0;      // used twice, both times in the same direction
  size_t degenerateTriangles = 0;   // repeated vertex index or zero area
  size_t unusedVertices = 0;
  size_t components = 0;            // triangles connected through shared edges
  double volume = 0;                // signed enclosed volume (divergence theorem), mesh units^3

  // Every edge shared by exactly two triangles.
  bool closed() const { return triangles > 0 && boundaryEdges == 0 && nonManifoldEdges == 0; }
  // Each shared edge used once in each direction.
  bool oriented() const { return misorientedEdges == 0 && nonManifoldEdges == 0; }
  // Closed, oriented and enclosing a positive volume: normals point out.
  bool outward() const { return closed() && oriented() && volume > 0; }
  // What a contact or volume computation can rely on.
  bool usable() const { return outward() && degenerateTriangles == 0; }
};

// Counts edges, components and the signed volume. Never throws; indices out
// of range count as degenerate triangles.
MeshReport analyseMesh(const TriangleMesh& mesh);

// One line per finding, e.g. "12 boundary edges (holes)"; empty when usable.
std::vector<std::string> describeProblems(const MeshReport& report);

// The same triangles over merged vertices: every vertex within `tolerance`
// of an earlier one (0: at the identical position) is replaced by it. Changes
// no geometry beyond `tolerance`; keeps degenerate triangles (see repairMesh).
TriangleMesh weldVertices(const TriangleMesh& mesh, double tolerance = 0);

struct RepairResult {
  TriangleMesh mesh;                   // the repaired surface (or the best attempt)
  MeshReport report;                   // of `mesh`
  std::vector<std::string> actions;    // what was changed, for the user
  bool usable = false;
  std::string reason;                  // why not usable (empty when usable)
};

// Safe repairs only: weld vertices closer than `weldTolerance` (0: identical
// positions only), drop degenerate triangles and unused vertices, orient each
// component consistently by walking shared edges, and flip components that
// enclose a negative volume. Refuses (usable = false, with the reason)
// surfaces with holes or non-manifold edges or that are not orientable:
// filling holes or splitting edges would invent geometry.
RepairResult repairMesh(const TriangleMesh& mesh, double weldTolerance = 0);

}  // namespace coilsim::geometry
