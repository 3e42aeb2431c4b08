#include <chrono>
#include <cmath>

#include "physics/assembly.h"
#include "physics/integrator.h"
#include "physics/pair_contact_set.h"
#include "physics/pair_coupling.h"
#include "physics/sleep.h"

namespace coilsim {
namespace {

void saveStart(RodState& r) {
  RodWorkspace& w = r.work;
  w.x0 = r.x, w.q0 = r.q, w.v0 = r.v, w.w0 = r.w;
  w.targets0 = r.targets;
}

// The poses and velocities of the step's start (its targets stay advanced).
void restorePoses(RodState& r) {
  const RodWorkspace& w = r.work;
  r.x = w.x0, r.q = w.q0, r.v = w.v0, r.w = w.w0;
}

void restoreStart(RodState& r) {
  restorePoses(r);
  r.targets = r.work.targets0;
}

// Generalised velocity each constrained node must have to reach its target
// at the end of the step.
void prescribedVelocities(const RodModel& rm, RodState& r, double h) {
  RodWorkspace& w = r.work;
  for (size_t k = 0; k < rm.constraints.size(); ++k) {
    const int i = rm.constraints[k].node;
    if (i >= r.activeNodes) continue;
    const Pose& t = r.targets[k];
    w.fixedValue[i].head<3>() = (t.position - w.x0[i]) / h;
    w.fixedValue[i].tail<3>() = quatLog(t.rotation * w.q0[i].conjugate()) / h;
  }
}

// Poses at the end of the step for the current velocity guess.
void integratePoses(RodState& r, double h) {
  const RodWorkspace& w = r.work;
  for (int i = 0; i < r.activeNodes; ++i) {
    r.x[i] = w.x0[i] + h * r.v[i];
    r.q[i] = (quatExp(h * r.w[i]) * w.q0[i]).normalized();
  }
}

// Newton iteration `it`'s implicit system of one rod in work.system and
// work.rhs, its fixed DOFs applied.
void buildSystem(const Model& model, int rodIndex, RodState& r, double time, double h, int it) {
  RodWorkspace& w = r.work;
  const double a = model.damping.massCoeff, b = model.damping.stiffnessCoeff;
  const int n = r.activeNodes;
  // The matrix starts as (h b + h^2) K, assembled in place together with
  // (h b + h^2) K vel for the right-hand side; the mass goes on after.
  for (int i = 0; i < n; ++i) w.velocity[i] << r.v[i], r.w[i];
  BlockTridiagonal& A = w.system;
  TangentRequest tangent{&A, h * b + h * h, &w.velocity, &w.stiffnessTimesVelocity};
  assembleRodInto(model, rodIndex, r, time + h, h, 1.0, tangent);
  // h (b + h) K vel in the first iteration, h b K vel after it.
  const double kRhs = h * (b + (it == 0 ? h : 0.0)) / tangent.scale;
  for (int i = 0; i < n; ++i) {
    const Vec6& vel = w.velocity[i];
    const double m = r.nodes[i].mass;
    const Mat3 inertia = nodeInertiaGlobal(r, w.q0[i], i);
    // Mass and Rayleigh mass damping act on translation and rotation separately.
    Vec6 massTimes;  // M (a vel) and, from the second iteration, M (vel - v0) / h
    massTimes.head<3>() = a * m * r.v[i];
    massTimes.tail<3>() = a * (inertia * r.w[i]);
    if (it > 0) {
      massTimes.head<3>() += m * (r.v[i] - w.v0[i]) / h;
      massTimes.tail<3>() += inertia * (r.w[i] - w.w0[i]) / h;
    }
    Vec6& rhs = w.rhs[i];
    rhs = h * (w.force[i] - massTimes) - kRhs * w.stiffnessTimesVelocity[i];
    Mat6& Ad = A.diag[i];
    Ad.topLeftCorner<3, 3>().diagonal().array() += (1 + h * a) * m;
    Ad.bottomRightCorner<3, 3>() += (1 + h * a) * inertia;
    // An effect's force already holds its own damping (-D v); D and K only
    // make the matrix implicit in them.
    if (w.effectsTouchedMatrix) {
      Ad += h * w.effectD[i] + h * h * w.effectK[i];
      if (it == 0) rhs.noalias() -= (h * h) * (w.effectK[i] * vel);
    }
  }
  for (int i = 0; i < n; ++i) {
    const unsigned m = w.fixedMask[i];
    if (!m) continue;
    for (int d = 0; d < 6; ++d)
      if (m & (1u << d)) applyDirichlet(A, w.rhs, i, d, w.fixedValue[i][d] - w.velocity[i][d], n);
  }
}

// Solves one rod's system alone: work.rhs becomes the velocity increment.
std::optional<Failure> solveSystem(const RodModel& rm, RodState& r, double h, int it, bool& recovered) {
  RodWorkspace& w = r.work;
  const int n = r.activeNodes;
  if (!w.unilateral.constraints.empty()) {
    recovered = recovered || it == 0;
    // Wall contacts held as constraints: an active-set solve on the same band (physics/unilateral.h).
    if (std::optional<Failure> f =
            solveUnilateral(w.system, w.rhs, n, h, &w.velocity, it == 0, w.fixedMask, w.solver, w.unilateral)) {
      f->rod = rm.name;
      return f;
    }
  } else if (!w.solver.factorize(w.system, n)) {
    Failure f = badRod(rm.name, "implicit matrix is not positive definite");
    f.kind = FailureKind::SolverFailure;
    return f;
  } else {
    w.solver.solve(w.rhs);
  }
  return std::nullopt;
}

void applyIncrement(RodState& r, double h) {
  const RodWorkspace& w = r.work;
  for (int i = 0; i < r.activeNodes; ++i) {
    r.v[i] += w.rhs[i].head<3>();
    r.w[i] += w.rhs[i].tail<3>();
  }
  integratePoses(r, h);
}

void finishRod(RodState& r, bool recovered) {
  RodWorkspace& w = r.work;
  if (w.unilateral.constraints.empty()) return;
  // A node that started the step inside a wall is carried out by the
  // step's positions, not by a velocity it keeps (the position
  // correction split from the velocity, as Bullet's split impulse):
  // kept, depth / h is kinetic energy the wall gives the coil, at every
  // step a sliding node meets the curved wall beyond its tangent plane,
  // and h / 64 in a retaken step's substeps (physics/unilateral.h).
  for (int i = 0; recovered && i < r.activeNodes; ++i) r.v[i] -= w.unilateral.recovery[i];
  // The wall's force per node is its constraints' multipliers, known only now.
  std::fill(r.contact.wallForce.begin(), r.contact.wallForce.end(), 0.0);
  for (const NodeConstraint& c : w.unilateral.constraints)
    if (c.force && size_t(c.node) < r.contact.wallForce.size()) r.contact.wallForce[c.node] += *c.force;
}

StepReport stepRod(const Model& model, int rodIndex, RodState& r, double time, double h, long& iterations) {
  const RodModel& rm = model.rods[rodIndex];
  collectFixedDofs(rm, r);
  prescribedVelocities(rm, r, h);
  bool recovered = false;  // the first iteration's solve held nodes (UnilateralScratch::recovery)
  for (int it = 0; it < model.newtonIterations; ++it) {
    ++iterations;
    buildSystem(model, rodIndex, r, time, h, it);
    if (std::optional<Failure> f = solveSystem(rm, r, h, it, recovered)) return {std::move(*f)};
    applyIncrement(r, h);
  }
  finishRod(r, recovered);
  return {};
}

bool stepped(const RodState& r) { return r.active && !r.asleep; }

// Whether this step solves its pair contacts with both sides moving
// (physics/pair_coupling.h): the model asks for it, some stepped rod has
// one, and no effect holds nodes by constraints (each rod's solve is then
// an active-set solve of its own, and the pairs are lumped).
bool couplesPairs(const Model& model, const State& state) {
  if (!model.coupledPairs) return false;
  for (const EffectUse& u : model.effects)
    if (u.enabled && u.effect->constrainsNodes(u.values)) return false;
  for (const RodState& r : state.rods)
    if (stepped(r) && (!r.contact.self.empty() || !r.contact.rod.empty())) return true;
  return false;
}

// Passes of the coupled step's contact set beyond its first solve. A node
// let go can leave a neighbour pulling in the next pass; in a packed sac
// four passes left one step in 170 with wall nodes still pulling.
constexpr int kContactSetPasses = 8;

// Every stepped rod in one solve, its pair contacts coupled.
StepReport stepCoupled(const Model& model, State& state, double time, double h, long& iterations) {
  std::vector<char>& on = state.pairSolve.stepped;
  on.assign(state.rods.size(), 0);
  for (size_t k = 0; k < state.rods.size(); ++k) {
    RodState& r = state.rods[k];
    if (!stepped(r)) continue;
    on[k] = 1;
    collectFixedDofs(model.rods[k], r);
    prescribedVelocities(model.rods[k], r, h);
    r.work.pairsCoupled = true;
  }
  std::optional<Failure> failure;
  // The contact set is decided within the step: a pair (or wall node) the
  // solve carried into touch from outside it joins the solve, one it let go
  // of again leaves it, and the step is taken again from its start
  // (physics/pair_contact_set.h).
  clearEnteredContacts(state.rods);
  for (int pass = 0; pass <= kContactSetPasses && !failure; ++pass) {
    if (pass > 0)
      for (size_t k = 0; k < state.rods.size(); ++k)
        if (on[k]) restorePoses(state.rods[k]);
    for (int it = 0; it < model.newtonIterations && !failure; ++it) {
      followOtherSides(state.rods, on);
      for (size_t k = 0; k < state.rods.size(); ++k)
        if (on[k]) ++iterations, buildSystem(model, int(k), state.rods[k], time, h, it);
      failure = solvePairsCoupled(model, state.rods, on, h, it == 0, state.pairSolve, state.stats.pairSolve);
      for (size_t k = 0; k < state.rods.size() && !failure; ++k)
        if (on[k]) applyIncrement(state.rods[k], h);
    }
    if (failure || pass == kContactSetPasses || reviseContactSet(state.rods, on) == 0) break;
  }
  for (RodState& r : state.rods) r.work.pairsCoupled = false;
  if (failure) return {std::move(*failure)};
  reportSolvedPairForces(state.rods, on);
  reportSolvedWallForces(state.rods, on);
  return {};
}

}  // namespace

void advanceTargets(const Model& model, State& state, double dt) {
  for (size_t k = 0; k < model.rods.size(); ++k) {
    const RodModel& rm = model.rods[k];
    for (size_t c = 0; c < rm.constraints.size(); ++c) {
      Pose& t = state.rods[k].targets[c];
      t.position += rm.constraints[c].velocity * dt;
      t.rotation = (quatExp(rm.constraints[c].angularVelocity * dt) * t.rotation).normalized();
    }
  }
}

namespace {

// One linearised step moves each node along a straight line (x += h v), so
// an element that turns by an angle a within the step ends stretched by
// sqrt(1 + a^2) - 1, about a^2 / 2, whatever its axial stiffness: a stretch
// of the step, not of the wire. Left in, the stiff wire gives it back as
// newtons of tension the next step, which turn the elements further (the
// twist-and-pull and the soak's refusals, docs/input-limits.md). A step
// that leaves an element stretched by more than this (turned by more than
// about 0.32 rad) is taken again in substeps, as an unhealthy one is.
constexpr double kLinearisedStretch = 0.05;

// Whether some active element is stretched beyond kLinearisedStretch
// (compared squared: no square root per element).
bool overstretched(const State& state) {
  const double limit = (1 + kLinearisedStretch) * (1 + kLinearisedStretch);
  for (const RodState& r : state.rods) {
    if (!r.active) continue;
    for (int e = 0; e + 1 < r.activeNodes; ++e)
      if ((r.x[e + 1] - r.x[e]).squaredNorm() > limit * r.beams[e].length * r.beams[e].length) return true;
  }
  return false;
}

// One implicit step of length h from the current state; `detect` runs the
// effects' per-step preparation (contact detection) first, `verify` asks
// them afterwards whether the step outran it, and whether it stretched an
// element beyond what one linearised step follows (`retake`, set only then).
// `sweep`, if given, is the velocity per rod and node the detection takes
// for the step's motion instead of the start velocity (the solve still
// starts from the latter).
StepReport attempt(const Model& model, State& state, double h, bool detect, bool verify, long& iterations,
                   bool& retake, std::vector<std::vector<Vec3>>* sweep = nullptr) {
  retake = false;
  for (RodState& r : state.rods) saveStart(r);
  advanceTargets(model, state, h);
  if (detect) {
    if (sweep)
      for (size_t k = 0; k < state.rods.size(); ++k) std::swap(state.rods[k].v, (*sweep)[k]);
    for (const EffectUse& u : model.effects)
      if (u.enabled) u.effect->beginStep(model, u.values, state, h);
    if (sweep)
      for (size_t k = 0; k < state.rods.size(); ++k) std::swap(state.rods[k].v, (*sweep)[k]);
  }
  StepReport report;
  if (couplesPairs(model, state))
    report = stepCoupled(model, state, state.time, h, iterations);
  else
    for (size_t k = 0; k < model.rods.size() && report.ok(); ++k)
      if (stepped(state.rods[k])) report = stepRod(model, int(k), state.rods[k], state.time, h, iterations);
  if (report.ok()) report.failure = checkHealth(model, state);
  for (size_t k = 0; k < model.effects.size() && verify && report.ok(); ++k)
    if (model.effects[k].enabled)
      report.failure = model.effects[k].effect->endStep(model, model.effects[k].values, state, h);
  if (verify && report.ok()) retake = overstretched(state);
  return report;
}

// What a refused step must give back, kept only once a step has failed.
struct Snapshot {
  std::vector<RodState> rods;
  double time = 0;
};

// A shock (a clamp released under load, a loop snapping onto a wall) can
// turn a node by radians within one step, beyond what one linearised step
// follows; the same interval in 2, 4 ... kMaxParts substeps usually can.
// Healthy steps never come here, so the hot path pays nothing.
constexpr int kMaxParts = 64;

// How often a substep of the finest split that outran its contact detection
// is taken again with the detection sweeping the motion it took.
constexpr int kSweptRetakes = 3;

bool missedContact(const StepReport& report) {
  return report.failure && report.failure->kind == FailureKind::MissedContact;
}

// A substep of the finest split. Where a split does not catch a contact,
// a finer one seldom does: a loop snapping off a wall swings its free end
// into the wall the faster, the finer the steps resolve the snap
// (docs/contact.md, "Three more ways past the skin"). The detection at the
// substep's start found no wall within the reach of the start velocity, so
// the solve never met it. So such a substep is taken again from its start,
// its contacts detected for the velocity the trial ended with (its
// displacement over h): a wall the trial went into is then closing and in
// the solve, which stops the approach (a predictor-corrector detection).
// What still outruns its contacts after that is kept, as before.
StepReport finestSubstep(const Model& model, State& state, double h, bool detect, long& iterations) {
  const std::vector<RodState> start = state.rods;
  std::vector<std::vector<Vec3>> sweep;
  bool retake = false;
  StepReport report = attempt(model, state, h, detect, true, iterations, retake);
  for (int k = 0; k < kSweptRetakes && missedContact(report); ++k) {
    sweep.resize(state.rods.size());
    for (size_t r = 0; r < state.rods.size(); ++r) {
      const RodState& rod = state.rods[r];
      sweep[r].resize(rod.v.size());
      for (size_t i = 0; i < rod.v.size(); ++i) sweep[r][i] = (rod.x[i] - rod.work.x0[i]) / h;
    }
    state.rods = start;
    report = attempt(model, state, h, true, true, iterations, retake, &sweep);
  }
  if (missedContact(report)) report = {};
  return report;
}

StepReport retryInSubsteps(const Model& model, State& state, const Snapshot& start, long& iterations) {
  StepReport report;
  for (int parts = 2; parts <= kMaxParts; parts *= 2) {
    const double h = model.timeStep / parts;
    report = {};
    bool retake = false;
    for (int p = 0; p < parts && report.ok() && !retake; ++p) {
      // The contacts found at the start of the interval still hold for the first substep.
      // The finest split is kept even if an element is still stretched
      // beyond kLinearisedStretch, or an effect says it outran its
      // preparation after finestSubstep's retakes.
      report = parts < kMaxParts ? attempt(model, state, h, p > 0, true, iterations, retake)
                                 : finestSubstep(model, state, h, p > 0, iterations);
      state.time += h;
    }
    state.time = start.time;  // step() adds the whole interval
    if (report.ok() && !retake) return report;
    state.rods = start.rods;
  }
  return report;
}

// Wall penetration is meant to stay within 10 % of the wire radius. A wall
// set softer than the wire needs (wall_contact's stiffness_n_mm2 with
// stiffness_per_rigidity_1_mm3 at 0) or a coil pressed harder than its
// EI / r says goes deeper. Said once per run, when first seen.
constexpr double kWallPenetrationWarning = 0.1;

void recordWallPenetration(const Model& model, State& state) {
  StepStats& s = state.stats;
  for (size_t k = 0; k < state.rods.size(); ++k) {
    RodState& r = state.rods[k];
    // Every detection of the step, the substeps' too.
    const double depth = r.contact.wallPenetrationPeak;
    r.contact.wallPenetrationPeak = 0;
    if (!(depth > 0) || r.activeNodes < 1) continue;
    double radius = INFINITY;
    for (int i = 0; i < r.activeNodes; ++i) radius = std::min(radius, r.nodes[i].radius);
    const double ratio = radius > 0 ? depth / radius : 0.0;
    if (ratio > kWallPenetrationWarning && !(s.maxWallPenetrationOfRadius > kWallPenetrationWarning))
      warnOnce(state, "wall contact: rod '" + model.rods[k].name + "' went " + std::to_string(int(std::lround(depth * 1e6))) +
                          " um (" + std::to_string(int(std::lround(100 * ratio))) + " % of its wire radius) into a wall at t = " +
                          std::to_string(state.time) + " s (more than " + std::to_string(int(100 * kWallPenetrationWarning)) +
                          " %; see docs/contact.md)");
    s.maxWallPenetration = std::max(s.maxWallPenetration, depth);
    s.maxWallPenetrationOfRadius = std::max(s.maxWallPenetrationOfRadius, ratio);
  }
}

// Where a state that the last step left healthy was made non-finite from
// outside (a device placed at an absurd pose, a caller's edit): nothing if none.
std::optional<Failure> nonFiniteStart(const Model& model, const State& state) {
  for (size_t k = 0; k < state.rods.size(); ++k) {
    const RodState& r = state.rods[k];
    if (!r.active) continue;
    for (int i = 0; i < r.activeNodes; ++i) {
      const double sum = r.x[i].sum() + r.q[i].coeffs().sum() + r.v[i].sum() + r.w[i].sum();
      if (std::isfinite(sum)) continue;
      Failure f = badRod(model.rods[k].name, "non-finite position, rotation or velocity before the step");
      f.kind = FailureKind::BlowUp;
      f.node = i;
      f.quantity = "position, rotation or velocity";
      f.value = sum, f.limit = INFINITY;
      return f;
    }
  }
  return std::nullopt;
}

}  // namespace

StepReport step(const Model& model, State& state) {
  // Contact detection must never see non-finite positions: refused before it runs.
  if (std::optional<Failure> bad = nonFiniteStart(model, state)) {
    ++state.blowups;
    bad->time = state.time;
    warnOnce(state, describe(*bad));
    return {std::move(bad)};
  }
  const auto start = std::chrono::steady_clock::now();
  long iterations = 0;
  bool retake = false;
  StepReport report = attempt(model, state, model.timeStep, true, true, iterations, retake);
  if (!report.ok() || retake) {
    for (RodState& r : state.rods) restoreStart(r);
    Snapshot snapshot{state.rods, state.time};
    const StepReport first = report;
    report = retryInSubsteps(model, state, snapshot, iterations);
    if (report.ok()) {
      ++state.substepped;
    } else {
      state.rods = std::move(snapshot.rods);
      ++state.blowups;
      // A missed contact or a stretch of the linearisation alone is not why a
      // step is refused: the substeps' failure is.
      if (first.failure && first.failure->kind != FailureKind::MissedContact) report = first;
      report.failure->time = state.time;
      warnOnce(state, describe(*report.failure));
    }
  }
  if (report.ok()) state.time += model.timeStep;
  recordWallPenetration(model, state);
  if (report.ok()) recordWallLoad(model, state);
  if (report.ok()) updateSleep(model, state);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  StepStats& s = state.stats;
  ++s.steps;
  s.newtonIterations += iterations;
  s.lastStepSeconds = seconds;
  s.totalStepSeconds += seconds;
  s.maxStepSeconds = std::max(s.maxStepSeconds, seconds);
  return report;
}

}  // namespace coilsim
