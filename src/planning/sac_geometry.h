#pragma once
// The aneurysm sac as planning sees it: a closed triangle surface (sac and
// parent vessel, metres, outward counter-clockwise triangles) and the neck
// plane that closes the sac off from the vessel. Pure geometry: no files,
// no GL. Inside tests go through the geometry layer's BVH (MeshQuery) and
// volumes through its exact plane cut (geometry/volume.h).
#include <memory>
#include <string>

#include "geometry/mesh_query.h"
#include "physics/math.h"
#include "physics/triangle_mesh.h"

namespace coilsim::planning {

// The neck plane; `normal` (unit) points into the sac.
struct Plane {
  Vec3 point = Vec3::Zero();
  Vec3 normal = Vec3::UnitZ();
  double signedDistance(const Vec3& x) const { return normal.dot(x - point); }
};

struct Sac {
  std::shared_ptr<const TriangleMesh> mesh;  // closed surface holding the sac (and usually the vessel)
  Plane neck;
  std::shared_ptr<const geometry::MeshQuery> query;  // inside tests on `mesh`; built by makeSac
};

// A sac of `mesh` closed by `neck` (normal normalised), with its query structure.
Sac makeSac(std::shared_ptr<const TriangleMesh> mesh, const Plane& neck);

// Volume enclosed by the closed `mesh` on the side of `plane` its normal
// points to (m^3; geometry::volumeAbovePlane, exact for the mesh).
double volumeOnSide(const TriangleMesh& mesh, const Plane& plane);

// Whole enclosed volume (divergence theorem), m^3; negative if the triangles face inwards.
double enclosedVolume(const TriangleMesh& mesh);

// True when `x` is inside the sac's closed surface (either side of the neck plane).
bool insideSurface(const Sac& sac, const Vec3& x);

// Length of the segment a-b inside the sac (inside the mesh and on the sac
// side of the neck plane), m: the segment is split at every crossing with the
// surface and the plane, and each piece is classified by its midpoint. Exact
// up to rounding for a closed mesh.
double lengthInSac(const Sac& sac, const Vec3& a, const Vec3& b);
// The same for the other side: inside the mesh beyond the neck plane (the parent vessel).
double lengthBeyondNeck(const Sac& sac, const Vec3& a, const Vec3& b);

// A closed icosphere (subdivided icosahedron, vertices on the sphere), for
// analytic checks and spherical phantoms given by centre and radius.
TriangleMesh makeIcosphere(const Vec3& centre, double radius, int subdivisions, const std::string& name = "sphere");

}  // namespace coilsim::planning
