#include "render/xray_look.h"

#include <algorithm>
#include <cmath>

namespace coilsim::render {
namespace {

struct MeshChord {
  double chord = 0, volume = 0;  // m, m^3
  bool closed = false;
};

// Volume over area projected along `dir` (unit): the mean chord. A surface
// that encloses contrast (each ray enters and leaves it) has no net vector
// area; an open disc (a neck plane) has all of its area as one: a mesh
// whose vector area is more than 5 % of its area holds no contrast.
MeshChord meanChord(const DrawMesh& m, const Vec3& dir) {
  MeshChord out;
  double projected = 0, area = 0;
  Vec3 vectorArea = Vec3::Zero();
  for (const Eigen::Vector3i& t : m.triangles) {
    const Vec3 &a = m.vertices[size_t(t[0])], &b = m.vertices[size_t(t[1])], &c = m.vertices[size_t(t[2])];
    const Vec3 n = 0.5 * (b - a).cross(c - a);
    out.volume += a.dot(b.cross(c)) / 6.0;
    // Each ray through a convex surface crosses it twice: half the sum of |n.d| dA.
    projected += 0.5 * std::abs(n.dot(dir));
    area += n.norm();
    vectorArea += n;
  }
  out.volume = std::abs(out.volume);
  out.closed = area > 0 && vectorArea.norm() <= 0.05 * area;
  out.chord = projected > 0 ? out.volume / projected : 0.0;
  return out;
}

// The mean grey across a tube of radius r and attenuation mu: the midpoint
// rule over the offset y from its axis, 64 strips.
float tubeGrey(const XRaySettings& x, double mu, double r) {
  constexpr int n = 64;
  double sum = 0;
  for (int i = 0; i < n; ++i) {
    const double u = -1 + (i + 0.5) * 2.0 / n;
    sum += xrayGrey(x, mu * 2 * r * std::sqrt(1 - u * u));
  }
  return float(sum / n);
}

}  // namespace

float xrayGrey(const XRaySettings& x, double attenuation) {
  return std::clamp(float(x.brightness * std::exp(-attenuation)), 0.0f, 1.0f);
}

XRayGreys xrayGreys(const DrawData& data, const Camera& camera, const XRaySettings& x) {
  XRayGreys g;
  g.background = xrayGrey(x, 0);
  double thinnest[3] = {-1, -1, -1};  // coil, catheter, wire
  for (const DrawTube& t : data.tubes) {
    if (!(t.radius > 0) || t.centre.size() < 2) continue;
    double& r = thinnest[t.role == RodRole::Coil ? 0 : t.role == RodRole::Catheter ? 1 : 2];
    if (r < 0 || t.radius < r) r = t.radius;
  }
  // The composite weighs metal, catheter and contrast by 1 (its uWeight).
  if (thinnest[0] > 0) g.coil = tubeGrey(x, x.muMetal, thinnest[0]);
  if (thinnest[1] > 0) g.catheter = tubeGrey(x, x.muCatheter, thinnest[1]);
  if (thinnest[2] > 0) g.wire = tubeGrey(x, x.muWire, thinnest[2]);
  double largest = 0, vesselChord = 0;
  for (const DrawMesh& m : data.meshes) {
    const MeshChord c = meanChord(m, camera.forward());
    if (c.closed && c.volume > largest) largest = c.volume, vesselChord = c.chord;
  }
  if (largest > 0) {
    g.vessel = xrayGrey(x, x.muContrast * vesselChord);
    // The composite's outline term saturates at 1.5 (its `edge`).
    g.vesselEdge = xrayGrey(x, x.muContrast * vesselChord + x.outline * 1.5);
  }
  return g;
}

}  // namespace coilsim::render
