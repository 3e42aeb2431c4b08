// Tube triangles by role, built at the detail their size needs and kept while unchanged.
#include "render/tube_cache.h"

#include <algorithm>
#include <cmath>

namespace coilsim::render {
namespace {

bool sameOptions(const TubeOptions& a, const TubeOptions& b) {
  return a.sides == b.sides && a.capRings == b.capRings && a.radiusScale == b.radiusScale &&
         a.subdivisions == b.subdivisions;
}

bool sameShape(const DrawTube& a, const DrawTube& b) {
  return a.role == b.role && a.radius == b.radius && a.centre == b.centre && a.colours == b.colours;
}

// Mean distance between consecutive finite nodes, m (0 for fewer than two).
double meanSegment(const std::vector<Vec3>& c) {
  double sum = 0;
  int n = 0;
  for (size_t i = 1; i < c.size(); ++i) {
    const double d = (c[i] - c[i - 1]).norm();
    if (std::isfinite(d)) sum += d, ++n;
  }
  return n ? sum / n : 0.0;
}

}  // namespace

int tubeRoleIndex(RodRole role) {
  switch (role) {
    case RodRole::Coil: return 0;
    case RodRole::Catheter: return 1;
    case RodRole::Wire: return 2;
  }
  return 0;
}

void TubeCache::update(const std::vector<DrawTube>& tubes, const TubeOptions& most, const PixelScale& scale,
                       bool reuse) {
  built_ = 0;
  bool roleChanged[kTubeRoles] = {false, false, false};
  // Tubes added or gone change the roles they were in.
  if (entries_.size() != tubes.size()) {
    for (const Entry& e : entries_) roleChanged[tubeRoleIndex(e.source.role)] = true;
    for (const DrawTube& t : tubes) roleChanged[tubeRoleIndex(t.role)] = true;
    entries_.resize(tubes.size());
  }
  for (size_t i = 0; i < tubes.size(); ++i) {
    const DrawTube& t = tubes[i];
    const double perMetre = scale ? scale(t) : 0.0;
    const TubeOptions options =
        perMetre > 0 ? tubeDetail(most, perMetre * t.radius * most.radiusScale, perMetre * meanSegment(t.centre)) : most;
    Entry& e = entries_[i];
    if (reuse && e.built && sameOptions(e.options, options) && sameShape(e.source, t)) continue;
    if (e.source.role != t.role) roleChanged[tubeRoleIndex(e.source.role)] = true;
    e.source.role = t.role;
    e.source.radius = t.radius;
    e.source.centre = t.centre;
    e.source.colours = t.colours;
    e.options = options;
    e.mesh.clear();
    appendTube(t, options, e.mesh);
    e.built = true;
    roleChanged[tubeRoleIndex(t.role)] = true;
    ++built_;
  }
  for (int r = 0; r < kTubeRoles; ++r) {
    changed_[r] = roleChanged[r] || !reuse;
    if (!changed_[r]) continue;
    TriangleMesh& out = roles_[r];
    out.clear();
    for (const Entry& e : entries_) {
      if (tubeRoleIndex(e.source.role) != r) continue;
      const std::uint32_t base = std::uint32_t(out.vertices.size());
      out.vertices.insert(out.vertices.end(), e.mesh.vertices.begin(), e.mesh.vertices.end());
      for (const std::uint32_t k : e.mesh.indices) out.indices.push_back(base + k);
    }
  }
}

}  // namespace coilsim::render
