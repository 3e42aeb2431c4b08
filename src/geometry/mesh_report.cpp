#include "geometry/mesh_report.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <numeric>
#include <unordered_map>

namespace coilsim::geometry {
namespace {

// A directed edge a->b of triangle `tri`, grouped by its undirected key.
struct HalfEdge {
  uint64_t key;
  int a, b, tri;
};

uint64_t edgeKey(int a, int b) {
  const auto lo = uint64_t(std::min(a, b)), hi = uint64_t(std::max(a, b));
  return (lo << 32) | hi;
}

bool validTriangle(const TriangleMesh& m, const Eigen::Vector3i& t) {
  const int n = int(m.vertices.size());
  for (int k = 0; k < 3; ++k)
    if (t[k] < 0 || t[k] >= n) return false;
  return t[0] != t[1] && t[1] != t[2] && t[0] != t[2];
}

// Below this squared area (relative to the squared bounds diagonal) a
// triangle has no usable normal.
double degenerateArea2(const MeshReport& r) {
  const double d2 = (r.upper - r.lower).squaredNorm();
  return 1e-24 * d2 * d2;
}

std::vector<HalfEdge> halfEdges(const TriangleMesh& m, const std::vector<char>& skip) {
  std::vector<HalfEdge> h;
  h.reserve(3 * m.triangles.size());
  for (size_t t = 0; t < m.triangles.size(); ++t) {
    if (skip[t]) continue;
    const Eigen::Vector3i& f = m.triangles[t];
    for (int k = 0; k < 3; ++k) h.push_back({edgeKey(f[k], f[(k + 1) % 3]), f[k], f[(k + 1) % 3], int(t)});
  }
  std::sort(h.begin(), h.end(), [](const HalfEdge& x, const HalfEdge& y) {
    return x.key != y.key ? x.key < y.key : x.tri < y.tri;
  });
  return h;
}

int findRoot(std::vector<int>& parent, int i) {
  while (parent[i] != i) i = parent[i] = parent[parent[i]];
  return i;
}

}  // namespace

MeshReport analyseMesh(const TriangleMesh& m) {
  MeshReport r;
  r.vertices = m.vertices.size();
  r.triangles = m.triangles.size();
  if (!m.vertices.empty()) {
    r.lower = r.upper = m.vertices.front();
    for (const Vec3& v : m.vertices) r.lower = r.lower.cwiseMin(v), r.upper = r.upper.cwiseMax(v);
  }
  const double tiny = degenerateArea2(r);
  std::vector<char> skip(m.triangles.size(), 0);
  std::vector<char> used(m.vertices.size(), 0);
  for (size_t t = 0; t < m.triangles.size(); ++t) {
    const Eigen::Vector3i& f = m.triangles[t];
    if (!validTriangle(m, f)) {
      skip[t] = 1, ++r.degenerateTriangles;
      continue;
    }
    const Vec3 &a = m.vertices[f[0]], &b = m.vertices[f[1]], &c = m.vertices[f[2]];
    if ((b - a).cross(c - a).squaredNorm() <= tiny) ++r.degenerateTriangles;
    for (int k = 0; k < 3; ++k) used[f[k]] = 1;
    // Tetrahedra from the origin: their signed volumes sum to the enclosed one.
    r.volume += a.dot(b.cross(c)) / 6.0;
  }
  r.unusedVertices = size_t(std::count(used.begin(), used.end(), 0));

  const std::vector<HalfEdge> h = halfEdges(m, skip);
  std::vector<int> parent(m.triangles.size());
  std::iota(parent.begin(), parent.end(), 0);
  for (size_t i = 0; i < h.size();) {
    size_t j = i;
    while (j < h.size() && h[j].key == h[i].key) ++j;
    ++r.edges;
    const size_t uses = j - i;
    if (uses == 1) ++r.boundaryEdges;
    else if (uses > 2) ++r.nonManifoldEdges;
    else if (h[i].a == h[i + 1].a) ++r.misorientedEdges;
    for (size_t k = i + 1; k < j; ++k) parent[findRoot(parent, h[k].tri)] = findRoot(parent, h[i].tri);
    i = j;
  }
  for (size_t t = 0; t < m.triangles.size(); ++t)
    if (!skip[t] && findRoot(parent, int(t)) == int(t)) ++r.components;
  return r;
}

std::vector<std::string> describeProblems(const MeshReport& r) {
  std::vector<std::string> out;
  auto add = [&](size_t n, const char* what) {
    if (n) out.push_back(std::to_string(n) + " " + what);
  };
  if (r.triangles == 0) out.push_back("no triangles");
  add(r.boundaryEdges, "boundary edges (holes: the surface is open)");
  add(r.nonManifoldEdges, "non-manifold edges (shared by three or more triangles)");
  add(r.misorientedEdges, "edges whose two triangles are oriented inconsistently");
  add(r.degenerateTriangles, "degenerate triangles (repeated vertex or zero area)");
  if (r.closed() && r.oriented() && !(r.volume > 0))
    out.push_back("normals point inward (negative enclosed volume)");
  return out;
}

namespace {

// Maps every vertex to its representative: the first vertex within `tol`.
std::vector<int> weldMap(const std::vector<Vec3>& v, double tol) {
  std::vector<int> rep(v.size());
  if (tol <= 0) {
    std::map<std::array<double, 3>, int> seen;
    for (size_t i = 0; i < v.size(); ++i)
      rep[i] = seen.try_emplace({v[i].x(), v[i].y(), v[i].z()}, int(i)).first->second;
    return rep;
  }
  // Grid of cells of size tol: a close neighbour is in one of the 27 cells around.
  auto cell = [&](const Vec3& p) {
    return Eigen::Vector3<int64_t>(int64_t(std::floor(p.x() / tol)), int64_t(std::floor(p.y() / tol)),
                                   int64_t(std::floor(p.z() / tol)));
  };
  auto hash = [](const Eigen::Vector3<int64_t>& c) {
    return uint64_t(c.x()) * 73856093u ^ uint64_t(c.y()) * 19349663u ^ uint64_t(c.z()) * 83492791u;
  };
  std::unordered_multimap<uint64_t, int> grid;
  for (size_t i = 0; i < v.size(); ++i) {
    const auto c = cell(v[i]);
    rep[i] = int(i);
    bool found = false;
    for (int dx = -1; dx <= 1 && !found; ++dx)
      for (int dy = -1; dy <= 1 && !found; ++dy)
        for (int dz = -1; dz <= 1 && !found; ++dz) {
          const auto range = grid.equal_range(hash(c + Eigen::Vector3<int64_t>(dx, dy, dz)));
          for (auto it = range.first; it != range.second; ++it)
            if ((v[it->second] - v[i]).norm() <= tol) {
              rep[i] = it->second, found = true;
              break;
            }
        }
    if (!found) grid.emplace(hash(c), int(i));
  }
  return rep;
}

}  // namespace

TriangleMesh weldVertices(const TriangleMesh& in, double tolerance) {
  const std::vector<int> rep = weldMap(in.vertices, tolerance);
  TriangleMesh out;
  out.name = in.name;
  std::vector<int> newIndex(in.vertices.size(), -1);
  for (size_t i = 0; i < rep.size(); ++i)
    if (rep[i] == int(i)) newIndex[i] = int(out.vertices.size()), out.vertices.push_back(in.vertices[i]);
  out.triangles.reserve(in.triangles.size());
  for (const Eigen::Vector3i& f : in.triangles) {
    Eigen::Vector3i g;
    for (int k = 0; k < 3; ++k) g[k] = f[k] >= 0 && f[k] < int(rep.size()) ? newIndex[rep[f[k]]] : -1;
    out.triangles.push_back(g);
  }
  return out;
}

RepairResult repairMesh(const TriangleMesh& in, double weldTolerance) {
  RepairResult out;
  out.mesh.name = in.name;
  const MeshReport before = analyseMesh(in);
  const double tiny = degenerateArea2(before);

  // Weld, then keep only triangles with three distinct vertices and an area.
  const std::vector<int> rep = weldMap(in.vertices, weldTolerance);
  std::vector<int> newIndex(in.vertices.size(), -1);
  size_t welded = 0, dropped = 0;
  for (size_t i = 0; i < rep.size(); ++i) welded += rep[i] != int(i);
  for (const Eigen::Vector3i& f0 : in.triangles) {
    if (!validTriangle(in, f0)) {
      ++dropped;
      continue;
    }
    Eigen::Vector3i f(rep[f0[0]], rep[f0[1]], rep[f0[2]]);
    const Vec3 &a = in.vertices[f[0]], &b = in.vertices[f[1]], &c = in.vertices[f[2]];
    if (f[0] == f[1] || f[1] == f[2] || f[0] == f[2] || (b - a).cross(c - a).squaredNorm() <= tiny) {
      ++dropped;
      continue;
    }
    for (int k = 0; k < 3; ++k) {
      if (newIndex[f[k]] < 0) {
        newIndex[f[k]] = int(out.mesh.vertices.size());
        out.mesh.vertices.push_back(in.vertices[f[k]]);
      }
      f[k] = newIndex[f[k]];
    }
    out.mesh.triangles.push_back(f);
  }
  if (welded) out.actions.push_back("welded " + std::to_string(welded) + " duplicate vertices");
  if (dropped) out.actions.push_back("dropped " + std::to_string(dropped) + " degenerate triangles");
  const size_t unused = in.vertices.size() - welded - out.mesh.vertices.size();
  if (unused) out.actions.push_back("removed " + std::to_string(unused) + " unused vertices");

  MeshReport r = analyseMesh(out.mesh);
  if (!r.closed()) {
    out.report = r;
    out.reason = r.triangles == 0 ? "no triangles"
                 : r.nonManifoldEdges
                     ? std::to_string(r.nonManifoldEdges) + " non-manifold edges (shared by three or more triangles)"
                     : std::to_string(r.boundaryEdges) + " boundary edges: the surface has holes and is not closed";
    return out;
  }

  // Orient each component from its first triangle: across a shared edge the
  // neighbour must run the edge the other way.
  TriangleMesh& m = out.mesh;
  const std::vector<HalfEdge> h = halfEdges(m, std::vector<char>(m.triangles.size(), 0));
  std::vector<std::array<std::pair<int, bool>, 3>> adjacency(m.triangles.size());  // (neighbour, same direction)
  std::vector<int> filled(m.triangles.size(), 0);
  for (size_t i = 0; i + 1 < h.size(); i += 2) {
    const bool same = h[i].a == h[i + 1].a;
    adjacency[h[i].tri][filled[h[i].tri]++] = {h[i + 1].tri, same};
    adjacency[h[i + 1].tri][filled[h[i + 1].tri]++] = {h[i].tri, same};
  }
  std::vector<int> flip(m.triangles.size(), -1), component(m.triangles.size(), -1);
  std::vector<double> componentVolume;
  std::vector<int> stack;
  size_t reoriented = 0;
  for (size_t seed = 0; seed < m.triangles.size(); ++seed) {
    if (flip[seed] >= 0) continue;
    const int c = int(componentVolume.size());
    componentVolume.push_back(0);
    flip[seed] = 0, component[seed] = c;
    stack.assign(1, int(seed));
    while (!stack.empty()) {
      const int t = stack.back();
      stack.pop_back();
      for (const auto& [n, same] : adjacency[t]) {
        const int want = flip[t] ^ int(same);
        if (flip[n] < 0) {
          flip[n] = want, component[n] = c;
          stack.push_back(n);
        } else if (flip[n] != want) {
          out.report = r;
          out.reason = "the surface is not orientable (a Moebius-like band): inside and outside cannot be told";
          return out;
        }
      }
    }
  }
  for (size_t t = 0; t < m.triangles.size(); ++t) {
    if (flip[t]) std::swap(m.triangles[t][1], m.triangles[t][2]), ++reoriented;
    const Eigen::Vector3i& f = m.triangles[t];
    componentVolume[component[t]] += m.vertices[f[0]].dot(m.vertices[f[1]].cross(m.vertices[f[2]])) / 6.0;
  }
  if (reoriented) out.actions.push_back("re-oriented " + std::to_string(reoriented) + " triangles consistently");
  // A component enclosing a negative volume is inside out (nested cavities are not aneurysm walls).
  size_t turned = 0;
  for (size_t t = 0; t < m.triangles.size(); ++t)
    if (componentVolume[component[t]] < 0) std::swap(m.triangles[t][1], m.triangles[t][2]), ++turned;
  if (turned) out.actions.push_back("flipped " + std::to_string(turned) + " triangles of inward-facing components");

  out.report = analyseMesh(m);
  out.usable = out.report.usable();
  if (!out.usable) {
    const auto problems = describeProblems(out.report);
    out.reason = problems.empty() ? "unusable" : problems.front();
  }
  return out;
}

}  // namespace coilsim::geometry
