#pragma once
// A sac packed with coil, for the dense-contact tests (issue 16): four
// coils laid as nested spherical spirals in the bottom of a 7 mm sac, and
// what the tests measure on it independently of the contact code (segment
// distances in closed form, clearances from the icosphere's face planes,
// the coils' weight and upthrust from their section and density).
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "physics/effect.h"
#include "physics/model.h"
#include "physics/rest_shape.h"
#include "physics/section.h"
#include "physics/state.h"
#include "support/segment_distance.h"
#include "support/meshes.h"

namespace coilsim::test::dense {

constexpr double kSacRadius = 3.5e-3;   // m: the practice case's 7 mm sac
constexpr double kWireRadius = 0.127e-3;  // m: a 0.010 inch primary coil
constexpr double kBeam = 0.5e-3;        // m: the scenes' and planning's coil spacing
// m between neighbouring turns and shells: more than a 0.5 mm chord sags
// (L^2 / 8 rho: 22 um on the band's smallest turn, 1.4 mm across), so the
// laid chords do not overlap; gravity closes it.
constexpr double kGap = 40e-6;
constexpr int kShells = 4;
// The band the spirals cover, as angles from the sac's bottom pole: the
// bottom of the sac, where gravity keeps a packing, without the pole's
// small turns.
constexpr double kBandFrom = 25 * M_PI / 180, kBandTo = 50 * M_PI / 180;
constexpr double kMedium = 1000;  // kg/m^3, the buoyancy effect's default medium (water)

// The catalogue's filling-helical-4x80: platinum wound into a 0.254 mm
// primary coil, B 0.001827 N mm^2, C 0.002174 N mm^2 (docs/coils.md).
constexpr double kYoung = 168e9, kDensity = 21450, kArea = 0.023e-6;

inline Section coilSection() {
  Section s;
  s.area = kArea;
  s.iy = s.iz = 1.827e-9 / kYoung;
  s.torsion = 2.174e-9 / shearModulusOf(kYoung, 0.38);
  s.radius = kWireRadius;
  return s;
}

// A spherical spiral of radius R about the sac's centre, turns `pitch`
// apart along the sphere, from angle a0 to a1 off the bottom pole.
inline std::vector<Vec3> spiral(double radius, double pitch, double a0, double a1) {
  const double turnsPerRadian = radius / pitch;
  const int n = int(std::ceil((a1 - a0) * turnsPerRadian * 40)) + 2;
  std::vector<Vec3> p;
  for (int i = 0; i < n; ++i) {
    const double a = a0 + (a1 - a0) * i / (n - 1), phi = 2 * M_PI * turnsPerRadian * a;
    p.push_back(radius * Vec3(std::sin(a) * std::cos(phi), std::sin(a) * std::sin(phi), -std::cos(a)));
  }
  return p;
}

// A coil resting in the shape of the polyline `p`: makePolyline samples it
// canonically (first node at the origin, along x), and the rigid fit
// (Umeyama) of its nodes to the points at the same arc lengths places it.
inline RodDef coilAlong(const std::vector<Vec3>& p, const std::string& name) {
  std::vector<double> at(1, 0.0);
  for (size_t i = 1; i < p.size(); ++i) at.push_back(at.back() + (p[i] - p[i - 1]).norm());
  RodDef r;
  r.name = name;
  r.length = at.back();
  r.beams = std::max(2, int(std::lround(r.length / kBeam)));
  r.rest = makePolyline(p, r.length, r.beams, FrameRule::ParallelTransport, 0);
  Eigen::Matrix3Xd from(3, r.beams + 1), to(3, r.beams + 1);
  for (int i = 0; i <= r.beams; ++i) {
    const double s = r.length * i / r.beams;
    const size_t j = std::min(size_t(std::upper_bound(at.begin(), at.end(), s) - at.begin()), p.size() - 1);
    const double t = (s - at[j - 1]) / (at[j] - at[j - 1]);
    to.col(i) = p[j - 1] + std::clamp(t, 0.0, 1.0) * (p[j] - p[j - 1]);
    from.col(i) = r.rest.points[size_t(i)];
  }
  const Eigen::Matrix4d fit = Eigen::umeyama(from, to, false);
  r.placement.position = fit.topRightCorner<3, 1>();
  r.placement.direction = fit.block<3, 1>(0, 0);
  r.placement.normal = fit.block<3, 1>(0, 1);
  r.material = {kYoung, shearModulusOf(kYoung, 0.38), kDensity};
  r.section = coilSection();
  return r;
}

// The sac's wall: an icosphere of 5120 triangles.
inline TriangleMesh sacWall() { return icosphere(kSacRadius, 4); }

// The packed sac: kShells coils, the outer one 0.1 r off the wall, each
// next one a pitch (2 r + gap) further in (194 mm of coil, 389 segments,
// 5.5 % of the sac, the bottom 1.2 mm of it packed as densely as the laying
// allows); gravity, buoyancy and drag, and the three contacts with their
// registered laws, the wall's friction off when asked.
inline ModelDef packedSac(bool frictionlessWall) {
  ModelDef def;
  def.timeStep = 1e-3;
  def.gravity = Vec3(0, 0, -9.81);
  def.damping = {1.0, 0.0};
  for (const char* e : {"gravity", "buoyancy", "drag", "wall_contact", "self_contact", "rod_contact"})
    def.effects.push_back(EffectRegistry::global().use(e));
  for (EffectUse& e : def.effects)
    if (e.name() == "wall_contact" && frictionlessWall) {
      e.set("friction_static", 0);
      e.set("friction_dynamic", 0);
    }
  def.obstacles.push_back(obstacleOf(sacWall()));
  const double pitch = 2 * kWireRadius + kGap;
  for (int k = 0; k < kShells; ++k)
    def.rods.push_back(coilAlong(spiral(kSacRadius - 1.1 * kWireRadius - k * pitch, pitch, kBandFrom, kBandTo),
                                 "shell " + std::to_string(k)));
  return def;
}

// A straight coil of `length` whose proximal node is held (all its
// degrees of freedom), lying along `along` with its free tip at `tip`: the
// coil pushed into the packing (its hold driven by a constraint velocity).
inline RodDef pushedCoil(const Vec3& tip, const Vec3& along, double length) {
  RodDef r;
  r.name = "pushed";
  r.length = length;
  r.beams = int(std::lround(length / kBeam));
  r.rest = makeStraight(length, r.beams);
  r.placement.position = tip - length * along;
  r.placement.direction = along;
  r.placement.normal = along.unitOrthogonal();
  r.material = {kYoung, shearModulusOf(kYoung, 0.38), kDensity};
  r.section = coilSection();
  r.constraints.push_back({0, kAllDofs});
  return r;
}

inline double coilLength(const ModelDef& def) {
  double l = 0;
  for (const RodDef& r : def.rods) l += r.length;
  return l;
}

// The coils' weight less their upthrust, N (Archimedes: the fluid displaced
// by a cylinder of the wire's outer radius), from the section and densities.
inline double netWeight(const ModelDef& def) {
  return (kDensity * kArea - kMedium * M_PI * kWireRadius * kWireRadius) * 9.81 * coilLength(def);
}

using test::segmentDistance;  // tests/support/segment_distance.h

struct Depths {
  double pair = 0;  // deepest overlap of two wires (2 r - centre-line distance), m
  double wall = 0;  // deepest the wire reaches past the wall's faces (r - clearance), m
  int touching = 0, segments = 0;  // segments within 10 % of r of another wire or the wall, and all
};

// Every pair of segments (but neighbours along one rod) and every node
// against the sac's face planes.
inline Depths measure(const State& s, const ConvexCavity& sac) {
  struct Seg {
    Vec3 a, b;
    int rod, index;
    bool touching;
  };
  std::vector<Seg> segs;
  for (size_t r = 0; r < s.rods.size(); ++r)
    for (int i = 0; i + 1 < s.rods[r].activeNodes; ++i)
      segs.push_back({s.rods[r].x[size_t(i)], s.rods[r].x[size_t(i) + 1], int(r), i, false});
  const double r = kWireRadius, near = 0.1 * r;
  Depths d;
  d.wall = -INFINITY;
  for (size_t i = 0; i < segs.size(); ++i)
    for (size_t j = i + 1; j < segs.size(); ++j) {
      Seg &p = segs[i], &q = segs[j];
      if (p.rod == q.rod && std::abs(p.index - q.index) < 2) continue;
      const double reach = 0.5 * ((p.b - p.a).norm() + (q.b - q.a).norm()) + 2 * r + near;
      if ((0.5 * (p.a + p.b - q.a - q.b)).squaredNorm() > reach * reach) continue;
      const double overlap = 2 * r - segmentDistance(p.a, p.b, q.a, q.b);
      d.pair = std::max(d.pair, overlap);
      if (overlap > -near) p.touching = q.touching = true;
    }
  for (Seg& g : segs) {
    const double past = r - std::min(sac.clearance(g.a, 2 * r), sac.clearance(g.b, 2 * r));
    d.wall = std::max(d.wall, past);
    if (past > -near) g.touching = true;
  }
  d.segments = int(segs.size());
  for (const Seg& g : segs) d.touching += g.touching;
  return d;
}

// Fastest node, m/s.
inline double fastestNode(const State& s) {
  double v = 0;
  for (const RodState& r : s.rods)
    for (int i = 0; i < r.activeNodes; ++i) v = std::max(v, r.v[size_t(i)].norm());
  return v;
}

// Sets the three contacts' penalties (and the wall's floor per bending
// rigidity) to `factor` times their registered values.
inline void scalePenalties(Model& model, double factor) {
  for (EffectUse& e : model.effects) {
    const EffectUse registered = EffectRegistry::global().use(e.name());
    if (e.name() == "wall_contact") {
      e.set("stiffness_n_mm2", registered.value("stiffness_n_mm2") * factor);
      e.set("stiffness_per_rigidity_1_mm3", registered.value("stiffness_per_rigidity_1_mm3") * factor);
    } else if (e.name() == "self_contact" || e.name() == "rod_contact") {
      e.set("stiffness_n_mm", registered.value("stiffness_n_mm") * factor);
    }
  }
}

// The wall's total normal force on the coils, N: each node's reported wall
// force (RodContacts::wallForce) along the sphere's inward normal there.
inline Vec3 wallNormalTotal(const State& s) {
  Vec3 f = Vec3::Zero();
  for (const RodState& r : s.rods)
    for (int i = 0; i < r.activeNodes && size_t(i) < r.contact.wallForce.size(); ++i)
      f -= r.contact.wallForce[size_t(i)] * r.x[size_t(i)].normalized();
  return f;
}

}  // namespace coilsim::test::dense

