#pragma once
// Inscribed balls of a closed surface: samples of its medial axis (the
// vessels' centre lines with their radii, the sac's deepest point), and the
// free length of rays cast from inside. Mesh units throughout.
//
// Why the shrinking-ball method (Ma et al., "3D medial axis point
// approximation using nearest neighbors and the normal field", The Visual
// Computer 28, 2012): it needs only closest-point queries, which MeshQuery
// answers through its hierarchy, works on any closed triangle surface
// (phantoms and segmented patient surfaces alike, no voxelisation, no
// Voronoi diagram of the vertices) and gives for a tube the centre line with
// the local radius, for a sac its largest inscribed ball.
#include <vector>

#include "geometry/mesh_query.h"

namespace coilsim::geometry {

struct Ball {
  Vec3 centre = Vec3::Zero();
  double radius = 0;
};

// One maximal inscribed ball per sampled vertex: tangent to the surface
// there (area-weighted normal), grown along the inward normal until it
// touches the surface elsewhere; its radius is then the centre's distance to
// the surface. At most `maxSamples` vertices (evenly strided) are used. Balls
// that do not converge, end up outside or are no wider than a facet are
// left out.
std::vector<Ball> medialBalls(const MeshQuery& query, int maxSamples = 6000);

// Moves `centre` (inside) uphill on the distance to the surface, a pattern
// search with steps from `step` down to 1e-3 `step`: the centre of a locally
// largest inscribed ball. Returns that ball's radius.
double deepestNear(const MeshQuery& query, Vec3& centre, double step);

// Distance from `from` (inside) along the unit `direction` to the surface,
// by sphere tracing on the distance; `reach` when nothing is hit before it.
double freeLength(const MeshQuery& query, const Vec3& from, const Vec3& direction, double reach);

// `count` directions spread evenly over the unit sphere (Fibonacci lattice).
std::vector<Vec3> sphereDirections(int count);

}  // namespace coilsim::geometry
