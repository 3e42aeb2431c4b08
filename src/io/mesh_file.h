#pragma once
// Triangle surfaces from files (STL, OBJ, PLY, OFF... through assimp) and
// binary STL out; the phantom sidecar (sac and neck plane) next to an STL.
// Files are in millimetres (times a scale); the core's meshes in metres.
#include <string>
#include <vector>

#include "geometry/mesh_report.h"
#include "geometry/phantom.h"
#include "physics/triangle_mesh.h"

namespace coilsim::io {

// What a mesh file may hold (docs/input-limits.md). Counts are checked
// against the header and the bytes the file holds before anything is
// allocated; the extent keeps out a file in metres (or micrometres) read as
// millimetres.
inline constexpr size_t kMaxMeshFileBytes = size_t(512) << 20;  // 512 MiB
inline constexpr size_t kMaxMeshVertices = 4'000'000;
inline constexpr size_t kMaxMeshTriangles = 8'000'000;
inline constexpr double kMinMeshExtentMm = 0.2;   // largest side of the bounding box, at least
inline constexpr double kMaxMeshExtentMm = 2000;  // and at most (2 m)

// A surface file as read, before anything is refused.
struct MeshInspection {
  std::string file;
  int parts = 0;                    // meshes (groups, objects) in the file, merged into one
  TriangleMesh mesh;                // mm (scaled), identical vertices of all parts merged
  geometry::MeshReport report;      // of `mesh`
  geometry::RepairResult repaired;  // what loading would use (mm)
};

// Reads every triangle of the file (assimp: triangulated, identical vertices
// joined, node transforms applied; points and lines skipped), times
// `scaleToMm`. Before assimp reads it, the file's structure is checked
// (STL, PLY, OFF, OBJ): counts against the header, the limits above and the
// bytes present; every face index against the vertex count. Throws
// InputError naming the file (and the element, record and limit) when it is
// missing, a directory, unreadable, malformed, beyond a limit, of an unknown
// format or holds no triangle, when a coordinate is not finite, or when the
// scale is not a finite number > 0. A surface whose bounding box is outside
// [kMinMeshExtentMm, kMaxMeshExtentMm] is read but marked not usable
// (repaired.usable false, the reason suggesting the scale).
MeshInspection inspectMeshFile(const std::string& path, double scaleToMm = 1.0);

// A surface ready for contact and volumes, in metres: read, safely repaired
// (see geometry::repairMesh). Throws InputError naming the file, the reason
// (open, non-manifold...) and the report when it cannot be used.
TriangleMesh loadMeshFile(const std::string& path, double scaleToMm = 1.0);

// Multi-line report for users: triangles, bounds (mm), closed, oriented,
// components, volume (mm^3), repairs, and whether the surface is usable.
std::string describeInspection(const MeshInspection& inspection);

// Writes a binary STL of `mesh` with coordinates as they are (millimetres by
// convention) and face normals from the vertex order. Written to a temporary
// file and renamed. Throws std::runtime_error naming the file on failure.
void writeBinaryStl(const TriangleMesh& mesh, const std::string& path);

// The sidecar of a phantom STL: same path with ".phantom.json" for ".stl".
std::string phantomSidecarPath(const std::string& stlPath);
// Writes / reads a phantom's description (coilsim-phantom/1: type,
// parameters, sac centre, radii and axes, lobes, neck plane point and normal
// toward the dome, neck width, ideal sac volume), all in mm. Writing throws
// std::runtime_error naming the file; reading throws InputError naming the
// file and JSON path.
void writePhantomSidecar(const geometry::PhantomInfo& info, const std::string& path);
geometry::PhantomInfo readPhantomSidecar(const std::string& path);

}  // namespace coilsim::io
