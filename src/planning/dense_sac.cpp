// Nested spherical spirals of coil in a spherical sac (see dense_sac.h).
#include "planning/dense_sac.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "physics/effect.h"
#include "physics/rest_shape.h"
#include "physics/section.h"
#include "planning/run_contacts.h"
#include "planning/sac_geometry.h"

namespace coilsim::planning {
namespace {

// One spherical spiral of radius R, turns `spacing` apart along the sphere,
// from polar angle theta0 to theta1. The caps near the axis are left out by
// the caller: there the chords of 0.5 mm beams would sag (L^2 / 8 rho, 31 um
// at 1 mm) into the next turn, 10 um away.
std::vector<Vec3> spiral(double radius, double spacing, double theta0, double theta1) {
  const double turnsPerRadian = radius / spacing;  // phi = 2 pi (R / d) theta
  std::vector<Vec3> p;
  const int n = int(std::ceil((theta1 - theta0) * turnsPerRadian * 40)) + 2;
  for (int i = 0; i < n; ++i) {
    const double theta = theta0 + (theta1 - theta0) * i / (n - 1), phi = 2 * M_PI * turnsPerRadian * theta;
    p.push_back(radius * Vec3(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)));
  }
  return p;
}

double polylineLength(const std::vector<Vec3>& p) {
  double l = 0;
  for (size_t i = 1; i < p.size(); ++i) l += (p[i] - p[i - 1]).norm();
  return l;
}

}  // namespace

double densePacking(double coilLength, const DenseSacSpec& spec) {
  return coilLength * M_PI * spec.wireRadius * spec.wireRadius / (4.0 / 3 * M_PI * std::pow(spec.sacRadius, 3));
}

ModelDef denseSacModel(double total, const DenseSacSpec& spec) {
  if (!(total > 0)) throw std::invalid_argument("dense sac: the coil length must be positive");
  ModelDef def;
  for (const char* e : {"gravity", "buoyancy", "drag"}) def.effects.push_back(EffectRegistry::global().use(e));
  def.damping = {1.0, 0.0};
  def.timeStep = 1e-3;
  def.gravity = Vec3(0, 0, -9.81);
  const double pitch = 2 * spec.wireRadius + spec.gap;
  double left = total, radius = spec.sacRadius - 1.1 * spec.wireRadius;
  for (int shell = 0; left > spec.beam && radius > 1.5e-3; ++shell, radius -= pitch) {
    const double theta0 = std::asin(std::min(1.0, spec.capRadius / radius)), theta1 = M_PI - theta0;
    std::vector<Vec3> p = spiral(radius, pitch, theta0, theta1);
    if (polylineLength(p) > left) {  // the last shell: only as much as is left
      double lo = theta0, hi = theta1;
      for (int i = 0; i < 40; ++i) {
        const double mid = 0.5 * (lo + hi);
        (polylineLength(spiral(radius, pitch, theta0, mid)) > left ? hi : lo) = mid;
      }
      p = spiral(radius, pitch, theta0, lo);
    }
    const double length = polylineLength(p);
    RodDef r;
    r.name = "shell " + std::to_string(shell);
    r.length = length;
    r.beams = std::max(2, int(std::lround(length / spec.beam)));
    r.rest = makePolyline(p, length, r.beams, FrameRule::ParallelTransport, 0);
    // makePolyline returns the curve canonical (first node at the origin,
    // along x): placed back onto the spiral by the rigid fit (Umeyama) of
    // its nodes to the points at the same arc lengths.
    Eigen::Matrix3Xd from(3, r.beams + 1), to(3, r.beams + 1);
    for (int i = 0, j = 0; i <= r.beams; ++i) {
      const double target = length * i / r.beams;
      double at = 0;
      for (j = 0; j + 2 < int(p.size()) && at + (p[j + 1] - p[j]).norm() < target; ++j) at += (p[j + 1] - p[j]).norm();
      const double seg = (p[j + 1] - p[j]).norm();
      to.col(i) = p[j] + std::clamp((target - at) / seg, 0.0, 1.0) * (p[j + 1] - p[j]);
      from.col(i) = r.rest.points[i];
    }
    const Eigen::Matrix4d fit = Eigen::umeyama(from, to, false);
    const Eigen::Matrix3d rot = fit.topLeftCorner<3, 3>();
    r.placement.position = fit.topRightCorner<3, 1>();
    r.placement.direction = rot.col(0);
    r.placement.normal = rot.col(1);
    // The catalogue's filling-helical-4x80: platinum wound into a 0.254 mm
    // primary coil, B 0.001827 N mm^2, C 0.002174 N mm^2 (docs/coils.md).
    r.material = {168e9, shearModulusOf(168e9, 0.38), 21450};
    r.section.area = 0.023e-6;
    r.section.iy = r.section.iz = 1.827e-9 / 168e9;
    r.section.torsion = 2.174e-9 / shearModulusOf(168e9, 0.38);
    r.section.radius = spec.wireRadius;
    def.rods.push_back(r);
    left -= length;
  }
  Sac sac;
  sac.mesh = std::make_shared<const TriangleMesh>(makeIcosphere(Vec3::Zero(), spec.sacRadius, spec.subdivisions, "7 mm sac"));
  addRunContacts(def, sac);
  return def;
}

}  // namespace coilsim::planning
