#pragma once
// The wall's narrow phase for one segment: the nearest triangle feature of
// an obstacle, from its collision tree (or the segment's cached walk of it),
// with the closest points of the other candidates that the contact built
// from it needs (detect_wall.cpp).
#include <cstddef>

#include "physics/contact/geometry.h"
#include "physics/contact/obstacle_tree.h"
#include "physics/contact/scratch.h"

namespace coilsim {

struct NearestTriangle {
  SegmentTriangle hit;
  int triangle = -1;      // -1: no candidate
  size_t candidate = 0;   // its index in the query's candidates
};

// The nearest triangle feature to segment [a, b] among those whose boxes
// overlap the segment's box grown by `reach`. A triangle whose own box is
// farther from the segment's box, or whose plane and disc (ObstacleTree::
// distanceBound) are farther from the segment, than the best distance found
// so far cannot be nearer and is skipped without the exact query. Leaves in
// `scratch` the candidates, their closest points to the segment (hits, kept
// for the concave-neighbour pass; NaN distance where a triangle was
// skipped) and the square of a lower bound of the distance from any point
// of the segment (boxGap2: the boxes' gap, or the plane and disc's bound
// where that skipped the triangle).
// The result is the first nearest candidate in the tree's order, exactly
// what measuring every candidate gives (tests/physics/contact/
// detect_nearest_test.cpp); a null `triangle` when there is no candidate.
//
// `slackScale` sets the tie slack (1e-9 of it), so that a narrower query of
// the same segment keeps exactly the ties of a wider one. `hint` (a triangle
// that was the segment's nearest before, or -1) only speeds the search: when
// it is among the candidates its distance bounds the pruning from the
// start, and the result is still the first nearest in the candidates' order.
// `cache` (the segment's last walk of the tree, or null) gives the same
// candidates in the same order without a walk while the segment stays
// within it (ObstacleTree::overlapping).
NearestTriangle nearestWallFeature(const ObstacleTree& tree, const Vec3& a, const Vec3& b, double reach,
                                   ContactScratch& scratch, double slackScale, int hint = -1,
                                   TriangleCache* cache = nullptr);

}  // namespace coilsim
