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
  // When the plane cuts the surface into several pieces on its sac side (a
  // bifurcation's daughter vessels rising past it), the sac is the piece
  // above the neck's point: one flag per triangle of `mesh`, and a point of
  // that piece's surface. Null when the whole sac side is one piece.
  std::shared_ptr<const std::vector<char>> piece;
  Vec3 pieceSeed = Vec3::Zero();
};

// A sac of `mesh` closed by `neck` (normal normalised), with its query
// structure and, when the plane cuts several pieces, the sac's piece: the
// one a ray from the neck's point along the normal meets first (the space
// just above the ostium is the sac's). Throws std::invalid_argument when the
// plane cuts several pieces and that point is not inside the surface.
Sac makeSac(std::shared_ptr<const TriangleMesh> mesh, const Plane& neck);

// The sac's volume: enclosed by its piece of the surface and the neck plane
// (m^3; volumeOnSide when the sac side is one piece).
double sacVolume(const Sac& sac);

// True when `x` is in the sac: inside the surface, on the sac side of the
// plane and, when the plane cuts several pieces, under the sac's piece.
bool inSac(const Sac& sac, const Vec3& x);

// Volume enclosed by the closed `mesh` on the side of `plane` its normal
// points to (m^3; geometry::volumeAbovePlane, exact for the mesh).
double volumeOnSide(const TriangleMesh& mesh, const Plane& plane);

// Whole enclosed volume (divergence theorem), m^3; negative if the triangles face inwards.
double enclosedVolume(const TriangleMesh& mesh);

// True when `x` is inside the sac's closed surface (either side of the neck plane).
bool insideSurface(const Sac& sac, const Vec3& x);

// Length of the segment a-b inside the sac (inSac), m: the segment is split
// at every crossing with the surface and the plane, and each piece is
// classified by its midpoint. Exact up to rounding for a closed mesh.
double lengthInSac(const Sac& sac, const Vec3& a, const Vec3& b);
// The same for the rest of the inside of the surface: beyond the neck plane
// (the parent vessel) or, on the sac side, in another piece (a daughter vessel).
double lengthBeyondNeck(const Sac& sac, const Vec3& a, const Vec3& b);

// A closed icosphere (subdivided icosahedron, vertices on the sphere), for
// analytic checks and spherical phantoms given by centre and radius.
TriangleMesh makeIcosphere(const Vec3& centre, double radius, int subdivisions, const std::string& name = "sphere");

}  // namespace coilsim::planning
