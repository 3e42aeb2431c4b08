// Packing density, neck coverage, protrusion, occlusion class, wall-force statistics.
#include "planning/metrics.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace coilsim::planning {

CoilLines coilLines(const Model& model, const State& state, int chainRod, int skipNodes) {
  CoilLines out;
  for (size_t r = 0; r < model.rods.size(); ++r) {
    const RodState& rs = state.rods[r];
    if (model.rods[r].role != RodRole::Coil || !rs.active) continue;
    const int first = int(r) == chainRod ? skipNodes : 0;
    if (rs.activeNodes - first < 2) continue;
    out.lines.emplace_back(rs.x.begin() + first, rs.x.begin() + rs.activeNodes);
    out.radius = std::max(out.radius, model.rods[r].section.radius);
    out.radii.push_back(model.rods[r].section.radius);
  }
  return out;
}

NeckGrid sampleNeck(const Sac& sac, int resolution) {
  NeckGrid g;
  const Vec3 n = sac.neck.normal.normalized();
  g.u = n.unitOrthogonal();
  g.v = n.cross(g.u);
  // Bounding box, in plane coordinates, of where the surface's edges cross the plane.
  double lo[2] = {std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
  double hi[2] = {-lo[0], -lo[1]};
  const TriangleMesh& m = *sac.mesh;
  for (const auto& t : m.triangles)
    for (int i = 0; i < 3; ++i) {
      const Vec3 &a = m.vertices[t[i]], &b = m.vertices[t[(i + 1) % 3]];
      const double sa = sac.neck.signedDistance(a), sb = sac.neck.signedDistance(b);
      if ((sa < 0) == (sb < 0)) continue;
      const Vec3 p = a + (sa / (sa - sb)) * (b - a) - sac.neck.point;
      const double c[2] = {p.dot(g.u), p.dot(g.v)};
      for (int k = 0; k < 2; ++k) lo[k] = std::min(lo[k], c[k]), hi[k] = std::max(hi[k], c[k]);
    }
  if (!(hi[0] > lo[0]) || !(hi[1] > lo[1])) return g;
  const double h = std::max(hi[0] - lo[0], hi[1] - lo[1]) / resolution;
  const int nu = int(std::ceil((hi[0] - lo[0]) / h)), nv = int(std::ceil((hi[1] - lo[1]) / h));
  auto centre = [&](int i, int j) {
    return Vec3(sac.neck.point + (lo[0] + (i + 0.5) * h) * g.u + (lo[1] + (j + 0.5) * h) * g.v);
  };
  std::vector<char> inside(size_t(nu) * nv, 0), reached(size_t(nu) * nv, 0);
  int seed = -1;
  double best = std::numeric_limits<double>::infinity();
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j) {
      const Vec3 c = centre(i, j);
      if (!(inside[size_t(i) * nv + j] = sac.query->inside(c))) continue;
      const double d = (c - sac.neck.point).squaredNorm();
      if (d < best) best = d, seed = i * nv + j;
    }
  if (seed < 0) return g;
  // Flood fill: the neck is the interior region around the plane's point.
  std::vector<int> stack{seed};
  reached[size_t(seed)] = 1;
  while (!stack.empty()) {
    const int k = stack.back();
    stack.pop_back();
    const int i = k / nv, j = k % nv;
    g.cells.push_back(centre(i, j));
    const int nb[4][2] = {{i - 1, j}, {i + 1, j}, {i, j - 1}, {i, j + 1}};
    for (const auto& q : nb) {
      if (q[0] < 0 || q[0] >= nu || q[1] < 0 || q[1] >= nv) continue;
      const int kk = q[0] * nv + q[1];
      if (inside[size_t(kk)] && !reached[size_t(kk)]) reached[size_t(kk)] = 1, stack.push_back(kk);
    }
  }
  g.cellArea = h * h;
  return g;
}

namespace {

// Distance from p to segment a-b.
double pointSegment(const Vec3& p, const Vec3& a, const Vec3& b) {
  const Vec3 d = b - a;
  const double l2 = d.squaredNorm();
  const double t = l2 > 0 ? std::clamp((p - a).dot(d) / l2, 0.0, 1.0) : 0.0;
  return (a + t * d - p).norm();
}

}  // namespace

SacMetrics measureSac(const Sac& sac, double sacVolume, const NeckGrid& neck, const CoilLines& coil,
                      const MetricOptions& options) {
  SacMetrics s;
  s.sacVolume = sacVolume;
  // Pieces of coil near the neck, projected onto the plane, with their radius, for coverage.
  struct Piece {
    Vec3 p, q;
    double r;
  };
  std::vector<Piece> nearNeck;
  for (size_t k = 0; k < coil.lines.size(); ++k) {
    const auto& line = coil.lines[k];
    const double r = coil.radiusOf(k);
    for (size_t i = 0; i + 1 < line.size(); ++i) {
      const Vec3 &a = line[i], &b = line[i + 1];
      const double inSac = lengthInSac(sac, a, b);
      s.coilLengthInSac += inSac;
      s.coilVolume += M_PI * r * r * inSac;
      s.protrudingLength += lengthBeyondNeck(sac, a, b);
      const double da = sac.neck.signedDistance(a), db = sac.neck.signedDistance(b);
      for (const double d : {da, db})
        if (d < 0) s.maxProtrusionDepth = std::max(s.maxProtrusionDepth, -d);
      // Clip to the band [-r, band] above the plane, then project.
      const double lo = -r, hi = options.coverageBand;
      double t0 = 0, t1 = 1;
      const double dd = db - da;
      if (dd == 0) {
        if (da < lo || da > hi) continue;
      } else {
        double ta = (lo - da) / dd, tb = (hi - da) / dd;
        if (ta > tb) std::swap(ta, tb);
        t0 = std::max(t0, ta), t1 = std::min(t1, tb);
        if (t0 > t1) continue;
      }
      const Vec3 n = sac.neck.normal;
      Vec3 p = a + t0 * (b - a), q = a + t1 * (b - a);
      p -= sac.neck.signedDistance(p) * n;
      q -= sac.neck.signedDistance(q) * n;
      nearNeck.push_back({p, q, r});
    }
  }
  // Depth only counts where the coil is in the vessel, not outside the surface.
  if (s.protrudingLength == 0) s.maxProtrusionDepth = 0;
  s.packingDensity = sacVolume > 0 ? s.coilVolume / sacVolume : 0.0;
  s.protruding = s.protrudingLength > options.protrusionLength;
  if (!neck.cells.empty()) {
    long covered = 0;
    for (const Vec3& c : neck.cells)
      for (const Piece& piece : nearNeck)
        if (pointSegment(c, piece.p, piece.q) <= piece.r) {
          ++covered;
          break;
        }
    s.neckCoverage = double(covered) / double(neck.cells.size());
  }
  return s;
}

int occlusionClass(double packing, double coverage) {
  if (packing >= 0.24) return coverage >= 0.5 ? 1 : 2;
  return packing >= 0.20 ? 2 : 3;
}

std::string occlusionClassName(int cls) {
  switch (cls) {
    case 1: return "I (complete occlusion)";
    case 2: return "II (residual neck)";
    default: return "III (residual aneurysm)";
  }
}

void WallForceStats::add(const State& state, double dt, double threshold) {
  const WallLoad& load = state.stats.wallLoad;
  if (load.now > 0) sum += load.now, ++samples;
  max = std::max(max, load.max);
  peak = std::max(peak, load.peak);
  if (load.now > threshold) timeAbove += dt;
}

}  // namespace coilsim::planning
