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

// A pair of segments the pair search keeps as a candidate: segment si of
// rod ki and sj of rod kj, i before j.
struct CandidatePair {
  int ki = 0, si = 0, kj = 0, sj = 0;
};

// The pair search's candidates kept from step to step (a Verlet list,
// detect_rods.cpp): every pair that the grid found within the two
// segments' reaches plus the margin plus `skin` when it was built. While
// no segment's midpoint has moved, plus its reach grown, by more than half
// the skin since, and the same rods are searched with the same nodes, every
// pair the grid would find now is among them, so a step visits these
// instead of sorting and walking the grid again.
struct PairCandidates {
  bool valid = false;
  double margin = 0, radiusScale = 0, skin = 0;
  std::vector<CandidatePair> pairs;
  std::vector<CandidatePair> found[2];  // each part's, while building
  // Per rod when built: its first segment in `mid`/`extent`, its active
  // nodes (0: not searched) and whether it slept.
  std::vector<int> first, nodes;
  std::vector<char> asleep;
  std::vector<Vec3> mid;        // per segment: midpoint when built, m
  std::vector<double> extent;   // per segment: reach when built, m
  std::vector<Vec3> midNow;     // the same now (scratch of the check)
  std::vector<double> extentNow;
  long builds = 0, reuses = 0;  // how often it was built and used (bench)
};

struct ContactScratch {
  // Wall detection from last step's findings (the clear distances, the
  // nearest triangles) where they give the same contacts faster; false: every
  // segment is queried afresh (the reference the tests and the bench compare
  // against).
  bool coherentWall = true;
  // The pair search's candidates kept from step to step (PairCandidates)
  // where they still hold; false: the grid is searched afresh every time
  // (the reference the tests and the bench compare against).
  bool keepPairCandidates = true;
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
  // The self-contact search's and the between-rods search's candidates.
  PairCandidates selfCandidates, rodCandidates;
  // Detection split over a second thread (detect_parallel.h): the thread,
  // and the two parts' findings.
  DetectionThreads threads;
  DetectionPart parts[2];
};

}  // namespace coilsim
