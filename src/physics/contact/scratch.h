#pragma once
// Scratch of contact detection, kept in the State (State::contactScratch)
// rather than in thread-local buffers, so that States stepped in parallel
// (plan candidates, fits) never share it and nothing outlives its run. The
// vectors grow to the largest query and keep their capacity; their
// contents are meaningless between calls.
#include <cstdint>
#include <vector>

#include "physics/contact/contact_state.h"
#include "physics/contact/detect_parallel.h"
#include "physics/contact/geometry.h"

namespace coilsim {

// A segment in the uniform grid of the pair search (detect_rods.cpp).
struct GridSegment {
  std::uint64_t cell = 0;
  int rod = 0, segment = 0;
  Vec3 mid = Vec3::Zero();  // midpoint, m
  double extent = 0;        // half the length + the scaled contact radius + what it sweeps, m
};

// A pair found in contact by one part of a split pair search: segment si
// of rod ki and sj of rod kj, and their closest points (detect_rods.cpp).
struct FoundPair {
  int ki = 0, si = 0, kj = 0, sj = 0;
  SegmentPair p;
};

// What one part of a detection split over threads found, joined in the
// parts' order (detect_parallel.h).
struct DetectionPart {
  std::vector<std::vector<ContactPoint>> wall;  // per rod, in segment order
  std::vector<FoundPair> pairs;                 // in the order visited
};

struct ContactScratch {
  // Wall detection from last step's findings (the clear distances, the
  // nearest triangles) where they give the same contacts faster; false: every
  // segment is queried afresh (the reference the tests and the bench compare
  // against).
  bool coherentWall = true;
  // Wall queries (detect_wall.cpp): the tree traversal, the candidate
  // triangles, the closest points of the segment and of one of its nodes to
  // each candidate, and the squared gap between their boxes.
  std::vector<int> stack, candidates;
  std::vector<SegmentTriangle> hits, nodeHits;
  std::vector<double> boxGap2;
  // Pair queries (detect_rods.cpp): the grid, last step's lists per rod
  // while they are matched, and each segment's largest static move.
  std::vector<GridSegment> grid, fast;  // fast: segments paired directly, not through the grid
  std::vector<std::vector<ContactPoint>> previous;
  std::vector<double> moves;
  // Detection split over a second thread (detect_parallel.h): the thread,
  // and the two parts' findings.
  DetectionThreads threads;
  DetectionPart parts[2];
};

}  // namespace coilsim
