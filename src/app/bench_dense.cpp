// Dense-packing timings for `coilsim bench` (see bench_dense.h): coil laid
// in nested spherical spirals inside a 7 mm sac, the step timed against the
// length of coil in the sac.
#include "app/bench_dense.h"

#include <time.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

#include "io/units.h"
#include "physics/integrator.h"
#include "physics/model.h"
#include "physics/run.h"
#include "planning/dense_sac.h"

namespace coilsim {
namespace {

// CPU time of this thread, in microseconds: on a machine shared with other
// builds the wall clock measures the neighbours as much as the code.
double cpuMicroseconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return units::sToUs(double(t.tv_sec)) + units::nsToUs(double(t.tv_nsec));
}

double wallMicroseconds() {
  return 1e-3 * double(std::chrono::duration_cast<std::chrono::nanoseconds>(
                           std::chrono::steady_clock::now().time_since_epoch()).count());
}

// Steps State a under model ma and State b under mb alternately, `steps`
// times each, so that a machine whose speed drifts affects both alike;
// adds each one's thread CPU time per step to usA and usB. Returns whether
// every step was taken.
bool timeAlternately(const Model& ma, State& a, const Model& mb, State& b, int steps, double& usA, double& usB) {
  bool ok = true;
  double spentA = 0, spentB = 0;
  for (int i = 0; i < steps; ++i) {
    double t0 = cpuMicroseconds();
    ok = step(ma, a).ok() && ok;
    spentA += cpuMicroseconds() - t0;
    t0 = cpuMicroseconds();
    ok = step(mb, b).ok() && ok;
    spentB += cpuMicroseconds() - t0;
  }
  usA += spentA / steps, usB += spentB / steps;
  return ok;
}

bool isContact(const EffectUse& u) {
  return u.name() == "wall_contact" || u.name() == "self_contact" || u.name() == "rod_contact";
}

// One sleeping-coil case (physics/sleep.h): `asleepMm` of coil at rest in
// the outer shells, asleep, and the about 100 mm of the inner shells awake,
// sliding along themselves at the push speed (5 mm/s) as a coil being
// pushed in does, against all of it awake, in the same run. Returns the
// thread CPU time per step (us) of each and the wakes seen.
struct SleepingCase {
  double awakeUs = 0, asleepUs = 0;
  int rodsAsleep = 0;
  double mmAsleep = 0, mmAwake = 0;
  long wakes = 0;
  bool ok = true;
};

SleepingCase benchSleeping(int asleepMm, int steps) {
  SleepingCase c;
  // The sleeping coil: asleepMm in shells from the wall inwards; the awake
  // one: 100 mm in shells laid on from the innermost of those inwards (a
  // sac of its own, whose wall is left out), one shell pitch further in.
  ModelDef def = planning::denseSacModel(units::mmToM(asleepMm));
  const size_t outerRods = def.rods.size();
  const planning::DenseSacSpec spec;
  double innermost = INFINITY;
  for (const RodModel& r : compileModel(def).rods)
    for (const Vec3& p : r.restPoints) innermost = std::min(innermost, p.norm());
  planning::DenseSacSpec inner = spec;
  inner.sacRadius = innermost - (2 * spec.wireRadius + spec.gap) + 1.1 * spec.wireRadius;
  for (RodDef& r : planning::denseSacModel(units::mmToM(100), inner).rods) {
    r.name = "awake " + r.name;
    def.rods.push_back(std::move(r));
  }
  def.sleep.enabled = true;
  const Model model = compileModel(def);
  State start = makeState(model);
  std::vector<bool> sleeps(model.rods.size(), false);
  for (size_t k = 0; k < model.rods.size(); ++k) {
    double length = 0;
    for (const BeamRest& b : model.rods[k].beams) length += b.length;
    sleeps[k] = k < outerRods;
    (sleeps[k] ? c.mmAsleep : c.mmAwake) += units::mToMm(length);
  }
  // One step awake first, so that the sleeping shells keep contacts found
  // where they lie (what a rod falling asleep keeps).
  c.ok = step(model, start).ok();
  constexpr double kPush = 5e-3;  // m/s
  for (size_t k = 0; k < model.rods.size(); ++k) {
    RodState& r = start.rods[k];
    for (int i = 0; i < r.activeNodes; ++i) {
      const Vec3 along = r.x[std::min(i + 1, r.activeNodes - 1)] - r.x[std::max(i - 1, 0)];
      r.v[i] = sleeps[k] ? Vec3::Zero() : Vec3(kPush * along.normalized());
      r.w[i].setZero();
    }
  }
  State awake = start, asleep = start;
  for (size_t k = 0; k < model.rods.size(); ++k) asleep.rods[k].asleep = sleeps[k];
  c.rodsAsleep = int(std::count(sleeps.begin(), sleeps.end(), true));
  Model awakeModel = model;
  awakeModel.sleep.enabled = false;
  c.ok = timeAlternately(awakeModel, awake, model, asleep, steps, c.awakeUs, c.asleepUs) && c.ok;
  c.wakes = asleep.sleep.wakes;
  return c;
}

// The packing, settled `settle` steps under the coupled solve from the laid
// state (the shells closed onto one another: most segments then press
// another, as in a packed sac), stepped `steps` steps from that one State
// with the pair contacts lumped (the default) and solved coupled
// (Model::coupledPairs, physics/pair_coupling.h): thread CPU time per step
// of each, and the coupled step's solves per step (its contact set is
// decided within the step, physics/pair_contact_set.h) and rows per solve.
struct CoupledCase {
  double lumpedUs = 0, coupledUs = 0, solvesPerStep = 0, rowsPerSolve = 0;
  bool ok = true;
};

CoupledCase benchCoupled(int mm, int settle, int steps) {
  CoupledCase c;
  ModelDef def = planning::denseSacModel(units::mmToM(mm));
  const Model lumped = compileModel(def);
  def.coupledPairs = true;
  const Model coupled = compileModel(def);
  State start = makeState(coupled);
  for (int i = 0; i < settle; ++i) c.ok = step(coupled, start).ok() && c.ok;
  start.stats.pairSolve = {};
  State a = start, b = start;
  c.ok = timeAlternately(lumped, a, coupled, b, steps, c.lumpedUs, c.coupledUs) && c.ok;
  const PairSolveStats& p = b.stats.pairSolve;
  c.solvesPerStep = double(p.solves) / steps;
  c.rowsPerSolve = p.solves ? double(p.rows) / double(p.solves) : 0.0;
  return c;
}

}  // namespace

void benchDenseFigures(const std::function<void(const std::string&, double)>& set, bool quick, bool json) {
  const std::vector<int> lengths = quick ? std::vector<int>{100, 500} : std::vector<int>{100, 250, 500, 1000, 1500};
  if (!json)
    std::printf("dense packing: coil in nested spherical spirals in a 7 mm sac (5120 triangles), 0.254 mm primary, "
                "wall + self + rod contact, thread CPU time per step (detect_wall_us: wall time of detection on 1 and "
                "2 threads, physics/contact/detect_parallel.h):\n"
                "  %8s %8s %8s %10s %12s %14s %12s %12s %14s %8s\n",
                "coil_mm", "segments", "packing", "step_us", "detect_us", "detect_fresh_us", "1t_wall_us", "2t_wall_us",
                "contacts/seg", "us/seg");
  for (int mm : lengths) {
    const Model model = compileModel(planning::denseSacModel(units::mmToM(mm)));
    State s = makeState(model);
    int segments = 0;
    for (const RodModel& r : model.rods) segments += r.nnode - 1;
    const int warm = 3, steps = quick ? 5 : 20;
    for (int i = 0; i < warm; ++i)
      if (const StepReport rep = step(model, s); !rep.ok() && !json) std::printf("  (%d mm, warm-up: %s)\n", mm, rep.message().c_str());
    double stepUs = 0, detectUs = 0, freshUs = 0, wall1Us = 0, wall2Us = 0;
    long contacts = 0;
    bool ok = true;
    for (int i = 0; i < steps; ++i) {
      State copy = s;
      double t0 = cpuMicroseconds();
      for (const EffectUse& u : model.effects)
        if (u.enabled && isContact(u)) u.effect->beginStep(model, u.values, copy, model.timeStep);
      detectUs += cpuMicroseconds() - t0;
      // Wall time on one thread and on two (the same contacts, bit for bit).
      for (const int threads : {1, 2}) {
        copy = s;
        copy.contactScratch.threads.setCount(threads);
        const double w0 = wallMicroseconds();
        for (const EffectUse& u : model.effects)
          if (u.enabled && isContact(u)) u.effect->beginStep(model, u.values, copy, model.timeStep);
        (threads == 1 ? wall1Us : wall2Us) += wallMicroseconds() - w0;
      }
      copy = s;
      copy.contactScratch.coherentWall = false;
      t0 = cpuMicroseconds();
      for (const EffectUse& u : model.effects)
        if (u.enabled && isContact(u)) u.effect->beginStep(model, u.values, copy, model.timeStep);
      freshUs += cpuMicroseconds() - t0;
      t0 = cpuMicroseconds();
      const StepReport rep = step(model, s);
      stepUs += cpuMicroseconds() - t0;
      if (!rep.ok() && ok && !json) std::printf("  (%d mm: %s)\n", mm, rep.message().c_str());
      ok = rep.ok() && ok;
      for (const RodState& r : s.rods) contacts += long(r.contact.wall.size() + r.contact.self.size() + r.contact.rod.size());
    }
    const double packing = planning::densePacking(units::mmToM(mm));
    const std::string k = "_" + std::to_string(mm) + "mm";
    set("dense_step_us" + k, stepUs / steps);
    set("dense_detect_us" + k, detectUs / steps);
    set("dense_detect_fresh_us" + k, freshUs / steps);
    set("dense_detect_wall_1thread_us" + k, wall1Us / steps);
    set("dense_detect_wall_2threads_us" + k, wall2Us / steps);
    set("dense_segments" + k, segments);
    set("dense_run_ok" + k, ok ? 1.0 : 0.0);
    if (!json)
      std::printf("  %8d %8d %7.1f%% %10.0f %12.0f %14.0f %12.0f %12.0f %14.2f %8.2f%s\n", mm, segments, 100 * packing,
                  stepUs / steps, detectUs / steps, freshUs / steps, wall1Us / steps, wall2Us / steps,
                  double(contacts) / steps / segments, stepUs / steps / segments,
                  ok ? "" : "  (a step was refused)");
  }
  // Pair contacts solved coupled: what the solve that lets a packing come
  // to rest costs against the lumped one.
  const std::vector<int> coupledLengths = quick ? std::vector<int>{100} : std::vector<int>{100, 250};
  const int settle = quick ? 100 : 300;
  if (!json)
    std::printf("dense packing with the pair contacts solved coupled (physics/pair_coupling.h) against lumped (the "
                "default), from one State settled %d steps under the coupled solve, thread CPU time per step:\n"
                "  %8s %10s %11s %8s %15s %14s\n",
                settle, "coil_mm", "lumped_us", "coupled_us", "ratio", "solves/step", "rows/solve");
  for (int mm : coupledLengths) {
    const CoupledCase c = benchCoupled(mm, settle, quick ? 10 : 40);
    const std::string k = "_" + std::to_string(mm) + "mm";
    set("dense_lumped_step_us" + k, c.lumpedUs);
    set("dense_coupled_step_us" + k, c.coupledUs);
    set("dense_coupled_solves_per_step" + k, c.solvesPerStep);
    set("dense_coupled_run_ok" + k, c.ok ? 1.0 : 0.0);
    if (!json)
      std::printf("  %8d %10.0f %11.0f %8.2f %15.2f %14.1f%s\n", mm, c.lumpedUs, c.coupledUs,
                  c.lumpedUs > 0 ? c.coupledUs / c.lumpedUs : 0.0, c.solvesPerStep, c.rowsPerSolve,
                  c.ok ? "" : "  (a step was refused)");
  }
  // Sleeping coils: what a coil at rest costs once it sleeps.
  const std::vector<int> asleepLengths = quick ? std::vector<int>{250} : std::vector<int>{250, 500, 1000};
  if (!json)
    std::printf("dense packing with sleeping coils (physics/sleep.h): N mm asleep (outer shells) + about 100 mm awake "
                "(inner shells sliding along themselves at 5 mm/s), thread CPU time per step, against the same all "
                "awake:\n  %10s %10s %10s %12s %12s %8s %6s\n",
                "asleep_mm", "awake_mm", "rods_asleep", "awake_us", "asleep_us", "ratio", "wakes");
  for (int mm : asleepLengths) {
    const SleepingCase c = benchSleeping(mm, quick ? 5 : 20);
    const std::string k = "_" + std::to_string(mm) + "mm";
    set("dense_sleeping_all_awake_step_us" + k, c.awakeUs);
    set("dense_sleeping_step_us" + k, c.asleepUs);
    set("dense_sleeping_run_ok" + k, c.ok ? 1.0 : 0.0);
    if (!json)
      std::printf("  %10.0f %10.0f %10d %12.0f %12.0f %8.2f %6ld%s\n", c.mmAsleep, c.mmAwake, c.rodsAsleep, c.awakeUs,
                  c.asleepUs, c.asleepUs > 0 ? c.awakeUs / c.asleepUs : 0.0, c.wakes, c.ok ? "" : "  (a step was refused)");
  }
}

}  // namespace coilsim
