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

bool isContact(const EffectUse& u) {
  return u.name() == "wall_contact" || u.name() == "self_contact" || u.name() == "rod_contact";
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
}

}  // namespace coilsim
