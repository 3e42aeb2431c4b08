// Dense-packing timings for `coilsim bench` (see bench_dense.h): coil laid
// in nested spherical spirals inside a 7 mm sac, the step timed against the
// length of coil in the sac.
#include "app/bench_dense.h"

#include <time.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "physics/integrator.h"
#include "physics/model.h"
#include "physics/run.h"
#include "planning/run_contacts.h"
#include "planning/sac_geometry.h"

namespace coilsim {
namespace {

// CPU time of this thread, in microseconds: on a machine shared with other
// builds the wall clock measures the neighbours as much as the code.
double cpuMicroseconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return 1e6 * double(t.tv_sec) + 1e-3 * double(t.tv_nsec);
}

constexpr double kSacRadius = 3.5e-3;     // m: the practice case's 7 mm sac
constexpr double kWireRadius = 0.127e-3;  // m: a 0.010 inch primary coil
constexpr double kBeam = 0.5e-3;          // m: planning's coil spacing

// One spherical spiral of radius R, turns `spacing` apart along the sphere,
// from polar angle theta0 to theta1. The caps within 1.2 mm of the axis are
// left out: there the chords of 0.5 mm beams would sag (L^2 / 8 rho, 31 um
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

// `total` m of coil in nested shells from the wall inwards, each shell's
// turns and the shells themselves 2 r + 10 um apart: every segment lies
// within the contact margin of its neighbours and the outer shell of the wall.
ModelDef denseSac(double total) {
  ModelDef def;
  for (const char* e : {"gravity", "buoyancy", "drag"}) def.effects.push_back(EffectRegistry::global().use(e));
  def.damping = {1.0, 0.0};
  def.timeStep = 1e-3;
  def.gravity = Vec3(0, 0, -9.81);
  const double pitch = 2 * kWireRadius + 10e-6;
  double left = total, radius = kSacRadius - 1.1 * kWireRadius;
  for (int shell = 0; left > kBeam && radius > 1.5e-3; ++shell, radius -= pitch) {
    const double theta0 = std::asin(std::min(1.0, 1.2e-3 / radius)), theta1 = M_PI - theta0;
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
    r.beams = std::max(2, int(std::lround(length / kBeam)));
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
    r.section.radius = kWireRadius;
    def.rods.push_back(r);
    left -= length;
  }
  planning::Sac sac;
  sac.mesh = std::make_shared<const TriangleMesh>(planning::makeIcosphere(Vec3::Zero(), kSacRadius, 4, "7 mm sac"));
  planning::addRunContacts(def, sac);
  return def;
}

bool isContact(const EffectUse& u) {
  return u.name() == "wall_contact" || u.name() == "self_contact" || u.name() == "rod_contact";
}

}  // namespace

void benchDenseFigures(const std::function<void(const std::string&, double)>& set, bool quick, bool json) {
  const std::vector<int> lengths = quick ? std::vector<int>{100, 500} : std::vector<int>{100, 250, 500, 1000, 1500};
  if (!json)
    std::printf("dense packing: coil in nested spherical spirals in a 7 mm sac (5120 triangles), 0.254 mm primary, "
                "wall + self + rod contact, thread CPU time per step:\n"
                "  %8s %8s %8s %10s %12s %14s %14s %8s\n",
                "coil_mm", "segments", "packing", "step_us", "detect_us", "detect_fresh_us", "contacts/seg", "us/seg");
  for (int mm : lengths) {
    const Model model = compileModel(denseSac(mm * 1e-3));
    State s = makeState(model);
    int segments = 0;
    for (const RodModel& r : model.rods) segments += r.nnode - 1;
    const int warm = 3, steps = quick ? 5 : 20;
    for (int i = 0; i < warm; ++i)
      if (const StepReport rep = step(model, s); !rep.ok() && !json) std::printf("  (%d mm, warm-up: %s)\n", mm, rep.message.c_str());
    double stepUs = 0, detectUs = 0, freshUs = 0;
    long contacts = 0;
    bool ok = true;
    for (int i = 0; i < steps; ++i) {
      State copy = s;
      double t0 = cpuMicroseconds();
      for (const EffectUse& u : model.effects)
        if (u.enabled && isContact(u)) u.effect->beginStep(model, u.values, copy, model.timeStep);
      detectUs += cpuMicroseconds() - t0;
      copy = s;
      copy.contactScratch.coherentWall = false;
      t0 = cpuMicroseconds();
      for (const EffectUse& u : model.effects)
        if (u.enabled && isContact(u)) u.effect->beginStep(model, u.values, copy, model.timeStep);
      freshUs += cpuMicroseconds() - t0;
      t0 = cpuMicroseconds();
      const StepReport rep = step(model, s);
      stepUs += cpuMicroseconds() - t0;
      if (!rep.ok() && ok && !json) std::printf("  (%d mm: %s)\n", mm, rep.message.c_str());
      ok = rep.ok() && ok;
      for (const RodState& r : s.rods) contacts += long(r.contact.wall.size() + r.contact.self.size() + r.contact.rod.size());
    }
    const double packing = mm * 1e-3 * M_PI * kWireRadius * kWireRadius / (4.0 / 3 * M_PI * std::pow(kSacRadius, 3));
    const std::string k = "_" + std::to_string(mm) + "mm";
    set("dense_step_us" + k, stepUs / steps);
    set("dense_detect_us" + k, detectUs / steps);
    set("dense_detect_fresh_us" + k, freshUs / steps);
    set("dense_segments" + k, segments);
    set("dense_run_ok" + k, ok ? 1.0 : 0.0);
    if (!json)
      std::printf("  %8d %8d %7.1f%% %10.0f %12.0f %14.0f %14.2f %8.2f%s\n", mm, segments, 100 * packing, stepUs / steps,
                  detectUs / steps, freshUs / steps, double(contacts) / steps / segments, stepUs / steps / segments,
                  ok ? "" : "  (a step was refused)");
  }
}

}  // namespace coilsim
