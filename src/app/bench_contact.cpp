// Contact timings for `coilsim bench` (see bench_contact.h), in thread CPU
// time. Each sampled step is timed from the same state: detection alone
// (the contact effects' beginStep on a copy), the same with every wall query
// made afresh (the baseline; its contacts must be the same), the real step
// with contacts, and the step of the same deployment without contacts.
#include "app/bench_contact.h"

#include <algorithm>
#include <cstdio>
#include <time.h>

#include "geometry/phantom.h"
#include "io/units.h"
#include "physics/run.h"
#include "physics/integrator.h"
#include "physics/model.h"

namespace coilsim {
namespace {

// CPU time of this thread, in microseconds: on a machine shared with other
// builds the wall clock measures the neighbours as much as the code.
double cpuMicroseconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return units::sToUs(double(t.tv_sec)) + units::nsToUs(double(t.tv_nsec));
}

bool isContact(const EffectUse& u) { return u.name() == "wall_contact" || u.name() == "self_contact"; }

// Whether two States hold the same wall contacts, bit for bit.
bool sameWallContacts(const State& a, const State& b) {
  for (size_t k = 0; k < a.rods.size(); ++k) {
    const std::vector<ContactPoint>&x = a.rods[k].contact.wall, &y = b.rods[k].contact.wall;
    if (x.size() != y.size()) return false;
    for (size_t i = 0; i < x.size(); ++i)
      if (x[i].segment != y[i].segment || x[i].node != y[i].node || x[i].gap != y[i].gap || x[i].normal != y[i].normal ||
          x[i].anchor != y[i].anchor)
        return false;
  }
  return true;
}

}  // namespace

void benchContactFigures(const std::function<void(const std::string&, double)>& set, bool quick, bool json) {
  // A 10 mm spherical sac on a 4 mm sidewall vessel, sampled finely enough
  // for about 50,000 triangles; millimetres to metres here, as a scene does.
  geometry::PhantomSpec spec;
  spec.sacDiameter = 10;
  spec.resolution = 0.33;
  geometry::Phantom phantom = geometry::makePhantom(spec);
  for (Vec3& v : phantom.mesh.vertices) v *= units::kMetresPerMm;
  const geometry::PhantomInfo& info = phantom.info;

  ModelDef def;
  for (const char* e : {"gravity", "buoyancy", "drag", "wall_contact", "self_contact"})
    def.effects.push_back(EffectRegistry::global().use(e));
  def.damping = {1.0, 0.0};
  def.timeStep = 1e-3;
  Obstacle sac;
  sac.name = "sidewall phantom";
  sac.mesh = std::make_shared<const TriangleMesh>(phantom.mesh);
  def.obstacles.push_back(sac);
  // The paper's 150 mm coil (300 beams), the catheter tip 2 mm past the neck
  // plane, pointing at the dome.
  DeploymentDef d;
  // The paper's coil: 150 mm of platinum wire of radius 0.3556 mm in 7 mm helical loops.
  d.coil.length = 0.150;
  d.coil.rest.type = RestShapeDef::Type::Helix;
  d.coil.rest.loopDiameter = 0.007, d.coil.rest.pitch = 0.00096;
  d.coil.youngModulus = 7.5e9, d.coil.poissonRatio = 0.39, d.coil.density = 21450;
  d.coil.wireRadius = 0.3556e-3;
  d.coilBeams = 300;
  d.tip.direction = info.neck.normal;
  d.tip.position = units::kMetresPerMm * (info.neck.point + 2.0 * info.neck.normal);
  d.tip.normal = info.axisU;
  d.catheterDrawLength = 2e-3;
  def.device = d;
  const Model model = compileModel(def);
  Model free = model;
  for (EffectUse& u : free.effects)
    if (isContact(u)) u.enabled = false;

  State s = makeState(model);
  State scratch = s, reference = s;
  const double speed = 0.01, pushed = quick ? 0.01 : 0.06;
  command(model, s, {DeviceCommand::Kind::Push, speed, pushed});
  const int steps = int(pushed / speed / model.timeStep), every = quick ? 5 : 10;
  double detect = 0, detectFresh = 0, contact = 0, contactFree = 0, penetration = 0;
  int samples = 0, mismatches = 0;
  bool ok = true, freeOk = true;
  State sFree = makeState(free);
  command(free, sFree, {DeviceCommand::Kind::Push, speed, pushed});
  for (int i = 0; i < steps && ok; ++i) {
    moveDevice(model, s);
    moveDevice(free, sFree);
    const bool sample = i % every == every - 1;
    if (sample) {
      scratch = s;
      double c0 = cpuMicroseconds();
      for (const EffectUse& u : model.effects)
        if (u.enabled && isContact(u)) u.effect->beginStep(model, u.values, scratch, model.timeStep);
      detect += cpuMicroseconds() - c0;
      // The baseline: every segment queried afresh, from the same state.
      reference = s;
      reference.contactScratch.coherentWall = false;
      c0 = cpuMicroseconds();
      for (const EffectUse& u : model.effects)
        if (u.enabled && isContact(u)) u.effect->beginStep(model, u.values, reference, model.timeStep);
      detectFresh += cpuMicroseconds() - c0;
      // The two must find the same contacts (the shortcuts are exact).
      if (!sameWallContacts(scratch, reference)) ++mismatches;
      // The baseline is the same deployment run without contacts (in free
      // space), at the same pushed length: taken from this state, a coil
      // pressed on walls that vanish springs out and needs substeps.
      c0 = cpuMicroseconds();
      freeOk = step(free, sFree).ok() && freeOk;
      contactFree += cpuMicroseconds() - c0;
    } else {
      freeOk = step(free, sFree).ok() && freeOk;
    }
    const double c0 = cpuMicroseconds();
    ok = step(model, s).ok();
    if (sample) contact += cpuMicroseconds() - c0, ++samples;
  }
  // The run's own record: every detection, those of substeps too.
  penetration = s.stats.maxWallPenetration;
  const int n = std::max(1, samples);
  set("contact_mesh_triangles", double(phantom.mesh.triangles.size()));
  set("contact_step_us_n300", contact / n);
  set("contact_detect_us_n300", detect / n);
  set("contact_detect_fresh_us_n300", detectFresh / n);
  set("contact_detect_speedup_n300", detect > 0 ? detectFresh / detect : 0.0);
  const double freeStep = contactFree / n;
  set("contact_free_step_us_n300", freeStep);
  set("contact_over_free_n300", freeStep > 0 ? contact / n / freeStep : 0.0);
  set("contact_max_penetration_um", units::mToUm(penetration));
  set("contact_max_penetration_of_radius", penetration / d.coil.wireRadius);
  set("contact_detect_mismatches", mismatches);
  set("contact_run_ok", ok ? 1.0 : 0.0);
  set("contact_free_run_ok", freeOk ? 1.0 : 0.0);
  if (json) return;
  std::printf("contact: 150 mm coil (300 beams) pushed %.0f mm at 10 mm/s into a %zu-triangle sidewall phantom "
              "(wall + self contact), %d sampled steps%s:\n",
              units::mToMm(pushed), phantom.mesh.triangles.size(), samples, ok ? "" : " (a step was refused: figures cut short)");
  std::printf("  detection %.1f us of thread CPU time; every segment queried afresh (the baseline, same states) %.1f us: "
              "%.2fx; sampled steps whose contacts differ: %d\n",
              detect / n, detectFresh / n, detect > 0 ? detectFresh / detect : 0.0, mismatches);
  std::printf("  step %.1f us, of which detection %.1f us; the same deployment without contacts %.1f us per step; "
              "ratio %.2f; deepest wall penetration %.1f um (%.1f %% of the wire radius)\n",
              contact / n, detect / n, freeStep, freeStep > 0 ? contact / n / freeStep : 0.0, units::mToUm(penetration),
              100 * penetration / d.coil.wireRadius);
}

}  // namespace coilsim
