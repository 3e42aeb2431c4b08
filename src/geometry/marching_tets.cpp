#include "geometry/marching_tets.h"

#include <array>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <unordered_map>

namespace coilsim::geometry {
namespace {

// The six tetrahedra of a unit cube sharing the diagonal (0,0,0)-(1,1,1):
// one per order in which the three axes are stepped. Corners as bit masks
// x=1, y=2, z=4.
constexpr std::array<std::array<int, 4>, 6> kTets = {{
    {0, 1, 3, 7}, {0, 1, 5, 7}, {0, 2, 3, 7}, {0, 2, 6, 7}, {0, 4, 5, 7}, {0, 4, 6, 7},
}};

struct Grid {
  long nx, ny, nz;
  long index(long i, long j, long k) const { return (k * ny + j) * nx + i; }
};

}  // namespace

TriangleMesh polygonise(const Field& field, const Vec3& lower, const Vec3& upper, double h, long maxPoints) {
  if (!(h > 0) || !std::isfinite(h)) throw std::invalid_argument("polygonise: spacing must be a finite number > 0");
  if (!((upper - lower).minCoeff() > 0)) throw std::invalid_argument("polygonise: empty box");
  const Vec3 size = upper - lower;
  const Grid g{long(std::ceil(size.x() / h)) + 1, long(std::ceil(size.y() / h)) + 1, long(std::ceil(size.z() / h)) + 1};
  if (double(g.nx) * double(g.ny) * double(g.nz) > double(maxPoints))
    throw std::invalid_argument("polygonise: " + std::to_string(g.nx) + " x " + std::to_string(g.ny) + " x " +
                                std::to_string(g.nz) + " samples exceed the limit of " + std::to_string(maxPoints) +
                                ": use a coarser spacing");
  auto position = [&](long i, long j, long k) { return Vec3(lower + h * Vec3(double(i), double(j), double(k))); };

  std::vector<double> f(size_t(g.nx * g.ny * g.nz));
  // A sample on or next to the surface would put several surface vertices
  // on or next to it: needle triangles of no usable area. Keeping every
  // sample at least h/100 from zero (same side; zero counts as outside)
  // moves the surface by at most h/100 and keeps crossings clear of samples.
  const double nudge = 1e-2 * h;
  for (long k = 0; k < g.nz; ++k)
    for (long j = 0; j < g.ny; ++j)
      for (long i = 0; i < g.nx; ++i) {
        double v = field(position(i, j, k));
        if (!std::isfinite(v)) throw std::invalid_argument("polygonise: the field is not finite");
        if (std::abs(v) < nudge) v = v < 0 ? -nudge : nudge;
        const bool face = i == 0 || j == 0 || k == 0 || i == g.nx - 1 || j == g.ny - 1 || k == g.nz - 1;
        if (face && v < 0) throw std::invalid_argument("polygonise: the solid reaches the sampling box");
        f[g.index(i, j, k)] = v;
      }

  TriangleMesh mesh;
  std::unordered_map<uint64_t, int> edgeVertex;
  // The surface vertex on the grid edge between samples a (inside) and b.
  auto vertexOn = [&](long a, long b, const Vec3& pa, const Vec3& pb) {
    const uint64_t key = a < b ? (uint64_t(a) << 32 | uint64_t(b)) : (uint64_t(b) << 32 | uint64_t(a));
    const auto [it, fresh] = edgeVertex.try_emplace(key, int(mesh.vertices.size()));
    if (fresh) {
      const double t = f[a] / (f[a] - f[b]);
      mesh.vertices.push_back(pa + t * (pb - pa));
    }
    return it->second;
  };
  // Adds triangle abc facing along `out` (from inside to outside).
  auto emit = [&](int a, int b, int c, const Vec3& out) {
    const Vec3 n = (mesh.vertices[b] - mesh.vertices[a]).cross(mesh.vertices[c] - mesh.vertices[a]);
    mesh.triangles.emplace_back(a, n.dot(out) >= 0 ? b : c, n.dot(out) >= 0 ? c : b);
  };

  std::array<long, 8> corner;
  std::array<Vec3, 8> cornerPos;
  for (long k = 0; k + 1 < g.nz; ++k)
    for (long j = 0; j + 1 < g.ny; ++j)
      for (long i = 0; i + 1 < g.nx; ++i) {
        int insideCount = 0;
        for (int c = 0; c < 8; ++c) {
          corner[c] = g.index(i + (c & 1), j + ((c >> 1) & 1), k + ((c >> 2) & 1));
          insideCount += f[corner[c]] < 0;
        }
        if (insideCount == 0 || insideCount == 8) continue;
        for (int c = 0; c < 8; ++c) cornerPos[c] = position(i + (c & 1), j + ((c >> 1) & 1), k + ((c >> 2) & 1));
        for (const auto& tet : kTets) {
          std::array<int, 4> in{}, out{};
          int nin = 0, nout = 0;
          for (int c : tet) (f[corner[c]] < 0 ? in[nin++] : out[nout++]) = c;
          if (nin == 0 || nout == 0) continue;
          auto v = [&](int a, int b) { return vertexOn(corner[a], corner[b], cornerPos[a], cornerPos[b]); };
          Vec3 centreIn = Vec3::Zero(), centreOut = Vec3::Zero();
          for (int q = 0; q < nin; ++q) centreIn += cornerPos[in[q]] / nin;
          for (int q = 0; q < nout; ++q) centreOut += cornerPos[out[q]] / nout;
          // f is linear on the tetrahedron, so its gradient has a positive
          // component along any vector from an inside to an outside corner.
          const Vec3 dir = centreOut - centreIn;
          if (nin == 1) {
            emit(v(in[0], out[0]), v(in[0], out[1]), v(in[0], out[2]), dir);
          } else if (nout == 1) {
            emit(v(in[0], out[0]), v(in[1], out[0]), v(in[2], out[0]), dir);
          } else {
            // A quad whose consecutive corners share a tetrahedron vertex.
            const int a = v(in[0], out[0]), b = v(in[0], out[1]), c = v(in[1], out[1]), d = v(in[1], out[0]);
            emit(a, b, c, dir);
            emit(a, c, d, dir);
          }
        }
      }
  return mesh;
}

}  // namespace coilsim::geometry
