#include "physics/contact/detect_nearest.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace coilsim {
namespace {

// How much larger than a query the box of a segment's cached tree walk is
// (m): a segment on the wall moves about 10 um a step at a 10 mm/s push, so
// the tree is walked again every ten steps or more, and the cached list is
// about a third longer than the query's.
constexpr double kCacheSlack = 0.1e-3;

// Squared distance between two axis-aligned boxes (0 when they overlap).
double boxDistance2(const Vec3& lo1, const Vec3& hi1, const Vec3& lo2, const Vec3& hi2) {
  const Vec3 gap = (lo2 - hi1).cwiseMax(lo1 - hi2).cwiseMax(0.0);
  return gap.squaredNorm();
}

}  // namespace

NearestTriangle nearestWallFeature(const ObstacleTree& tree, const Vec3& a, const Vec3& b, double reach,
                                   ContactScratch& scratch, double slackScale, int hint, TriangleCache* cache) {
  std::vector<int>& candidates = scratch.candidates;
  std::vector<SegmentTriangle>& hits = scratch.hits;
  std::vector<double>& boxGap2 = scratch.boxGap2;
  const Vec3 grow = Vec3::Constant(reach);
  const Vec3 lo = a.cwiseMin(b), hi = a.cwiseMax(b);
  candidates.clear();
  if (cache)
    tree.overlapping(lo - grow, hi + grow, kCacheSlack, *cache, scratch.stack, candidates);
  else
    tree.overlapping(lo - grow, hi + grow, scratch.stack, candidates);
  hits.resize(candidates.size());
  boxGap2.resize(candidates.size());
  const TriangleMesh& m = tree.mesh();
  // An upper bound of the nearest candidate's distance, from the hint.
  double known = INFINITY;
  size_t hintAt = candidates.size();
  if (hint >= 0) {
    hintAt = size_t(std::find(candidates.begin(), candidates.end(), hint) - candidates.begin());
    if (hintAt < candidates.size()) {
      const Eigen::Vector3i& f = m.triangles[hint];
      hits[hintAt] = closestSegmentTriangle(a, b, m.vertices[f[0]], m.vertices[f[1]], m.vertices[f[2]]);
      known = hits[hintAt].distance;
    }
  }
  NearestTriangle best;
  for (size_t k = 0; k < candidates.size(); ++k) {
    const Eigen::Vector3i& f = m.triangles[candidates[k]];
    const Vec3 &p = m.vertices[f[0]], &q = m.vertices[f[1]], &r = m.vertices[f[2]];
    // (With a little slack: a triangle sharing the nearest feature must
    // not be lost to round-off, pseudoNormal needs it.)
    const double bound = (best.triangle >= 0 ? std::min(best.hit.distance, known) : known) + 1e-9 * slackScale;
    boxGap2[k] = boxDistance2(lo, hi, p.cwiseMin(q).cwiseMin(r), p.cwiseMax(q).cwiseMax(r));
    if (best.triangle >= 0 || known < INFINITY) {
      // Two lower bounds of the distance, the boxes' and the triangle's
      // plane and disc's (which also prunes under a segment lying over the
      // wall); the larger is kept for the passes that read boxGap2.
      bool far = boxGap2[k] > bound * bound;
      if (!far) {
        const double lower = tree.distanceBound(candidates[k], a, b);
        if (lower > bound) far = true, boxGap2[k] = std::max(boxGap2[k], lower * lower);
      }
      if (far) {
        hits[k].distance = std::numeric_limits<double>::quiet_NaN();
        continue;
      }
    }
    if (k != hintAt) hits[k] = closestSegmentTriangle(a, b, p, q, r);
    if (best.triangle < 0 || hits[k].distance < best.hit.distance) best = {hits[k], candidates[k], k};
  }
  return best;
}


}  // namespace coilsim
