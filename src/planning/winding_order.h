#pragma once
// How ordered a wire packed in a cavity is: the winding order W of its
// centre line about the cavity's centre. Stoop et al. (PRL 106, 214102,
// 2011) call the ordered packing a "coil" (a spool: turns wound the same way
// about one axis) and the other "disordered"; W separates the two:
//
//   w_i = (x_i - c) x (p_{i+1} - p_i)   (x_i the segment's midpoint)
//   J = sum_i w_i,   n = J / |J|,   W = (J . n) / sum_i |w_i . n|
//
// the net winding about the axis n over the winding regardless of sense.
// W is 1 when every segment winds the same way about n (turns of any radii,
// a spool, a planar spiral), 0 when the line winds as much one way as the
// other, and of order 1 / sqrt(N) for an isotropic tangle of N segments.
// Pure geometry, SI or any unit.
#include <vector>

#include "physics/math.h"

namespace coilsim::planning {

struct WindingOrder {
  double order = 0;            // W in [0, 1]
  Vec3 axis = Vec3::UnitZ();   // n, unit (UnitZ when the line has no winding at all)
};

// W of the polyline `points` about `centre`. Fewer than two points, or no
// net winding (|J| at round-off of the terms): order 0.
WindingOrder windingOrder(const std::vector<Vec3>& points, const Vec3& centre);

}  // namespace coilsim::planning
