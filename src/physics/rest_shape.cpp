#include "physics/rest_shape.h"

#include <cmath>

#include "physics/failure.h"

namespace coilsim {
namespace {

Quat frameFromColumns(const Vec3& t, const Vec3& d1) {
  Mat3 m;
  m.col(0) = t;
  m.col(1) = d1;
  m.col(2) = t.cross(d1);
  return Quat(m).normalized();
}

// Moves a curve so its first node is at the origin with frame identity.
RestCurve canonical(RestCurve c) {
  const Quat q0inv = c.frames.front().conjugate();
  const Vec3 p0 = c.points.front();
  for (size_t i = 0; i < c.points.size(); ++i) {
    c.points[i] = q0inv * (c.points[i] - p0);
    c.frames[i] = (q0inv * c.frames[i]).normalized();
  }
  return c;
}

// Points at equal arc-length fractions of a polyline, scaled to total `length`.
std::vector<Vec3> resample(const std::vector<Vec3>& pts, double length, int beams) {
  std::vector<double> s(pts.size(), 0.0);
  for (size_t i = 1; i < pts.size(); ++i) s[i] = s[i - 1] + (pts[i] - pts[i - 1]).norm();
  const double total = s.back();
  if (!(total > 0)) throw PhysicsError(badDefinition({}, "polyline has zero length"));
  std::vector<Vec3> out(beams + 1);
  size_t k = 0;
  for (int i = 0; i <= beams; ++i) {
    const double target = total * i / beams;
    while (k + 2 < pts.size() && s[k + 1] < target) ++k;
    const double seg = s[k + 1] - s[k];
    const double a = seg > 0 ? std::clamp((target - s[k]) / seg, 0.0, 1.0) : 0.0;
    out[i] = (1 - a) * pts[k] + a * pts[k + 1];
  }
  const double scale = length / total;
  const Vec3 origin = out.front();
  for (auto& p : out) p = (p - origin) * scale;
  return out;
}

// Tangents at equally spaced samples, exact on circular arcs: central
// differences inside; at an end, the end chord turned back by half the angle
// between the last two chords (a bare chord there would halve the end beams'
// rest curvature).
std::vector<Vec3> nodeTangents(const std::vector<Vec3>& x) {
  const size_t n = x.size();
  std::vector<Vec3> t(n);
  for (size_t i = 1; i + 1 < n; ++i) t[i] = (x[i + 1] - x[i - 1]).normalized();
  auto halfTurn = [](const Vec3& from, const Vec3& to) { return quatExp(0.5 * quatLog(minimalRotation(from, to))); };
  if (n < 3) {
    t[0] = t[n - 1] = (x[n - 1] - x[0]).normalized();
    return t;
  }
  const Vec3 e0 = (x[1] - x[0]).normalized(), e1 = (x[2] - x[1]).normalized();
  t[0] = (halfTurn(e1, e0) * e0).normalized();
  const Vec3 f0 = (x[n - 2] - x[n - 3]).normalized(), f1 = (x[n - 1] - x[n - 2]).normalized();
  t[n - 1] = (halfTurn(f0, f1) * f1).normalized();
  return t;
}

}  // namespace

RestCurve makeStraight(double length, int beams) {
  RestCurve c;
  for (int i = 0; i <= beams; ++i) {
    c.points.emplace_back(length * i / beams, 0.0, 0.0);
    c.frames.push_back(Quat::Identity());
  }
  return c;
}

RestCurve makeHelix(double length, int beams, double loopDiameter, double pitch, bool rightHanded) {
  const double R = 0.5 * loopDiameter;
  const double c = pitch / (2 * M_PI);
  const double a = std::sqrt(R * R + c * c);
  const double sg = rightHanded ? 1.0 : -1.0;
  RestCurve curve;
  for (int i = 0; i <= beams; ++i) {
    const double phi = length * i / beams / a;
    const Vec3 p(R * std::cos(phi), sg * R * std::sin(phi), c * phi);
    const Vec3 t = Vec3(-R * std::sin(phi), sg * R * std::cos(phi), c) / a;
    const Vec3 n(-std::cos(phi), -sg * std::sin(phi), 0.0);
    curve.points.push_back(p);
    curve.frames.push_back(frameFromColumns(t, n));
  }
  return canonical(curve);
}

RestCurve makePolyline(const std::vector<Vec3>& points, double length, int beams, FrameRule rule,
                       double twistPerLength) {
  if (points.size() < 2) throw PhysicsError(badDefinition({}, "polyline needs at least 2 points"));
  RestCurve c;
  c.points = resample(points, length, beams);
  const std::vector<Vec3> t = nodeTangents(c.points);
  const size_t n = c.points.size();
  // Parallel transport gives a twist-free d1; Frenet replaces it by the
  // principal normal wherever the curve bends measurably.
  std::vector<Vec3> d1(n);
  d1[0] = anyPerpendicular(t[0]);
  for (size_t i = 1; i < n; ++i) d1[i] = (minimalRotation(t[i - 1], t[i]) * d1[i - 1]).normalized();
  if (rule == FrameRule::Frenet) {
    std::vector<Vec3> normal(n, Vec3::Zero());
    std::vector<bool> ok(n, false);
    for (size_t i = 1; i + 1 < n; ++i) {
      const Vec3 e0 = c.points[i] - c.points[i - 1], e1 = c.points[i + 1] - c.points[i];
      const Vec3 kb = 2.0 * e0.cross(e1) / (e0.norm() * e1.norm() + e0.dot(e1));
      if (kb.norm() * e0.norm() > 1e-9) {
        normal[i] = kb.normalized().cross(t[i]).normalized();
        ok[i] = true;
      }
    }
    if (n > 2) {
      ok[0] = ok[1], normal[0] = (normal[1] - normal[1].dot(t[0]) * t[0]).normalized();
      ok[n - 1] = ok[n - 2], normal[n - 1] = (normal[n - 2] - normal[n - 2].dot(t[n - 1]) * t[n - 1]).normalized();
    }
    for (size_t i = 0; i < n; ++i)
      if (ok[i] && normal[i].allFinite()) d1[i] = normal[i];
  }
  for (size_t i = 0; i < n; ++i) {
    const double s = length * double(i) / beams;
    const Vec3 d = Eigen::AngleAxisd(twistPerLength * s, t[i]) * d1[i];
    c.frames.push_back(frameFromColumns(t[i], (d - d.dot(t[i]) * t[i]).normalized()));
  }
  return canonical(c);
}

RestCurve makeBirdcage(double length, int beams, double sphereDiameter, double planeTurnPerLoopRad) {
  // Small circles at polar angle alpha about a centre direction n0 tilted by
  // gamma from z; the whole loop system turns about z as the curve advances.
  const double R = 0.5 * sphereDiameter, alpha = 75.0 * M_PI / 180.0, gamma = 60.0 * M_PI / 180.0;
  const Vec3 n0(std::sin(gamma), 0, std::cos(gamma));
  const Vec3 u0 = Vec3(std::cos(gamma), 0, -std::sin(gamma)), v0 = n0.cross(u0);
  auto at = [&](double phi) {
    const Eigen::AngleAxisd turn(planeTurnPerLoopRad * phi / (2 * M_PI), Vec3::UnitZ());
    return Vec3(turn * (R * std::cos(alpha) * n0 +
                        R * std::sin(alpha) * (std::cos(phi) * u0 + std::sin(phi) * v0)));
  };
  const double loop = 2 * M_PI * R * std::sin(alpha);
  const int samples = std::max(2000, int(200 * length / loop));
  const double dphi = 2 * M_PI / 200;
  std::vector<Vec3> pts{at(0)};
  double s = 0;
  for (int k = 1; s < length && k < 1000 * samples; ++k) {
    pts.push_back(at(k * dphi));
    s += (pts.back() - pts[pts.size() - 2]).norm();
  }
  // Trim the last sample so the polyline is exactly `length` long.
  const double over = s - length;
  if (over > 0) {
    const Vec3 a = pts[pts.size() - 2], b = pts.back();
    pts.back() = b + (a - b).normalized() * over;
  }
  return makePolyline(pts, length, beams, FrameRule::Frenet, 0.0);
}

Quat Placement::rotation() const {
  const Vec3 t = direction.normalized();
  const Vec3 n = (normal - normal.dot(t) * t).normalized();
  return frameFromColumns(t, n);
}

RestCurve placed(const RestCurve& curve, const Placement& placement) {
  const Quat r = placement.rotation();
  RestCurve out = curve;
  for (size_t i = 0; i < out.points.size(); ++i) {
    out.points[i] = placement.position + r * curve.points[i];
    out.frames[i] = (r * curve.frames[i]).normalized();
  }
  return out;
}

RestCurve makeRest(const RestShapeDef& rest, double length, int beams) {
  switch (rest.type) {
    case RestShapeDef::Type::Straight: return makeStraight(length, beams);
    case RestShapeDef::Type::Helix: return makeHelix(length, beams, rest.loopDiameter, rest.pitch, rest.rightHanded);
    case RestShapeDef::Type::Polyline: return makePolyline(rest.points, length, beams, rest.frames, rest.twistPerLength);
    case RestShapeDef::Type::Birdcage: return makeBirdcage(length, beams, rest.sphereDiameter, rest.planeTurnPerLoop);
  }
  throw PhysicsError(badDefinition({}, "unknown rest shape type"));
}

}  // namespace coilsim
