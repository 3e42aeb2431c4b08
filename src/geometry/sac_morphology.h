#pragma once
// The morphology clinicians size coils by, measured on the surface: the sac
// is the piece of the closed surface on the dome side of the neck plane that
// holds a given point, closed by the plane. Mesh units. Definitions (and
// their sources) in docs/planning.md, "Morphology of a sac".
#include <vector>

#include "geometry/volume.h"
#include "physics/triangle_mesh.h"

namespace coilsim::geometry {

struct SacMorphology {
  double volume = 0;        // enclosed by the sac piece and the neck plane (units^3)
  double neckArea = 0;      // of the ostium, the sac piece's cut by the plane (units^2)
  double neckWidth = 0;     // largest distance across the ostium
  double domeHeight = 0;    // largest distance of the sac from the neck plane (perpendicular)
  double maxHeight = 0;     // largest distance of the sac from the neck's centre
  double maxDiameter = 0;   // largest distance between two points of the sac (ostium included)
  double width = 0;         // largest extent of the sac parallel to the neck plane
  double depth = 0;         // its extent parallel to the plane, across `width`
  double meanDiameter = 0;  // (domeHeight + width + depth) / 3
  double aspectRatio = 0;   // domeHeight / neckWidth
  double domeToNeck = 0;    // width / neckWidth
  double sizeRatio = 0;     // maxHeight / parent vessel diameter (0 when that is unknown)
  Vec3 neckCentre = Vec3::Zero();  // centroid of the ostium's outline
  size_t triangles = 0;     // of the sac piece
};

// Measures the piece of `mesh` (closed, outward) on the normal side of
// `neck` that holds the surface point nearest `inSac`. `vesselDiameter` <= 0
// leaves the size ratio 0. Returns all zeros when no surface lies on that
// side of the plane. `neckOnly` skips the sac's diameters and heights
// (quadratic in its points), for a caller that moves the plane.
// The sac piece itself, one flag per triangle of `mesh`: the triangles
// reaching the normal side of `neck`, connected there, that hold the one
// nearest `inSac` (all zero when no triangle reaches that side). What
// measureSac measures; the case editor highlights it.
std::vector<char> sacPiece(const TriangleMesh& mesh, const Plane& neck, const Vec3& inSac);

SacMorphology measureSac(const TriangleMesh& mesh, const Plane& neck, const Vec3& inSac, double vesselDiameter,
                         bool neckOnly = false);

}  // namespace coilsim::geometry
