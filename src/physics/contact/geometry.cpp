#include "physics/contact/geometry.h"

#include <algorithm>
#include <cmath>

namespace coilsim {

SegmentPair closestSegmentSegment(const Vec3& p0, const Vec3& p1, const Vec3& q0, const Vec3& q1) {
  const Vec3 d1 = p1 - p0, d2 = q1 - q0, r = p0 - q0;
  const double a = d1.squaredNorm(), e = d2.squaredNorm(), f = d2.dot(r);
  SegmentPair out;
  double s = 0, t = 0;
  if (a <= 1e-30 && e <= 1e-30) {
    s = t = 0;
  } else if (a <= 1e-30) {
    t = std::clamp(f / e, 0.0, 1.0);
  } else {
    const double c = d1.dot(r);
    if (e <= 1e-30) {
      s = std::clamp(-c / a, 0.0, 1.0);
    } else {
      const double b = d1.dot(d2), denom = a * e - b * b;
      if (denom > 1e-6 * a * e) {
        s = std::clamp((b * f - c * e) / denom, 0.0, 1.0);
      } else {
        // Parallel: the middle of the overlap of q's projection on p.
        const double u0 = std::clamp(-c / a, 0.0, 1.0), u1 = std::clamp((d1.dot(q1 - p0)) / a, 0.0, 1.0);
        s = 0.5 * (u0 + u1);
      }
      t = (b * s + f) / e;
      if (t < 0) {
        t = 0;
        s = std::clamp(-c / a, 0.0, 1.0);
      } else if (t > 1) {
        t = 1;
        s = std::clamp((b - c) / a, 0.0, 1.0);
      }
    }
  }
  out.s = s, out.t = t;
  out.p = p0 + s * d1;
  out.q = q0 + t * d2;
  out.distance = (out.p - out.q).norm();
  return out;
}

Vec3 closestPointTriangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  // Voronoi regions of the vertices, edges and face in turn (Ericson 5.1.5).
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return a;
  const Vec3 bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return b;
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return a + (d1 / (d1 - d3)) * ab;
  const Vec3 cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return c;
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return a + (d2 / (d2 - d6)) * ac;
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) return b + ((d4 - d3) / ((d4 - d3) + (d5 - d6))) * (c - b);
  const double denom = 1.0 / (va + vb + vc);
  return a + ab * (vb * denom) + ac * (vc * denom);
}

SegmentTriangle closestSegmentTriangle(const Vec3& p0, const Vec3& p1, const Vec3& a, const Vec3& b, const Vec3& c) {
  SegmentTriangle best;
  best.distance = INFINITY;
  const auto consider = [&](double s, const Vec3& onSeg, const Vec3& onTri) {
    const double d = (onSeg - onTri).norm();
    if (d < best.distance) best = {s, onSeg, onTri, d};
  };
  // A segment crossing the face: distance 0 at the crossing.
  const Vec3 n = (b - a).cross(c - a);
  const double h0 = n.dot(p0 - a), h1 = n.dot(p1 - a);
  if ((h0 <= 0 && h1 >= 0) || (h0 >= 0 && h1 <= 0)) {
    if (h0 != h1) {
      const double s = h0 / (h0 - h1);
      const Vec3 x = p0 + s * (p1 - p0);
      const Vec3 onTri = closestPointTriangle(x, a, b, c);
      if ((onTri - x).squaredNorm() <= 1e-24 * std::max(1.0, n.norm())) return {s, x, x, 0.0};
    }
  }
  consider(0, p0, closestPointTriangle(p0, a, b, c));
  consider(1, p1, closestPointTriangle(p1, a, b, c));
  const Vec3* v[3] = {&a, &b, &c};
  for (int k = 0; k < 3; ++k) {
    const SegmentPair e = closestSegmentSegment(p0, p1, *v[k], *v[(k + 1) % 3]);
    consider(e.s, e.p, e.q);
  }
  return best;
}

}  // namespace coilsim
