// Newton minimiser and continuation along the deployment (solver.h).
#include <Eigen/SparseCholesky>
#include <algorithm>
#include <cmath>

#include "solver.h"

namespace refrod {

double totalEnergy(const RodSpec& spec, const Rod& rod, const Dofs& dofs, const Inertia* in, Eigen::VectorXd* g,
                   Triplets* H) {
  double e = elasticEnergy(spec, rod, dofs, g, H) + contactEnergy(spec, rod, dofs, g, H);
  if (!in) return e;
  for (int k = 0; k < rod.nodes(); ++k) {
    const int i = dofs.node[k];
    if (i < 0) continue;
    const Vec3 dx = rod.x[k] - in->xt[k];
    const Vec3 v = in->vt[k] + in->kv * dx;
    e += 0.5 * in->kM * in->m[k] * dx.squaredNorm() + v.dot(in->C[k] * v) / (2 * in->kv);
    if (g) g->segment<3>(i) += in->kM * in->m[k] * dx + in->C[k] * v;
    if (H) {
      const Mat3 B = in->kM * in->m[k] * Mat3::Identity() + in->kv * in->C[k];
      for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) H->emplace_back(i + r, i + c, B(r, c));
    }
  }
  return e;
}

SolveReport minimise(const RodSpec& spec, Rod& rod, const Inertia* in, int maxIterations) {
  SolveReport rep;
  const Dofs dofs = numberDofs(rod);
  const int n = dofs.count;
  Eigen::VectorXd g(n), p(n);
  Triplets trip;
  Eigen::SparseMatrix<double> H(n, n);
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt;
  double lambda = 0;  // Levenberg shift, relative to the diagonal
  for (int it = 0; it < maxIterations; ++it) {
    rep.iterations = it + 1;
    g.setZero();
    trip.clear();
    const double e0 = totalEnergy(spec, rod, dofs, in, &g, &trip);
    if (!std::isfinite(e0) || !g.allFinite()) {
      rep.message = "energy or gradient not finite";
      return rep;
    }
    H.setFromTriplets(trip.begin(), trip.end());
    const Eigen::VectorXd diag = H.diagonal().cwiseAbs().array() + 1e-300;
    // Shift until the factorisation is positive definite: a descent direction.
    for (int tries = 0;; ++tries) {
      Eigen::SparseMatrix<double> A = H;
      if (lambda > 0)
        for (int i = 0; i < n; ++i) A.coeffRef(i, i) += lambda * diag[i];
      // Contact changes the pattern between iterations: analyse every time.
      ldlt.analyzePattern(A);
      ldlt.factorize(A);
      if (ldlt.info() == Eigen::Success && (ldlt.vectorD().array() > 0).all()) {
        p = -ldlt.solve(g);
        break;
      }
      lambda = lambda == 0 ? 1e-8 : lambda * 10;
      if (tries > 40) {
        rep.message = "no positive definite shift found";
        return rep;
      }
    }
    const double slope = g.dot(p);
    // Converged when the Newton step is below roundoff level (positions in m,
    // rotations in rad) or the predicted decrease -g.p (twice the energy still
    // to gain) is at roundoff level relative to the energy: the gradient
    // itself never falls below ~1e-16 EA, which soft rotations amplify.
    double px = 0, pw = 0;
    for (int k = 0; k < rod.nodes(); ++k) {
      if (dofs.node[k] >= 0) px = std::max(px, p.segment<3>(dofs.node[k]).cwiseAbs().maxCoeff());
      if (dofs.frame[k] >= 0) pw = std::max(pw, p.segment<3>(dofs.frame[k]).cwiseAbs().maxCoeff());
    }
    if (lambda <= 1e-4 && ((px < 1e-12 && pw < 1e-10) || -slope < 1e-13 * std::abs(e0) + 1e-30)) {
      applyStep(rod, dofs, p, 1.0);
      rep.converged = true;
      return rep;
    }
    // Armijo backtracking on the energy.
    double alpha = 1;
    bool accepted = false;
    for (int ls = 0; ls < 40; ++ls, alpha *= 0.5) {
      Rod trial = rod;
      applyStep(trial, dofs, p, alpha);
      const double e1 = totalEnergy(spec, trial, dofs, in, nullptr, nullptr);
      if (std::isfinite(e1) && e1 <= e0 + 1e-4 * alpha * slope) {
        rod = std::move(trial);
        accepted = true;
        break;
      }
    }
    if (!accepted) {
      if (-slope < 1e-10 * std::abs(e0) + 1e-30) {  // roundoff: nothing left to gain
        rep.converged = true;
        return rep;
      }
      lambda = std::max(lambda * 10, 1e-6);
      continue;
    }
    lambda = lambda < 1e-9 ? 0 : lambda / 10;
  }
  rep.message = "Newton did not converge in " + std::to_string(maxIterations) + " iterations";
  return rep;
}

SolveReport pushStatic(const RodSpec& spec, Rod& rod, double l, double twist, double dl) {
  SolveReport rep;
  const double l0 = rod.deployed, t0 = rod.twist;
  // At most one edge per increment: the predictor below then leaves Newton
  // a small correction, and at most one node is released at a time.
  dl = std::min(dl, spec.h());
  const int steps = std::max(1, int(std::ceil((l - l0) / dl - 1e-9)));
  for (int i = 1; i <= steps; ++i) {
    const double f = double(i) / steps;
    // Predictor: the deployed coil moves as a whole by the screw motion that
    // carries the rest shape's frame at s = 0 to s = step (exact for an
    // unloaded helix or straight rod), so the first edge keeps its length and
    // Newton only corrects for the changed loads. Without it the first edge
    // is compressed by the increment and Newton needs tens of iterations.
    const double step = l0 + f * (l - l0) - rod.deployed;
    int J = 0;
    while (rod.key[J + 1] < 0) ++J;
    const Quat F = rod.q[J];
    const Quat Q = F * restFrame(spec, step) * F.conjugate();
    const Vec3 p = rod.x[J], shift = F * restPosition(spec, step);
    for (int k = J + 1; k < rod.nodes(); ++k) {
      rod.x[k] = p + shift + Q * (rod.x[k] - p);
      rod.q[k] = (Q * rod.q[k]).normalized();
    }
    setDeployment(spec, rod, l0 + f * (l - l0), t0 + f * (twist - t0));
    SolveReport r = minimise(spec, rod);
    rep.iterations += r.iterations;
    if (!r.converged) {
      rep.message = "static push failed at l = " + std::to_string(rod.deployed * 1e3) + " mm: " + r.message;
      return rep;
    }
  }
  rep.converged = true;
  return rep;
}

Rod deployStatic(const RodSpec& spec, double l, double twist, double dl, SolveReport* report) {
  Rod rod = initialRod(spec, std::min(l, 2 * spec.h()), twist);
  SolveReport r = minimise(spec, rod);
  if (r.converged) r = pushStatic(spec, rod, l, twist, dl);
  if (report) *report = r;
  return rod;
}

}  // namespace refrod
