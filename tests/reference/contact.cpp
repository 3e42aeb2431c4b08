// Self-contact of the reference rod: a smooth repulsive potential between
// quadrature points of non-adjacent coil edges (deliberately not coilsim's
// capsule penalty). Each edge carries points about one wire radius apart;
// two points closer than the wire diameter 2r repel with
//   phi = k w (2r - d)^3 / 3,  w = ds_p ds_q / (2r)^2,
// C2 in the distance, so Newton sees a continuous Hessian. The weight w
// makes the force per length of two touching wires independent of the grid.
#include <cmath>

#include "rod.h"

namespace refrod {

namespace {
struct Point {
  int a, b;      // end nodes of its edge
  double t;      // x = (1 - t) x_a + t x_b
  double s, ds;  // arc length and weight
  Vec3 x;
};
}  // namespace

double contactEnergy(const RodSpec& spec, const Rod& rod, const Dofs& dofs, Eigen::VectorXd* g, Triplets* H) {
  if (!spec.contact) return 0;
  const double r = spec.coil.radius, dc = 2 * r;
  // Points nearer than this along the rod never count: bending keeps them apart.
  const double exclude = std::max(10 * r, 2 * spec.h());
  std::vector<Point> pts;
  std::vector<int> first;  // per edge k (coil only), index of its first point
  std::vector<int> edges;
  for (int k = 1; k < rod.nodes(); ++k) {
    if (rod.section[k] != 0) continue;
    const double l = rod.s[k] - rod.s[k - 1];
    const int m = std::max(1, int(std::ceil(l / r)));
    edges.push_back(k);
    first.push_back(int(pts.size()));
    for (int i = 0; i < m; ++i) {
      const double t = (i + 0.5) / m;
      pts.push_back({k - 1, k, t, rod.s[k - 1] + t * l, l / m, (1 - t) * rod.x[k - 1] + t * rod.x[k]});
    }
  }
  first.push_back(int(pts.size()));
  double e = 0;
  const double kc = spec.contactStiffness;
  for (size_t ei = 0; ei < edges.size(); ++ei) {
    const int ka = edges[ei];
    const Vec3 ma = 0.5 * (rod.x[ka - 1] + rod.x[ka]);
    const double ra = 0.5 * (rod.x[ka] - rod.x[ka - 1]).norm();
    for (size_t ej = ei + 1; ej < edges.size(); ++ej) {
      const int kb = edges[ej];
      const double rb = 0.5 * (rod.x[kb] - rod.x[kb - 1]).norm();
      // Bounding spheres of the two edges first: most pairs end here.
      if ((0.5 * (rod.x[kb - 1] + rod.x[kb]) - ma).norm() > ra + rb + dc) continue;
      for (int ip = first[ei]; ip < first[ei + 1]; ++ip)
        for (int iq = first[ej]; iq < first[ej + 1]; ++iq) {
          const Point &p = pts[ip], &q = pts[iq];
          if (std::abs(p.s - q.s) < exclude) continue;
          const Vec3 dv = p.x - q.x;
          const double d = dv.norm();
          if (d >= dc || d == 0) continue;
          const double w = kc * p.ds * q.ds / (dc * dc), del = dc - d;
          e += w * del * del * del / 3;
          const Vec3 n = dv / d;
          const Vec3 Fp = -w * del * del * n;  // gradient of phi with respect to p
          const Mat3 Hpp = w * (2 * del * n * n.transpose() - del * del / d * (Mat3::Identity() - n * n.transpose()));
          const int idx[4] = {dofs.node[p.a], dofs.node[p.b], dofs.node[q.a], dofs.node[q.b]};
          const double wt[4] = {1 - p.t, p.t, -(1 - q.t), -q.t};  // dp/dx and -dq/dx
          for (int i = 0; i < 4; ++i) {
            if (idx[i] < 0) continue;
            if (g) g->segment<3>(idx[i]) += wt[i] * Fp;
            if (!H) continue;
            for (int j = 0; j < 4; ++j) {
              if (idx[j] < 0) continue;
              for (int rr = 0; rr < 3; ++rr)
                for (int cc = 0; cc < 3; ++cc) H->emplace_back(idx[i] + rr, idx[j] + cc, wt[i] * wt[j] * Hpp(rr, cc));
            }
          }
        }
    }
  }
  return e;
}

}  // namespace refrod
