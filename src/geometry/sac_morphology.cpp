#include "geometry/sac_morphology.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <utility>

namespace coilsim::geometry {
namespace {

// Farthest pair among points (brute force: the sacs have a few thousand).
std::pair<int, int> farthestPair(const std::vector<Vec3>& p) {
  std::pair<int, int> best{0, 0};
  double d2 = -1;
  for (size_t i = 0; i < p.size(); ++i)
    for (size_t j = i + 1; j < p.size(); ++j) {
      const double e = (p[i] - p[j]).squaredNorm();
      if (e > d2) d2 = e, best = {int(i), int(j)};
    }
  return best;
}

}  // namespace

std::vector<char> sacPiece(const TriangleMesh& mesh, const Plane& neck, const Vec3& inSac) {
  const size_t nt = mesh.triangles.size();
  std::vector<double> side(mesh.vertices.size());
  for (size_t v = 0; v < side.size(); ++v) side[v] = neck.side(mesh.vertices[v]);
  // Triangles reaching above the plane, connected through edges that do.
  std::vector<char> above(nt, 0);
  for (size_t t = 0; t < nt; ++t)
    for (int k = 0; k < 3; ++k) above[t] |= side[mesh.triangles[t][k]] > 0;
  std::vector<int> parent(nt);
  std::iota(parent.begin(), parent.end(), 0);
  const auto root = [&](int i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  };
  std::map<std::pair<int, int>, int> edgeOwner;
  for (size_t t = 0; t < nt; ++t) {
    if (!above[t]) continue;
    for (int k = 0; k < 3; ++k) {
      const int a = mesh.triangles[t][k], b = mesh.triangles[t][(k + 1) % 3];
      if (side[a] <= 0 && side[b] <= 0) continue;
      const auto key = std::minmax(a, b);
      const auto [it, fresh] = edgeOwner.emplace(key, int(t));
      if (!fresh) parent[root(int(t))] = root(it->second);
    }
  }
  // The piece nearest the given point.
  int seed = -1;
  double nearest = INFINITY;
  for (size_t t = 0; t < nt; ++t) {
    if (!above[t]) continue;
    const Eigen::Vector3i& f = mesh.triangles[t];
    const double d = ((mesh.vertices[f[0]] + mesh.vertices[f[1]] + mesh.vertices[f[2]]) / 3.0 - inSac).squaredNorm();
    if (d < nearest) nearest = d, seed = int(t);
  }
  std::vector<char> piece(nt, 0);
  if (seed < 0) return piece;
  const int r = root(seed);
  for (size_t t = 0; t < nt; ++t) piece[t] = above[t] && root(int(t)) == r;
  return piece;
}

SacMorphology measureSac(const TriangleMesh& mesh, const Plane& neck, const Vec3& inSac, double vesselDiameter,
                         bool neckOnly) {
  SacMorphology m;
  const size_t nt = mesh.triangles.size();
  std::vector<double> side(mesh.vertices.size());
  for (size_t v = 0; v < side.size(); ++v) side[v] = neck.side(mesh.vertices[v]);
  const std::vector<char> piece = sacPiece(mesh, neck, inSac);
  if (std::find(piece.begin(), piece.end(), char(1)) == piece.end()) return m;

  // Clip each triangle of the piece to the dome side; sum tetrahedra with
  // their apex on the plane (the cap adds nothing), collect the cut edges.
  std::vector<Vec3> points;                     // sac points: vertices above, cut points
  std::vector<std::pair<Vec3, Vec3>> cuts;      // ostium outline, in the clipped polygons' order
  std::vector<char> listed(mesh.vertices.size(), 0);
  double volume = 0;
  for (size_t t = 0; t < nt; ++t) {
    if (!piece[t]) continue;
    ++m.triangles;
    const Eigen::Vector3i& f = mesh.triangles[t];
    std::vector<Vec3> poly;
    int cutStart = -1;
    for (int k = 0; k < 3; ++k) {
      const int a = f[k], b = f[(k + 1) % 3];
      const Vec3 pa = mesh.vertices[a], pb = mesh.vertices[b];
      if (side[a] > 0) {
        poly.push_back(pa);
        if (!listed[a]) listed[a] = 1, points.push_back(pa);
      }
      if ((side[a] > 0) != (side[b] > 0)) {
        const Vec3 x = pa + (side[a] / (side[a] - side[b])) * (pb - pa);
        if (side[a] > 0) cutStart = int(poly.size());  // leaving: the next edge runs on the plane
        poly.push_back(x);
        points.push_back(x);
      }
    }
    for (size_t i = 1; i + 1 < poly.size(); ++i)
      volume += (poly[0] - neck.point).dot((poly[i] - neck.point).cross(poly[i + 1] - neck.point)) / 6.0;
    if (cutStart >= 0) cuts.push_back({poly[size_t(cutStart)], poly[(size_t(cutStart) + 1) % poly.size()]});
  }
  m.volume = volume;
  if (!cuts.empty()) {
    Vec3 c = Vec3::Zero();
    double len = 0;
    for (const auto& [a, b] : cuts) c += 0.5 * (a + b) * (b - a).norm(), len += (b - a).norm();
    m.neckCentre = len > 0 ? Vec3(c / len) : cuts.front().first;
    double area = 0;
    for (const auto& [a, b] : cuts) area += 0.5 * neck.normal.dot((a - m.neckCentre).cross(b - m.neckCentre));
    m.neckArea = std::abs(area);
    std::vector<Vec3> rim;
    for (const auto& [a, b] : cuts) rim.push_back(a);
    const auto [i, j] = farthestPair(rim);
    m.neckWidth = (rim[i] - rim[j]).norm();
  } else {
    m.neckCentre = neck.point;
  }
  if (neckOnly) return m;
  // Heights and diameters over the sac's points.
  for (const Vec3& p : points) {
    m.domeHeight = std::max(m.domeHeight, neck.side(p));
    m.maxHeight = std::max(m.maxHeight, (p - m.neckCentre).norm());
  }
  const auto [i, j] = farthestPair(points);
  m.maxDiameter = (points[i] - points[j]).norm();
  std::vector<Vec3> flat;
  for (const Vec3& p : points) flat.push_back(p - neck.side(p) * neck.normal);
  const auto [u0, u1] = farthestPair(flat);
  m.width = (flat[u0] - flat[u1]).norm();
  if (m.width > 0) {
    const Vec3 v = neck.normal.cross((flat[u1] - flat[u0]).normalized());
    double lo = INFINITY, hi = -INFINITY;
    for (const Vec3& p : flat) lo = std::min(lo, v.dot(p)), hi = std::max(hi, v.dot(p));
    m.depth = hi - lo;
  }
  m.meanDiameter = (m.domeHeight + m.width + m.depth) / 3;
  if (m.neckWidth > 0) m.aspectRatio = m.domeHeight / m.neckWidth, m.domeToNeck = m.width / m.neckWidth;
  if (vesselDiameter > 0) m.sizeRatio = m.maxHeight / vesselDiameter;
  return m;
}

}  // namespace coilsim::geometry
