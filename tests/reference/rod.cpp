// Discretisation, rest shape and elastic energy of the reference rod (rod.h).
#include "rod.h"

#include <cmath>
#include <stdexcept>

#include "jet.h"

namespace refrod {

Section wireSection(double r, double E, double nu, double rho, double rhoFluid, const Vec3& g) {
  const double A = M_PI * r * r, I = M_PI * r * r * r * r / 4, G = E / (2 * (1 + nu));
  Section c;
  c.EA = E * A, c.GA = 0.9 * G * A;
  c.EI1 = c.EI2 = E * I, c.GJ = G * 2 * I;
  c.mu = rho * A;
  c.weight = (rho - rhoFluid) * A * g;
  c.radius = r;
  return c;
}

Section tubeSection(double rOut, double rIn, double Et, double nut, double rhoT, const Section& coil,
                    double coilRadius, double coilRho, double rhoFluid, const Vec3& g) {
  const double A = M_PI * (rOut * rOut - rIn * rIn);
  const double I = M_PI * (std::pow(rOut, 4) - std::pow(rIn, 4)) / 4, G = Et / (2 * (1 + nut));
  const double Ac = M_PI * coilRadius * coilRadius;
  Section t;
  // The coil slides inside: it adds bending and twist stiffness and weight,
  // its axial stiffness is irrelevant (the tube's own is already stiff).
  t.EA = Et * A, t.GA = 0.9 * G * A;
  t.EI1 = Et * I + coil.EI1, t.EI2 = Et * I + coil.EI2, t.GJ = G * 2 * I + coil.GJ;
  t.mu = rhoT * A + coilRho * Ac;
  t.weight = ((rhoT - rhoFluid) * A + (coilRho - rhoFluid) * Ac) * g;
  t.radius = rOut;
  return t;
}

Quat RodSpec::clampFrame(double twist) const {
  const Vec3 d3 = direction.normalized();
  const Vec3 d1 = (normal - normal.dot(d3) * d3).normalized();
  Mat3 R;
  R.col(0) = d1, R.col(1) = d3.cross(d1), R.col(2) = d3;
  return Quat(Eigen::AngleAxisd(twist, d3)) * Quat(R);
}

namespace {
Mat3 hat(const Vec3& w) {
  Mat3 W;
  W << 0, -w.z(), w.y(), w.z(), 0, -w.x(), -w.y(), w.x(), 0;
  return W;
}
}  // namespace

Vec3 restPosition(const RodSpec& spec, double s) {
  if (s < 0) return Vec3(0, 0, s);
  // x(s) = int_0^s exp(t W) e3 dt in closed form (Rodrigues integrated).
  const Vec3& om = spec.restDarboux;
  const double w = om.norm();
  const Mat3 W = hat(om);
  Mat3 P;
  if (w * s < 1e-4) {
    P = s * Mat3::Identity() + s * s / 2 * W + s * s * s / 6 * W * W;
  } else {
    P = s * Mat3::Identity() + (1 - std::cos(w * s)) / (w * w) * W + (w * s - std::sin(w * s)) / (w * w * w) * W * W;
  }
  return P * Vec3::UnitZ();
}

Quat restFrame(const RodSpec& spec, double s) {
  const double w = spec.restDarboux.norm();
  if (s <= 0 || w == 0) return Quat::Identity();
  return Quat(Eigen::AngleAxisd(w * s, spec.restDarboux / w));
}

namespace {

int tubeNodes(const RodSpec& spec) { return spec.tubeLength > 0 ? spec.tubeEdges + 1 : 1; }

// Index of the node at s = 0 (the catheter tip or the tube's end).
int junction(const RodSpec& spec) { return tubeNodes(spec) - 1; }

// s of the middle of edge k (k >= 1), or of node 0 for the clamp frame.
double frameS(const Rod& rod, int k) { return k == 0 ? rod.s[0] : 0.5 * (rod.s[k - 1] + rod.s[k]); }
double edgeLength(const Rod& rod, int k) { return k == 0 ? 0.0 : rod.s[k] - rod.s[k - 1]; }

}  // namespace

Rod initialRod(const RodSpec& spec, double l, double twist) {
  const double h = spec.h();
  if (!(l >= 1.5 * h && l <= spec.length * (1 + 1e-12)))
    throw std::invalid_argument("initialRod: deployed length outside [1.5 h, L]");
  Rod rod;
  rod.deployed = l, rod.twist = twist;
  const int nt = tubeNodes(spec);
  for (int k = 0; k < nt; ++k) {
    rod.s.push_back(nt == 1 ? 0.0 : -spec.tubeLength + k * spec.tubeLength / spec.tubeEdges);
    rod.key.push_back(-1 - k);
    rod.fixed.push_back(k == 0);
    rod.section.push_back(k == 0 ? -1 : 1);
  }
  // Coil nodes that have left the catheter by at least half an edge, tip outward.
  const int jmax = std::min(spec.coilEdges, int(std::floor((l - 0.5 * h) / h + 1e-9)));
  for (int j = jmax; j >= 0; --j) {
    rod.s.push_back(l - j * h);
    rod.key.push_back(j);
    rod.fixed.push_back(0);
    rod.section.push_back(0);
  }
  const Quat Rc = spec.clampFrame(twist);
  const int n = rod.nodes();
  rod.x.resize(n), rod.v.assign(n, Vec3::Zero()), rod.a.assign(n, Vec3::Zero()), rod.q.resize(n);
  for (int k = 0; k < n; ++k) {
    rod.x[k] = spec.tip + Rc * restPosition(spec, rod.s[k]);
    rod.q[k] = Rc * restFrame(spec, frameS(rod, k));
  }
  return rod;
}

void setDeployment(const RodSpec& spec, Rod& rod, double l, double twist) {
  const double h = spec.h();
  if (l < rod.deployed - 1e-15 || l > spec.length * (1 + 1e-12))
    throw std::invalid_argument("setDeployment: deployed length must grow and stay within L");
  const int J = junction(spec);
  for (int k = J + 1; k < rod.nodes(); ++k) rod.s[k] = l - rod.key[k] * h;
  // Release material points that are now at least h/2 outside the tip.
  for (int j = rod.key[J + 1] + 1; j <= spec.coilEdges && j * h <= l - 0.5 * h + 1e-9 * h; ++j) {
    const double sNew = l - j * h;
    const double f = sNew / rod.s[J + 1];  // along the first edge, which already spans it
    // The new node and the two edges beside it start on the rest shape seen
    // from the junction frame (a chord would bend them by the sagitta and
    // give Newton, or the dynamics, a needless kick).
    const Quat F = rod.q[J];
    const auto at = [&](auto& vec, auto val) { vec.insert(vec.begin() + J + 1, val); };
    at(rod.s, sNew);
    at(rod.key, j);
    at(rod.fixed, char(0));
    at(rod.section, 0);
    at(rod.x, Vec3(rod.x[J] + F * restPosition(spec, sNew)));
    at(rod.v, Vec3(rod.v[J] + f * (rod.v[J + 1] - rod.v[J])));
    at(rod.a, Vec3(rod.a[J] + f * (rod.a[J + 1] - rod.a[J])));
    at(rod.q, Quat(F * restFrame(spec, 0.5 * sNew)));
    rod.q[J + 2] = F * restFrame(spec, 0.5 * (sNew + rod.s[J + 2]));
  }
  rod.deployed = l;
  rod.twist = twist;
  rod.q[0] = spec.clampFrame(twist);
}

Dofs numberDofs(const Rod& rod) {
  Dofs d;
  const int n = rod.nodes();
  d.node.assign(n, -1), d.frame.assign(n, -1);
  // Interleaved node and frame unknowns keep the matrix banded along the rod.
  for (int k = 0; k < n; ++k) {
    if (!rod.fixed[k]) d.node[k] = d.count, d.count += 3;
    if (k > 0) d.frame[k] = d.count, d.count += 3;
  }
  return d;
}

namespace {

using J6 = Jet<6>;
template <class T>
struct Q {
  T w, x, y, z;
};
template <class T, class U>
auto mul(const Q<T>& a, const Q<U>& b) {
  using R = decltype(a.w * b.w);
  return Q<R>{a.w * b.w - a.x * b.x - a.y * b.y - a.z * b.z, a.w * b.x + a.x * b.w + a.y * b.z - a.z * b.y,
              a.w * b.y - a.x * b.z + a.y * b.w + a.z * b.x, a.w * b.z + a.x * b.y - a.y * b.x + a.z * b.w};
}
Q<double> toQ(const Quat& q) { return {q.w(), q.x(), q.y(), q.z()}; }

// Cayley quaternion (1, w/2) / |(1, w/2)| of the jet variables w = vars [i0, i0+3).
Q<J6> cayley(int i0) {
  const J6 wx = J6::variable(i0, 0), wy = J6::variable(i0 + 1, 0), wz = J6::variable(i0 + 2, 0);
  const J6 n = rsqrt(1.0 + 0.25 * (wx * wx + wy * wy + wz * wz));
  return {n, 0.5 * wx * n, 0.5 * wy * n, 0.5 * wz * n};
}

// Scatters a local 6-variable element (two blocks of 3) into the global system.
// Each block maps to up to two global blocks with a sign (+1, -1), or none.
struct Block {
  int dof[2] = {-1, -1};
  double sign[2] = {0, 0};
};
void scatter(const J6& e, const Block (&b)[2], Eigen::VectorXd* g, Triplets* H) {
  for (int bi = 0; bi < 2; ++bi)
    for (int ti = 0; ti < 2; ++ti) {
      const int gi = b[bi].dof[ti];
      if (gi < 0) continue;
      if (g) g->segment<3>(gi) += b[bi].sign[ti] * e.g.segment<3>(3 * bi);
      if (!H) continue;
      for (int bj = 0; bj < 2; ++bj)
        for (int tj = 0; tj < 2; ++tj) {
          const int gj = b[bj].dof[tj];
          if (gj < 0) continue;
          const double sg = b[bi].sign[ti] * b[bj].sign[tj];
          for (int r = 0; r < 3; ++r)
            for (int c = 0; c < 3; ++c) H->emplace_back(gi + r, gj + c, sg * e.H(3 * bi + r, 3 * bj + c));
        }
    }
}

const Section& sectionOf(const RodSpec& spec, const Rod& rod, int k) {
  return rod.section[k] == 1 ? spec.tube : spec.coil;
}

// Stretch and shear of edge k: gamma = R^T (x_k - x_{k-1}) / l0 - gamma0 with
// gamma0 the same measure on the rest shape, so the rest shape is exactly
// stress-free; energy l0/2 (GA g1^2 + GA g2^2 + EA g3^2).
double stretchEnergy(const RodSpec& spec, const Rod& rod, const Dofs& dofs, int k, Eigen::VectorXd* g, Triplets* H) {
  const double l0 = edgeLength(rod, k);
  const Section& c = sectionOf(spec, rod, k);
  const Quat q0 = restFrame(spec, frameS(rod, k));
  const Vec3 gamma0 =
      q0.conjugate() * (restPosition(spec, rod.s[k]) - restPosition(spec, rod.s[k - 1])) / l0;
  const Vec3 dv = rod.x[k] - rod.x[k - 1];
  const double K[3] = {c.GA, c.GA, c.EA};
  if (!g && !H) {  // energy only (line search): plain doubles
    const Vec3 gam = rod.q[k].conjugate() * dv / l0 - gamma0;
    return 0.5 * l0 * (K[0] * gam[0] * gam[0] + K[1] * gam[1] * gam[1] + K[2] * gam[2] * gam[2]);
  }
  const Mat3 Rt = rod.q[k].toRotationMatrix().transpose();
  J6 d[3] = {J6::variable(0, dv.x()), J6::variable(1, dv.y()), J6::variable(2, dv.z())};
  J6 w[3] = {J6::variable(3, 0), J6::variable(4, 0), J6::variable(5, 0)};
  // Cay(w)^T d = d + c (-(w x d) + (w x (w x d)) / 2), c = 1 / (1 + |w|^2 / 4).
  const J6 cf = inverse(1.0 + 0.25 * (w[0] * w[0] + w[1] * w[1] + w[2] * w[2]));
  const auto cross = [](const J6* a, const J6* b, J6* r) {
    r[0] = a[1] * b[2] - a[2] * b[1], r[1] = a[2] * b[0] - a[0] * b[2], r[2] = a[0] * b[1] - a[1] * b[0];
  };
  J6 wd[3], wwd[3], cd[3];
  cross(w, d, wd);
  cross(w, wd, wwd);
  for (int i = 0; i < 3; ++i) cd[i] = d[i] + cf * (0.5 * wwd[i] - wd[i]);
  J6 e;
  for (int i = 0; i < 3; ++i) {
    const J6 gi = (1.0 / l0) * (Rt(i, 0) * cd[0] + Rt(i, 1) * cd[1] + Rt(i, 2) * cd[2]) - gamma0[i];
    e = e + (0.5 * l0 * K[i]) * gi * gi;
  }
  Block b[2];
  b[0].dof[0] = dofs.node[k], b[0].sign[0] = 1;
  b[0].dof[1] = dofs.node[k - 1], b[0].sign[1] = -1;
  b[1].dof[0] = dofs.frame[k], b[1].sign[0] = 1;
  scatter(e, b, g, H);
  return e.v;
}

// Bend and twist between frames k and k+1: kappa = 2 vec(q_k^* q_{k+1}) / D,
// the rotation vector's sine measure per Voronoi length D; energy
// D/2 sum K_i (kappa_i - kappa0_i)^2 with the stiffness of the two half edges
// in series (exact where the section changes: tube to coil).
double bendEnergy(const RodSpec& spec, const Rod& rod, const Dofs& dofs, int k, Eigen::VectorXd* g, Triplets* H) {
  const double la = edgeLength(rod, k), lb = edgeLength(rod, k + 1), D = 0.5 * (la + lb);
  const Section& cb = sectionOf(spec, rod, k + 1);
  const Section& ca = k == 0 ? cb : sectionOf(spec, rod, k);
  const double Ka[3] = {ca.EI1, ca.EI2, ca.GJ}, Kb[3] = {cb.EI1, cb.EI2, cb.GJ};
  Quat r0 = restFrame(spec, frameS(rod, k)).conjugate() * restFrame(spec, frameS(rod, k + 1));
  if (r0.w() < 0) r0.coeffs() *= -1;
  const Vec3 kappa0 = 2 * r0.vec() / D;
  if (!g && !H) {  // energy only (line search): plain doubles
    Quat r = rod.q[k].conjugate() * rod.q[k + 1];
    if (r.w() < 0) r.coeffs() *= -1;
    const Vec3 dk = 2 * r.vec() / D - kappa0;
    double e = 0;
    for (int i = 0; i < 3; ++i) e += 0.5 * D * D / (0.5 * la / Ka[i] + 0.5 * lb / Kb[i]) * dk[i] * dk[i];
    return e;
  }
  const auto Ca = cayley(0), Cb = cayley(3);
  const Q<J6> CaConj{Ca.w, -Ca.x, -Ca.y, -Ca.z};
  const Q<double> qa = toQ(rod.q[k]), qaConj{qa.w, -qa.x, -qa.y, -qa.z}, qb = toQ(rod.q[k + 1]);
  Q<J6> r = mul(mul(qaConj, mul(CaConj, Cb)), qb);
  if (r.w.v < 0) r = {-r.w, -r.x, -r.y, -r.z};
  const J6 kap[3] = {(2 / D) * r.x, (2 / D) * r.y, (2 / D) * r.z};
  J6 e;
  for (int i = 0; i < 3; ++i) {
    const double K = D / (0.5 * la / Ka[i] + 0.5 * lb / Kb[i]);
    const J6 dk = kap[i] - kappa0[i];
    e = e + (0.5 * D * K) * dk * dk;
  }
  Block b[2];
  b[0].dof[0] = dofs.frame[k], b[0].sign[0] = 1;
  b[1].dof[0] = dofs.frame[k + 1], b[1].sign[0] = 1;
  scatter(e, b, g, H);
  return e.v;
}

}  // namespace

double elasticEnergy(const RodSpec& spec, const Rod& rod, const Dofs& dofs, Eigen::VectorXd* g, Triplets* H) {
  double e = 0;
  const int n = rod.nodes();
  for (int k = 1; k < n; ++k) e += stretchEnergy(spec, rod, dofs, k, g, H);
  for (int k = 0; k + 1 < n; ++k) e += bendEnergy(spec, rod, dofs, k, g, H);
  // Gravity minus buoyancy, lumped half an edge to each end node: -F . (x - tip).
  for (int k = 1; k < n; ++k) {
    const Vec3 F = 0.5 * edgeLength(rod, k) * sectionOf(spec, rod, k).weight;
    for (const int i : {k - 1, k}) {
      e -= F.dot(rod.x[i] - spec.tip);
      if (g && dofs.node[i] >= 0) g->segment<3>(dofs.node[i]) -= F;
    }
  }
  // End load: potential -F . (x_n + R_n b); with c = R_n b, the rotation
  // increment w enters as -F . (Cay(w) c): gradient -(c x F), Hessian
  // (F . c) I - (F c^T + c F^T) / 2.
  if (spec.endForce.squaredNorm() > 0) {
    const int k = n - 1;
    const Vec3& F = spec.endForce;
    const Vec3 c = rod.q[k] * spec.endArm;
    e -= F.dot(rod.x[k] + c - spec.tip);
    if (g && dofs.node[k] >= 0) g->segment<3>(dofs.node[k]) -= F;
    if (dofs.frame[k] >= 0) {
      const int i = dofs.frame[k];
      if (g) g->segment<3>(i) -= c.cross(F);
      if (H) {
        const Mat3 B = F.dot(c) * Mat3::Identity() - 0.5 * (F * c.transpose() + c * F.transpose());
        for (int r = 0; r < 3; ++r)
          for (int cc = 0; cc < 3; ++cc) H->emplace_back(i + r, i + cc, B(r, cc));
      }
    }
  }
  return e;
}

std::vector<double> nodeMasses(const RodSpec& spec, const Rod& rod) {
  std::vector<double> m(rod.nodes(), 0.0);
  for (int k = 1; k < rod.nodes(); ++k) {
    const double half = 0.5 * edgeLength(rod, k) * sectionOf(spec, rod, k).mu;
    m[k - 1] += half, m[k] += half;
  }
  return m;
}

void applyStep(Rod& rod, const Dofs& dofs, const Eigen::VectorXd& p, double alpha) {
  for (int k = 0; k < rod.nodes(); ++k) {
    if (dofs.node[k] >= 0) rod.x[k] += alpha * p.segment<3>(dofs.node[k]);
    if (dofs.frame[k] >= 0) {
      const Vec3 w = alpha * p.segment<3>(dofs.frame[k]);
      const Quat c = Quat(1, 0.5 * w.x(), 0.5 * w.y(), 0.5 * w.z()).normalized();
      rod.q[k] = (c * rod.q[k]).normalized();
    }
  }
}

std::vector<Vec3> centerline(const Rod& rod, std::vector<double>* s) {
  std::vector<Vec3> out;
  if (s) s->clear();
  for (int k = 0; k < rod.nodes(); ++k) {
    if (rod.s[k] < -1e-15) continue;
    out.push_back(rod.x[k]);
    if (s) s->push_back(std::max(0.0, rod.s[k]));
  }
  return out;
}

}  // namespace refrod
