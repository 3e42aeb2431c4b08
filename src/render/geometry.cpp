#include "render/geometry.h"

#include <algorithm>
#include <cmath>

namespace coilsim::render {
namespace {

void push(TriangleMesh& m, const Vec3& p, const Vec3& n, const Colour& c) {
  Vertex v;
  for (int k = 0; k < 3; ++k) {
    v.position[k] = float(p[k]);
    v.normal[k] = float(n[k]);
  }
  for (int k = 0; k < 4; ++k) v.colour[k] = c[k];
  m.vertices.push_back(v);
}

void tri(TriangleMesh& m, std::uint32_t a, std::uint32_t b, std::uint32_t c) {
  m.indices.insert(m.indices.end(), {a, b, c});
}

// Quads between two rings of `sides` vertices starting at r0 and r1, where
// ring r1 lies further along the axis `t` and the rings run counter-clockwise
// about t: the outward faces are then (r0 j, r1 j+1, r1 j) and (r0 j, r0 j+1, r1 j+1).
void stitch(TriangleMesh& m, std::uint32_t r0, std::uint32_t r1, int sides) {
  for (int j = 0; j < sides; ++j) {
    const std::uint32_t j1 = std::uint32_t((j + 1) % sides);
    tri(m, r0 + j, r1 + j1, r1 + j);
    tri(m, r0 + j, r0 + j1, r1 + j1);
  }
}

// A fan from a pole to a ring, wound outwards; `poleAhead` says whether the pole lies along +t
// from the ring (end cap) or along -t (start cap).
void fan(TriangleMesh& m, std::uint32_t pole, std::uint32_t ring, int sides, bool poleAhead) {
  for (int j = 0; j < sides; ++j) {
    const std::uint32_t j1 = std::uint32_t((j + 1) % sides);
    if (poleAhead)
      tri(m, ring + j, ring + j1, pole);
    else
      tri(m, ring + j, pole, ring + j1);
  }
}

// Uniform Catmull-Rom through the nodes, with `k` extra points per segment
// and colours interpolated linearly; the nodes themselves are kept.
void subdivide(std::vector<Vec3>& centre, std::vector<Colour>& colours, int k) {
  const size_t n = centre.size();
  if (k <= 0 || n < 2) return;
  std::vector<Vec3> c;
  std::vector<Colour> col;
  c.reserve((n - 1) * (k + 1) + 1);
  col.reserve(c.capacity());
  for (size_t i = 0; i + 1 < n; ++i) {
    const Vec3& p1 = centre[i];
    const Vec3& p2 = centre[i + 1];
    const Vec3 p0 = i > 0 ? centre[i - 1] : Vec3(2 * p1 - p2);  // reflected at the ends
    const Vec3 p3 = i + 2 < n ? centre[i + 2] : Vec3(2 * p2 - p1);
    for (int j = 0; j <= k; ++j) {
      const double t = double(j) / (k + 1), t2 = t * t, t3 = t2 * t;
      c.push_back(0.5 * (2 * p1 + (p2 - p0) * t + (2 * p0 - 5 * p1 + 4 * p2 - p3) * t2 + (3 * p1 - p0 - 3 * p2 + p3) * t3));
      col.push_back(colours[i] + float(t) * (colours[i + 1] - colours[i]));
    }
  }
  c.push_back(centre.back());
  col.push_back(colours.back());
  centre.swap(c);
  colours.swap(col);
}

}  // namespace

void tubeFrames(const std::vector<Vec3>& centre, std::vector<Vec3>& tangents, std::vector<Vec3>& normals) {
  const size_t n = centre.size();
  tangents.assign(n, Vec3::UnitX());
  normals.assign(n, Vec3::UnitY());
  if (n < 2) return;
  // Central-difference tangents; repeated nodes borrow their neighbour's.
  Vec3 last = Vec3::UnitX();
  bool found = false;
  for (size_t i = 0; i < n; ++i) {
    const Vec3 d = centre[std::min(i + 1, n - 1)] - centre[i == 0 ? 0 : i - 1];
    const double len = d.norm();
    if (len > 0 && std::isfinite(len)) {
      last = d / len;
      if (!found) std::fill(tangents.begin(), tangents.begin() + i, last);
      found = true;
    }
    tangents[i] = last;
  }
  // Parallel transport: rotate the previous normal by the least rotation
  // taking the previous tangent to this one, then re-orthogonalise.
  normals[0] = anyPerpendicular(tangents[0]);
  for (size_t i = 1; i < n; ++i) {
    const Vec3& a = tangents[i - 1];
    const Vec3& b = tangents[i];
    Vec3 v = normals[i - 1];
    const Vec3 axis = a.cross(b);
    const double s = axis.norm(), c = a.dot(b);
    if (s > 1e-12) v = Eigen::AngleAxisd(std::atan2(s, c), axis / s) * v;
    v -= v.dot(b) * b;
    const double len = v.norm();
    normals[i] = len > 1e-9 ? Vec3(v / len) : anyPerpendicular(b);
  }
}

TubeOptions tubeDetail(const TubeOptions& most, double radiusPixels, double segmentPixels, double toleranceRing,
                       double longestPiece) {
  TubeOptions o = most;
  const int lo = std::min(6, std::max(most.sides, 3));
  if (!(radiusPixels > 0) || !std::isfinite(radiusPixels) || !(toleranceRing > 0)) return o;
  // r (1 - cos(pi / n)) <= tol  <=>  n >= pi / acos(1 - tol / r).
  const double c = 1.0 - toleranceRing / radiusPixels;
  const double needed = c <= -1.0 ? 3.0 : M_PI / std::acos(std::max(c, -1.0));
  o.sides = std::clamp(int(std::ceil(needed - 1e-9)), lo, std::max(most.sides, lo));
  o.capRings = std::clamp(int(std::ceil(radiusPixels / 3.0)), 1, std::max(most.capRings, 1));
  if (segmentPixels > 0 && std::isfinite(segmentPixels) && longestPiece > 0)
    o.subdivisions = std::clamp(int(std::ceil(segmentPixels / longestPiece)) - 1, 0, std::max(most.subdivisions, 0));
  return o;
}

void appendTube(const DrawTube& tube, const TubeOptions& options, TriangleMesh& out) {
  // Only finite nodes take part; a blown-up state must never draw garbage.
  std::vector<Vec3> centre;
  std::vector<Colour> colours;
  const Colour fallback = tube.colours.empty() ? defaultColour(tube.role) : tube.colours.front();
  for (size_t i = 0; i < tube.centre.size(); ++i) {
    if (!tube.centre[i].allFinite()) continue;
    centre.push_back(tube.centre[i]);
    colours.push_back(i < tube.colours.size() && tube.colours[i].allFinite() ? tube.colours[i] : fallback);
  }
  const double r = tube.radius * options.radiusScale;
  const int sides = std::max(options.sides, 3), caps = std::max(options.capRings, 1);
  if (centre.size() < 2 || !(r > 0) || !std::isfinite(r)) return;
  subdivide(centre, colours, options.subdivisions);

  std::vector<Vec3> t, nrm;
  tubeFrames(centre, t, nrm);
  const size_t n = centre.size();
  std::vector<double> cs(sides), sn(sides);
  for (int j = 0; j < sides; ++j) {
    cs[j] = std::cos(2.0 * M_PI * j / sides);
    sn[j] = std::sin(2.0 * M_PI * j / sides);
  }
  // Ring j direction: cos n + sin b with b = t x n, counter-clockwise about t.
  auto ring = [&](const Vec3& c, const Vec3& tt, const Vec3& nn, double radius, double axial, const Colour& col) {
    const Vec3 b = tt.cross(nn);
    const std::uint32_t first = std::uint32_t(out.vertices.size());
    const double ca = std::cos(axial), sa = std::sin(axial);
    for (int j = 0; j < sides; ++j) {
      const Vec3 dir = cs[j] * nn + sn[j] * b;
      push(out, c + radius * dir, ca * dir + sa * tt, col);
    }
    return first;
  };

  // Start cap: from the pole (behind node 0) out to the first full ring.
  const std::uint32_t startPole = std::uint32_t(out.vertices.size());
  push(out, centre[0] - r * t[0], -t[0], colours[0]);
  std::uint32_t prev = 0;
  for (int k = 1; k <= caps; ++k) {
    const double theta = 0.5 * M_PI * (1.0 - double(k) / caps);  // from the pole towards the equator
    const std::uint32_t rk = ring(centre[0] - r * std::sin(theta) * t[0], t[0], nrm[0], r * std::cos(theta), -theta, colours[0]);
    if (k == 1)
      fan(out, startPole, rk, sides, false);
    else
      stitch(out, prev, rk, sides);
    prev = rk;
  }
  // Body: the last cap ring is the ring of node 0.
  for (size_t i = 1; i < n; ++i) {
    const std::uint32_t ri = ring(centre[i], t[i], nrm[i], r, 0.0, colours[i]);
    stitch(out, prev, ri, sides);
    prev = ri;
  }
  // End cap: from the ring of the last node to the pole ahead of it.
  const size_t e = n - 1;
  for (int k = 1; k < caps; ++k) {
    const double theta = 0.5 * M_PI * double(k) / caps;
    const std::uint32_t rk = ring(centre[e] + r * std::sin(theta) * t[e], t[e], nrm[e], r * std::cos(theta), theta, colours[e]);
    stitch(out, prev, rk, sides);
    prev = rk;
  }
  const std::uint32_t endPole = std::uint32_t(out.vertices.size());
  push(out, centre[e] + r * t[e], t[e], colours[e]);
  fan(out, endPole, prev, sides, true);
}

void appendSphere(const Vec3& centre, double radius, const Colour& colour, TriangleMesh& out, int slices, int stacks) {
  if (!centre.allFinite() || !(radius > 0)) return;
  slices = std::max(slices, 3);
  stacks = std::max(stacks, 2);
  const std::uint32_t south = std::uint32_t(out.vertices.size());
  push(out, centre - radius * Vec3::UnitZ(), -Vec3::UnitZ(), colour);
  std::uint32_t prev = 0;
  for (int k = 1; k < stacks; ++k) {
    const double phi = -0.5 * M_PI + M_PI * k / stacks;
    const std::uint32_t first = std::uint32_t(out.vertices.size());
    for (int j = 0; j < slices; ++j) {
      const double a = 2.0 * M_PI * j / slices;
      const Vec3 d(std::cos(phi) * std::cos(a), std::cos(phi) * std::sin(a), std::sin(phi));
      push(out, centre + radius * d, d, colour);
    }
    if (k == 1)
      fan(out, south, first, slices, false);
    else
      stitch(out, prev, first, slices);
    prev = first;
  }
  const std::uint32_t north = std::uint32_t(out.vertices.size());
  push(out, centre + radius * Vec3::UnitZ(), Vec3::UnitZ(), colour);
  fan(out, north, prev, slices, true);
}

void appendArrow(const Vec3& from, const Vec3& vector, double radius, const Colour& colour, TriangleMesh& out,
                 int sides) {
  const double len = vector.norm();
  if (!from.allFinite() || !(len > 0) || !std::isfinite(len) || !(radius > 0)) return;
  sides = std::max(sides, 3);
  const Vec3 t = vector / len, nn = anyPerpendicular(t), b = t.cross(nn);
  const double head = std::min(0.25 * len, 6.0 * radius), headR = std::min(3.0 * radius, 0.5 * head);
  const double shaftR = std::min(radius, headR / 1.5);  // short arrows: keep the head wider than the shaft
  const Vec3 neck = from + (len - head) * t, tip = from + vector;
  auto ringAt = [&](const Vec3& c, double rr, const Vec3& normalAxial, double axialWeight) {
    const std::uint32_t first = std::uint32_t(out.vertices.size());
    for (int j = 0; j < sides; ++j) {
      const double a = 2.0 * M_PI * j / sides;
      const Vec3 dir = std::cos(a) * nn + std::sin(a) * b;
      push(out, c + rr * dir, (dir + axialWeight * normalAxial).normalized(), colour);
    }
    return first;
  };
  // Base disc, shaft, the flat underside of the head, then the cone.
  const std::uint32_t base = std::uint32_t(out.vertices.size());
  push(out, from, -t, colour);
  const std::uint32_t baseRing = ringAt(from, shaftR, -t, 1.0);
  fan(out, base, baseRing, sides, false);
  const std::uint32_t s0 = ringAt(from, shaftR, t, 0.0);
  const std::uint32_t s1 = ringAt(neck, shaftR, t, 0.0);
  stitch(out, s0, s1, sides);
  const std::uint32_t under0 = ringAt(neck, shaftR, -t, 1.0);
  const std::uint32_t under1 = ringAt(neck, headR, -t, 1.0);
  // The underside annulus faces backwards (-t): wind it as a start cap.
  for (int j = 0; j < sides; ++j) {
    const std::uint32_t j1 = std::uint32_t((j + 1) % sides);
    tri(out, under0 + j, under1 + j1, under1 + j);
    tri(out, under0 + j, under0 + j1, under1 + j1);
  }
  const std::uint32_t cone = ringAt(neck, headR, t, headR / std::max(head, 1e-30));
  const std::uint32_t apex = std::uint32_t(out.vertices.size());
  push(out, tip, t, colour);
  fan(out, apex, cone, sides, true);
}

void appendMesh(const DrawMesh& mesh, TriangleMesh& out) {
  const std::uint32_t first = std::uint32_t(out.vertices.size());
  const size_t nv = mesh.vertices.size();
  std::vector<Vec3> normals(nv, Vec3::Zero());
  for (const Eigen::Vector3i& f : mesh.triangles) {
    if ((f.array() < 0).any() || (f.array() >= int(nv)).any()) continue;
    const Vec3 a = mesh.vertices[f[0]], b = mesh.vertices[f[1]], c = mesh.vertices[f[2]];
    const Vec3 w = (b - a).cross(c - a);  // length = twice the area: area weighting
    if (!w.allFinite()) continue;
    for (int k = 0; k < 3; ++k) normals[f[k]] += w;
  }
  for (size_t i = 0; i < nv; ++i) {
    const double len = normals[i].norm();
    push(out, mesh.vertices[i], len > 0 ? Vec3(normals[i] / len) : Vec3::UnitZ(), mesh.colour);
  }
  for (const Eigen::Vector3i& f : mesh.triangles) {
    if ((f.array() < 0).any() || (f.array() >= int(nv)).any()) continue;
    if (!(mesh.vertices[f[0]].allFinite() && mesh.vertices[f[1]].allFinite() && mesh.vertices[f[2]].allFinite())) continue;
    tri(out, first + f[0], first + f[1], first + f[2]);
  }
}

}  // namespace coilsim::render
