// Implicit Newmark time stepping of the reference rod with resistive-force
// drag (solver.h). Rotary inertia of the wire is neglected (rho I per length
// is r^2/4 of rho A: 1e-8 m^2 for these wires), so the frames stay in
// equilibrium at every step and only positions carry inertia.
#include <cmath>

#include "solver.h"

namespace refrod {

void historyAt(const std::vector<PushSample>& h, double t, double& l, double& twist) {
  if (t <= h.front().t) {
    l = h.front().l, twist = h.front().twist;
    return;
  }
  for (size_t i = 1; i < h.size(); ++i)
    if (t <= h[i].t) {
      const double f = (t - h[i - 1].t) / (h[i].t - h[i - 1].t);
      l = h[i - 1].l + f * (h[i].l - h[i - 1].l), twist = h[i - 1].twist + f * (h[i].twist - h[i - 1].twist);
      return;
    }
  l = h.back().l, twist = h.back().twist;
}

double kineticEnergy(const RodSpec& spec, const Rod& rod) {
  const std::vector<double> m = nodeMasses(spec, rod);
  double e = 0;
  for (int k = 0; k < rod.nodes(); ++k) e += 0.5 * m[k] * rod.v[k].squaredNorm();
  return e;
}

SolveReport stepDynamic(const RodSpec& spec, Rod& rod, double dt, double l, double twist, const Newmark& nm) {
  setDeployment(spec, rod, l, twist);
  const int n = rod.nodes();
  Inertia in;
  in.kM = 1 / (nm.beta * dt * dt), in.kv = nm.gamma / (nm.beta * dt);
  in.m = nodeMasses(spec, rod);
  in.xt.resize(n), in.vt.resize(n), in.C.assign(n, Mat3::Zero());
  for (int k = 0; k < n; ++k) {
    in.xt[k] = rod.x[k] + dt * rod.v[k] + dt * dt * (0.5 - nm.beta) * rod.a[k];
    in.vt[k] = rod.v[k] + dt * (1 - nm.gamma) * rod.a[k];
  }
  // Resistive-force theory on the coil: f = -(c_n (I - t t^T) + c_t t t^T) v per
  // length, tangent and length taken at the start of the step (linear in v).
  for (int k = 1; k < n; ++k) {
    if (rod.section[k] != 0) continue;
    const Vec3 e = rod.x[k] - rod.x[k - 1];
    const double len = e.norm();
    const Vec3 t = e / len;
    const Mat3 D = 0.5 * len * (spec.dragNormal * (Mat3::Identity() - t * t.transpose()) + spec.dragTangent * t * t.transpose());
    in.C[k - 1] += D, in.C[k] += D;
  }
  SolveReport r = minimise(spec, rod, &in);
  if (!r.converged) return r;
  for (int k = 0; k < n; ++k) {
    if (rod.fixed[k]) continue;
    rod.a[k] = in.kM * (rod.x[k] - in.xt[k]);
    rod.v[k] = in.vt[k] + dt * nm.gamma * rod.a[k];
  }
  return r;
}

SolveReport pushDynamic(const RodSpec& spec, Rod& rod, const std::vector<PushSample>& history, double tCapture,
                        double dt, const Newmark& nm) {
  SolveReport rep;
  const int steps = int(std::llround((tCapture - history.front().t) / dt));
  for (int i = 1; i <= steps; ++i) {
    double l, tw;
    historyAt(history, history.front().t + i * dt, l, tw);
    const SolveReport r = stepDynamic(spec, rod, dt, l, tw, nm);
    rep.iterations += r.iterations;
    if (!r.converged) {
      rep.message = "dynamic step " + std::to_string(i) + " failed: " + r.message;
      return rep;
    }
  }
  rep.converged = true;
  return rep;
}

}  // namespace refrod
