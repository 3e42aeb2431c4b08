#include "geometry/medial_balls.h"

#include <algorithm>
#include <cmath>

namespace coilsim::geometry {
namespace {

constexpr double kSlack = 0.05;  // of a ball's radius (about 18 degrees of tilt)

}  // namespace

std::vector<Ball> medialBalls(const MeshQuery& query, int maxSamples) {
  const TriangleMesh& mesh = query.mesh();
  std::vector<Ball> balls;
  const int nv = int(mesh.vertices.size());
  if (nv == 0 || mesh.triangles.empty()) return balls;
  // Area-weighted vertex normals (outward), and the longest edge at each vertex.
  std::vector<Vec3> normal(size_t(nv), Vec3::Zero());
  std::vector<double> reach(size_t(nv), 0.0);
  for (const Eigen::Vector3i& f : mesh.triangles) {
    const Vec3 a = mesh.vertices[f[0]], b = mesh.vertices[f[1]], c = mesh.vertices[f[2]];
    const Vec3 area = (b - a).cross(c - a);
    const double longest = std::max({(b - a).norm(), (c - b).norm(), (a - c).norm()});
    for (int k = 0; k < 3; ++k) normal[f[k]] += area, reach[f[k]] = std::max(reach[f[k]], longest);
  }
  Eigen::AlignedBox3d box;
  for (const Vec3& v : mesh.vertices) box.extend(v);
  const double start = box.diagonal().norm();
  const int stride = std::max(1, (nv + maxSamples - 1) / std::max(1, maxSamples));
  balls.reserve(size_t(nv / stride + 1));
  for (int v = 0; v < nv; v += stride) {
    if (!(normal[v].norm() > 0)) continue;
    const Vec3 inward = -normal[v].normalized();  // outward surfaces: the lumen is behind the normal
    const Vec3 p = mesh.vertices[v];
    // Shrink: the ball tangent at p through the nearest surface point q has
    // radius |p - q|^2 / (2 n.(q - p)). A ball is empty when the nearest
    // point to its centre is within kSlack of its radius or in p's own
    // neighbourhood (within its longest edge: a faceted surface grazes a
    // tangent ball there). The slack forgives a normal a few degrees off:
    // tangent at p along a normal tilted by b, no ball wider than about
    // r (1 - b^2 / 2) is empty in a tube of radius r. The
    // step can undershoot, and the balls tangent at p are nested, so the
    // largest empty one is then found by bisection.
    const auto empty = [&](double radius) {
      const ClosestPoint q = query.closest(p + radius * inward);
      return q.distance >= radius * (1 - kSlack) || (q.point - p).norm() <= 1.5 * reach[v];
    };
    double r = start, full = start;
    bool converged = false;
    for (int it = 0; it < 60; ++it) {
      const ClosestPoint q = query.closest(p + r * inward);
      const Vec3 pq = q.point - p;
      if (q.distance >= r * (1 - kSlack) || pq.norm() <= 1.5 * reach[v]) {
        converged = true;
        break;
      }
      full = r;
      const double along = inward.dot(pq);
      const double next = along > 1e-12 ? pq.squaredNorm() / (2 * along) : 0.5 * r;
      r = next < r ? next : 0.5 * r;
    }
    if (!converged) continue;
    for (int it = 0; it < 14 && full - r > 1e-3 * r; ++it) {
      const double mid = 0.5 * (r + full);
      (empty(mid) ? r : full) = mid;
    }
    if (!(r > reach[v])) continue;  // balls no wider than a facet are noise
    const Vec3 centre = p + r * inward;
    if (!query.inside(centre)) continue;
    balls.push_back({centre, query.closest(centre).distance});
  }
  return balls;
}

double deepestNear(const MeshQuery& query, Vec3& centre, double step) {
  double best = query.closest(centre).distance;
  const Vec3 dirs[6] = {Vec3::UnitX(), -Vec3::UnitX(), Vec3::UnitY(), -Vec3::UnitY(), Vec3::UnitZ(), -Vec3::UnitZ()};
  for (double h = step; h > 1e-3 * step; h *= 0.5) {
    bool moved = true;
    for (int guard = 0; moved && guard < 200; ++guard) {
      moved = false;
      for (const Vec3& d : dirs) {
        const Vec3 x = centre + h * d;
        const double r = query.closest(x).distance;
        if (r > best && query.inside(x)) {
          best = r, centre = x, moved = true;
        }
      }
    }
  }
  return best;
}

double freeLength(const MeshQuery& query, const Vec3& from, const Vec3& direction, double reach) {
  double t = 0;
  const double eps = 1e-4 * reach;
  for (int it = 0; it < 400 && t < reach; ++it) {
    const double d = query.closest(from + t * direction).distance;
    if (d < eps) return t;
    t += d;
  }
  return std::min(t, reach);
}

std::vector<Vec3> sphereDirections(int count) {
  std::vector<Vec3> dirs;
  dirs.reserve(size_t(std::max(count, 0)));
  const double golden = M_PI * (3 - std::sqrt(5.0));
  for (int i = 0; i < count; ++i) {
    const double z = 1 - (2 * i + 1.0) / count, s = std::sqrt(std::max(0.0, 1 - z * z));
    dirs.emplace_back(s * std::cos(golden * i), s * std::sin(golden * i), z);
  }
  return dirs;
}

}  // namespace coilsim::geometry
