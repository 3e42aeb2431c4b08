#include "geometry/phantom.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "geometry/marching_tets.h"

namespace coilsim::geometry {
namespace {

// Signed distances (exact where noted; a bound elsewhere: only the zero set
// must be exact, the rest only shapes the fillets).
double capsule(const Vec3& p, const Vec3& a, const Vec3& b, double r) {  // exact
  const Vec3 ab = b - a;
  const double t = std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
  return (p - (a + t * ab)).norm() - r;
}

// A tube of radius r around the arc of radius R about `centre` in the x-z
// plane, from angle -halfAngle to +halfAngle measured from +z toward +x. Exact.
double arcTube(const Vec3& p, const Vec3& centre, double R, double halfAngle, double r) {
  const Vec3 q = p - centre;
  const double phi = std::atan2(q.x(), q.z());
  if (std::abs(phi) <= halfAngle) return std::hypot(std::hypot(q.x(), q.z()) - R, q.y()) - r;
  const double end = std::copysign(halfAngle, phi);
  const Vec3 e(R * std::sin(end), 0, R * std::cos(end));
  return (q - e).norm() - r;
}

// Ellipsoid with semi-axes `radii` in local coordinates q (Quilez's bound:
// exact zero set, distance-like near it).
double ellipsoid(const Vec3& q, const Vec3& radii) {
  const double k0 = q.cwiseQuotient(radii).norm();
  const double k1 = q.cwiseQuotient(radii.cwiseProduct(radii)).norm();
  if (k1 == 0) return -radii.minCoeff();
  return k0 * (k0 - 1) / k1;
}

// Polynomial smooth minimum: a fillet of about radius k where a and b meet.
double smoothMin(double a, double b, double k) {
  if (k <= 0) return std::min(a, b);
  const double h = std::max(k - std::abs(a - b), 0.0) / k;
  return std::min(a, b) - h * h * k * 0.25;
}

void check(bool ok, const std::string& what) {
  if (!ok) throw std::invalid_argument("phantom: " + what);
}

// The parent vessel(s) as a field, with the point on the centre line under
// the sac and the dome direction there.
struct Vessels {
  Field field;
  Vec3 base, dome;
  Eigen::AlignedBox3d box;
};

Vessels makeVessels(VesselType type, double rv, double blend) {
  Vessels v;
  v.base = Vec3::Zero(), v.dome = Vec3::UnitZ();
  switch (type) {
    case VesselType::Sidewall: {
      // A straight segment of an internal carotid-like artery, sac on top.
      const Vec3 a(-12, 0, 0), b(12, 0, 0);
      v.field = [=](const Vec3& p) { return capsule(p, a, b, rv); };
      v.box.extend(a).extend(b);
      break;
    }
    case VesselType::Curved: {
      // A siphon-like bend of radius 10 mm over 140 degrees with straight
      // runs at both ends; the sac sits on the outer curve at its apex.
      const double R = 10, half = 70 * M_PI / 180, run = 4;
      const Vec3 c(0, 0, -R);
      const Vec3 e1 = c + R * Vec3(std::sin(half), 0, std::cos(half));
      const Vec3 e0 = c + R * Vec3(-std::sin(half), 0, std::cos(half));
      const Vec3 t1(std::cos(half), 0, -std::sin(half)), t0(-std::cos(half), 0, -std::sin(half));
      v.field = [=](const Vec3& p) {
        return std::min({arcTube(p, c, R, half, rv), capsule(p, e1, e1 + run * t1, rv), capsule(p, e0, e0 + run * t0, rv)});
      };
      v.box.extend(c + Vec3(-R, 0, 0)).extend(c + Vec3(R, 0, R)).extend(e1 + run * t1).extend(e0 + run * t0);
      break;
    }
    case VesselType::Bifurcation: {
      // A basilar-tip-like T: the parent from below, two daughters (0.8 of
      // its diameter, Murray's law) leaving at 100 degrees from its axis, so
      // they stay below the neck plane; the sac on the apex.
      const double rd = 0.8 * rv, angle = 100 * M_PI / 180, parent = 14, daughter = 11;
      const Vec3 o = Vec3::Zero(), bottom(0, 0, -parent);
      const Vec3 l = daughter * Vec3(-std::sin(angle), 0, std::cos(angle));
      const Vec3 r = daughter * Vec3(std::sin(angle), 0, std::cos(angle));
      v.field = [=](const Vec3& p) {
        return smoothMin(smoothMin(capsule(p, bottom, o, rv), capsule(p, o, l, rd), blend), capsule(p, o, r, rd), blend);
      };
      v.box.extend(bottom).extend(l).extend(r).extend(o);
      break;
    }
  }
  v.box.min().array() -= rv, v.box.max().array() += rv;
  return v;
}

// Distance along `dir` from `from` (inside) to the zero of f, by bisection.
double surfaceAlong(const Field& f, const Vec3& from, const Vec3& dir, double reach) {
  double lo = 0, hi = reach;
  if (!(f(from) < 0) || !(f(from + reach * dir) > 0)) throw std::logic_error("phantom: vessel top not bracketed");
  for (int i = 0; i < 100; ++i) {
    const double mid = 0.5 * (lo + hi);
    (f(from + mid * dir) < 0 ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

// Volume of the unit ball above the plane z = -s, s in [-1, 1].
double unitBallAbove(double s) {
  const double h = 1 - s;  // height of the cap below the plane
  return 4.0 * M_PI / 3.0 - M_PI * h * h * (3 - h) / 3.0;
}

}  // namespace

const char* vesselTypeName(VesselType type) {
  switch (type) {
    case VesselType::Sidewall: return "sidewall";
    case VesselType::Curved: return "curved";
    case VesselType::Bifurcation: return "bifurcation";
  }
  return "?";
}

bool parseVesselType(const std::string& name, VesselType& out) {
  for (VesselType t : {VesselType::Sidewall, VesselType::Curved, VesselType::Bifurcation})
    if (name == vesselTypeName(t)) return out = t, true;
  return false;
}

Phantom makePhantom(const PhantomSpec& s) {
  auto finite = [](double x) { return std::isfinite(x); };
  check(finite(s.sacDiameter) && s.sacDiameter >= 1 && s.sacDiameter <= 40, "sac diameter must be in [1, 40] mm");
  const double height = s.sacHeight == 0 ? s.sacDiameter : s.sacHeight;
  check(finite(height) && height >= 0.5 * s.sacDiameter && height <= 3 * s.sacDiameter,
        "sac height must be in [0.5, 3] x the sac diameter");
  check(finite(s.domeToNeck) && s.domeToNeck >= 1 && s.domeToNeck <= 10, "dome-to-neck ratio must be in [1, 10]");
  const double neck = s.neckWidth > 0 ? s.neckWidth : s.sacDiameter / s.domeToNeck;
  check(finite(neck) && neck >= 0 && neck <= s.sacDiameter,
        "neck width must be > 0 and at most the sac diameter (a sphere or ellipsoid is widest at its equator)");
  check(s.lobes >= 1 && s.lobes <= 6, "lobes must be in [1, 6]");
  check(finite(s.vesselDiameter) && s.vesselDiameter >= 1 && s.vesselDiameter <= 10,
        "vessel diameter must be in [1, 10] mm");
  check(finite(s.resolution) && s.resolution >= 0.02 && s.resolution <= s.sacDiameter / 8,
        "resolution must be in [0.02 mm, sac diameter / 8]");
  check(finite(s.blend) && s.blend >= 0 && s.blend <= 0.5 * s.vesselDiameter, "blend must be in [0, vessel radius]");

  Phantom out;
  PhantomInfo& info = out.info;
  info.type = vesselTypeName(s.vessel);
  info.spec = s;
  const double rv = 0.5 * s.vesselDiameter;
  info.vesselRadius = rv;
  const Vessels vessels = makeVessels(s.vessel, rv, s.blend);

  // Neck plane: where the dome axis leaves the vessel; the main lobe is
  // placed so that it crosses that plane in a circle of the neck's diameter.
  const Vec3 n = vessels.dome;
  const Vec3 neckPoint = vessels.base + surfaceAlong(vessels.field, vessels.base, n, 3 * rv) * n;
  info.neck = Plane{neckPoint, n};
  info.neckWidth = neck;
  info.axisU = Vec3::UnitX();  // along the parent vessel at the neck (daughters, for the bifurcation)
  info.axisV = n.cross(info.axisU);
  const double a = 0.5 * s.sacDiameter, c = 0.5 * height;
  const double lift = c * std::sqrt(std::max(0.0, 1 - (0.5 * neck / a) * (0.5 * neck / a)));
  info.sacCentre = neckPoint + lift * n;
  info.sacRadii = Vec3(a, a, c);
  info.lobes.push_back({info.sacCentre, info.sacRadii});
  // Daughter lobes: balls on the upper flank of the dome, evenly around it.
  for (int k = 1; k < s.lobes; ++k) {
    const double phi = 2 * M_PI * (k - 1) / (s.lobes - 1) + 0.3, beta = 55 * M_PI / 180, rb = 0.5 * a;
    const Vec3 offset = 0.9 * (a * std::sin(beta) * (std::cos(phi) * info.axisU + std::sin(phi) * info.axisV) +
                               c * std::cos(beta) * n);
    info.lobes.push_back({info.sacCentre + offset, Vec3::Constant(rb)});
  }
  info.idealSacVolume = a * a * c * unitBallAbove(lift / c);

  // The sac is cut a little below the neck plane so that a wide sac does not
  // wrap around the vessel; the cut lies inside the vessel.
  const double cutDepth = std::min(0.3 * rv, c - lift + 1e-3);
  const PhantomInfo frame = info;
  const double k = s.blend;
  const Field field = [vessels, frame, cutDepth, k](const Vec3& p) {
    double sac = 1e30;
    for (size_t i = 0; i < frame.lobes.size(); ++i) {
      const Vec3 d = p - frame.lobes[i].centre;
      const Vec3 q(d.dot(frame.axisU), d.dot(frame.axisV), d.dot(frame.neck.normal));
      sac = i == 0 ? ellipsoid(q, frame.lobes[i].radii) : smoothMin(sac, ellipsoid(q, frame.lobes[i].radii), k);
    }
    sac = std::max(sac, -frame.neck.side(p) - cutDepth);
    return smoothMin(vessels.field(p), sac, k);
  };

  Eigen::AlignedBox3d box = vessels.box;
  for (const Lobe& l : info.lobes) {
    const Vec3 reach = Vec3::Constant(l.radii.maxCoeff());
    box.extend(l.centre + reach).extend(l.centre - reach);
  }
  const double margin = s.blend + 3 * s.resolution;
  out.mesh = polygonise(field, box.min() - Vec3::Constant(margin), box.max() + Vec3::Constant(margin), s.resolution);
  out.mesh.name = std::string(info.type) + "-" + std::to_string(int(std::lround(s.sacDiameter))) + "mm";
  return out;
}

}  // namespace coilsim::geometry
