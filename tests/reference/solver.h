#pragma once
// Equilibrium and time stepping of the reference rod: a damped Newton
// minimiser (statics.cpp), continuation along the deployment, and an implicit
// Newmark integrator written as the minimisation of an incremental potential
// (dynamics.cpp), so statics and dynamics share one solver.
#include <string>
#include <vector>

#include "rod.h"

namespace refrod {

// Newmark terms added to the energy in a dynamic step, per node:
//   kM m |x - xt|^2 / 2 + (v^T C v) / (2 kv),  v = vt + kv (x - xt),
// whose gradient is m a_{n+1} + C v_{n+1} (inertia and linear drag).
struct Inertia {
  double kM = 0, kv = 0;
  std::vector<double> m;   // per node (kg)
  std::vector<Vec3> xt;    // per node: predicted position (m)
  std::vector<Vec3> vt;    // per node: predicted velocity (m/s)
  std::vector<Mat3> C;     // per node: drag matrix (N s/m)
};

struct SolveReport {
  bool converged = false;
  int iterations = 0;
  std::string message;  // why it failed, empty when converged
};

// Minimises elastic + gravity + contact (+ inertia) energy from the current
// rod by Newton's method with a Levenberg shift (until the factorisation is
// positive definite) and Armijo backtracking, so it goes to a nearby local
// minimum, never a saddle. On failure the rod holds the last iterate and the
// report says why.
SolveReport minimise(const RodSpec& spec, Rod& rod, const Inertia* inertia = nullptr, int maxIterations = 200);

// Total energy of the rod (J), optionally with gradient and Hessian.
double totalEnergy(const RodSpec& spec, const Rod& rod, const Dofs& dofs, const Inertia* inertia,
                   Eigen::VectorXd* g, Triplets* H);

// A slow push: continues the equilibrium from the rod's deployed length and
// twist to (l, twist) in increments of at most dl (and at most one edge),
// one equilibrium each, the deployed coil first moved out along its rest
// shape. On failure the report names the deployed length.
SolveReport pushStatic(const RodSpec& spec, Rod& rod, double l, double twist, double dl);

// Equilibrium at (l, twist) reached by a slow push from the shortest deployment.
Rod deployStatic(const RodSpec& spec, double l, double twist, double dl, SolveReport* report = nullptr);

struct PushSample {
  double t, l, twist;  // s, m, rad
};
// Deployed length and twist of a history at time t (linear, held outside).
void historyAt(const std::vector<PushSample>& h, double t, double& l, double& twist);

// Newmark parameters; gamma > 1/2 with beta = (gamma + 1/2)^2 / 4 damps the
// unresolved stiff (stretch) modes, gamma = 1/2, beta = 1/4 is the energy
// conserving trapezoidal rule.
struct Newmark {
  double beta = 0.3025, gamma = 0.6;
};

// One implicit step of dt from the rod's state, the deployment first moved
// to (l, twist). Velocities and accelerations are updated.
SolveReport stepDynamic(const RodSpec& spec, Rod& rod, double dt, double l, double twist, const Newmark& nm);

// From the static equilibrium at the history's first sample, follows the
// history with steps dt up to tCapture.
SolveReport pushDynamic(const RodSpec& spec, Rod& rod, const std::vector<PushSample>& history, double tCapture,
                        double dt, const Newmark& nm);

// Kinetic energy (J) of the nodes.
double kineticEnergy(const RodSpec& spec, const Rod& rod);

}  // namespace refrod
