#include "physics/catheter.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "physics/beam.h"
#include "physics/failure.h"

namespace coilsim {
namespace {

// A piece of the canonical planar centre line: straight (curvature 0) or a
// circular arc of signed curvature about +z.
struct Piece {
  double length = 0, curvature = 0;
};

std::vector<Piece> pieces(const CatheterShape& s, double length) {
  const double bends = s.bendLength();
  if (!(bends <= length * (1 + 1e-12)))
    throw PhysicsError(badDefinition({}, "catheter tip bends need " + std::to_string(bends * 1e3) +
                                                " mm but the catheter is " + std::to_string(length * 1e3) + " mm long"));
  std::vector<Piece> p{{std::max(0.0, length - bends), 0.0}};
  const double k = s.radius > 0 ? 1.0 / s.radius : 0.0;
  switch (s.type) {
    case CatheterShape::Type::Straight: break;
    case CatheterShape::Type::Angled:
    case CatheterShape::Type::J: p.push_back({s.angle * s.radius, k}); break;
    case CatheterShape::Type::S:
      p.push_back({s.angle * s.radius, k});
      p.push_back({s.angle * s.radius, -k});
      break;
  }
  return p;
}

}  // namespace

double CatheterShape::bendLength() const {
  switch (type) {
    case Type::Straight: return 0;
    case Type::Angled:
    case Type::J: return angle * radius;
    case Type::S: return 2 * angle * radius;
  }
  return 0;
}

Section tubeSection(double ro, double ri, double nu) {
  Section s;
  s.radius = ro;
  s.area = M_PI * (ro * ro - ri * ri);
  s.iy = s.iz = M_PI * (std::pow(ro, 4) - std::pow(ri, 4)) / 4.0;
  s.torsion = 2.0 * s.iy;
  const double m = ri / ro, a = (1 + m * m) * (1 + m * m);
  s.shearFactor = 6 * (1 + nu) * a / ((7 + 6 * nu) * a + (20 + 12 * nu) * m * m);
  return s;
}

RestCurve makeCatheterRest(const CatheterShape& shape, double length, int beams) {
  if (beams < 1) throw PhysicsError(badDefinition({}, "the catheter needs at least 1 beam"));
  const std::vector<Piece> ps = pieces(shape, length);
  RestCurve c;
  // Walk the pieces once, sampling at s_i = i L / beams with the exact arc formulas.
  Vec3 p0 = Vec3::Zero();
  double phi0 = 0, s0 = 0;
  size_t k = 0;
  for (int i = 0; i <= beams; ++i) {
    const double s = length * i / beams;
    while (k + 1 < ps.size() && s > s0 + ps[k].length) {
      const double l = ps[k].length, kap = ps[k].curvature, phi1 = phi0 + kap * l;
      p0 += kap == 0 ? Vec3(l * std::cos(phi0), l * std::sin(phi0), 0)
                     : Vec3(std::sin(phi1) - std::sin(phi0), std::cos(phi0) - std::cos(phi1), 0) / kap;
      phi0 = phi1, s0 += l, ++k;
    }
    const double d = s - s0, kap = ps[k].curvature, phi = phi0 + kap * d;
    c.points.push_back(p0 + (kap == 0 ? Vec3(d * std::cos(phi0), d * std::sin(phi0), 0)
                                      : Vec3(std::sin(phi) - std::sin(phi0), std::cos(phi0) - std::cos(phi), 0) / kap));
    c.frames.push_back(Quat(Eigen::AngleAxisd(phi, Vec3::UnitZ())));
  }
  return c;
}

Quat blendRestRotation(const Quat& qc, const Quat& qk, double wc, double wk, CompositeWeighting rule) {
  const double total = wc + wk;
  if (!(total > 0)) return qc;
  if (rule == CompositeWeighting::BendingStiffness) return quatExp((wc * quatLog(qc) + wk * quatLog(qk)) / total);
  // The paper's normalised weighted sum, in one hemisphere so it cannot cancel.
  const double side = qc.coeffs().dot(qk.coeffs()) < 0 ? -1.0 : 1.0;
  Quat q;
  q.coeffs() = (wc * qc.coeffs() + side * wk * qk.coeffs()).normalized();
  return q;
}

BeamRest compositeBeamRest(const Quat& catheterRel, double chord, const Quat& coilRel, double coverage,
                           const Material& mc, const Section& sc, const Material& mk, const Section& sk,
                           CompositeWeighting rule) {
  const double f = std::clamp(coverage, 0.0, 1.0);
  const double wc = rule == CompositeWeighting::BendingStiffness ? mc.youngModulus * sc.iy : mc.youngModulus;
  const double wk = f * (rule == CompositeWeighting::BendingStiffness ? mk.youngModulus * sk.iy : mk.youngModulus);
  const Quat rel = blendRestRotation(catheterRel, coilRel, wc, wk, rule);
  // One section with the summed rigidities: with E = G = 1 its "area" is EA,
  // its moments EI, its torsion constant GJ, and kappa G A is kept through
  // the shear factor.
  Material m{1.0, 1.0, 1.0};
  Section s;
  s.area = mc.youngModulus * sc.area + f * mk.youngModulus * sk.area;
  s.iy = mc.youngModulus * sc.iy + f * mk.youngModulus * sk.iy;
  s.iz = mc.youngModulus * sc.iz + f * mk.youngModulus * sk.iz;
  s.torsion = mc.shearModulus * sc.torsion + f * mk.shearModulus * sk.torsion;
  const double kGA = sc.shearFactor * mc.shearModulus * sc.area + f * sk.shearFactor * mk.shearModulus * sk.area;
  s.shearFactor = sc.shearFactor > 0 && sk.shearFactor > 0 ? kGA / s.area : 0.0;
  s.radius = sc.radius;
  // The chord of a uniformly bent element lies halfway along its rotation.
  const Vec3 along = quatExp(0.5 * quatLog(rel)) * Vec3::UnitX();
  return makeBeamRest(Vec3::Zero(), Quat::Identity(), chord * along, rel, m, s);
}

}  // namespace coilsim
