#include <gtest/gtest.h>
#include <cmath>
#include "physics/integrator.h"
#include "physics/model.h"
using namespace coilsim;
TEST(Smoke, Cantilever) {
  ModelDef d; d.gravity = Vec3::Zero();
  RodDef r; r.length = 0.1; r.beams = 20; r.rest = makeStraight(r.length, r.beams);
  r.material = {200e9, shearModulusOf(200e9, 0.3), 7800};
  r.section = circularSection(1e-3, 0.3);
  r.constraints.push_back({0, kAllDofs});
  const double P = 0.01;
  r.loads.push_back({20, Vec3(0, 0, -P), Vec3::Zero()});
  d.rods.push_back(r);
  Model m = compileModel(d);
  State s = makeState(m);
  auto rep = solveStatic(m, s);
  ASSERT_TRUE(rep.converged) << rep.message;
  double EI = 200e9 * r.section.iy;
  double ref = P * std::pow(0.1, 3) / (3 * EI);
  printf("tip z %g ref %g iters %d\n", s.rods[0].x[20].z(), ref, rep.iterations);
  EXPECT_NEAR(-s.rods[0].x[20].z(), ref, 1e-3 * ref);
}
TEST(Smoke, Roll) {
  ModelDef d; d.gravity = Vec3::Zero();
  RodDef r; r.length = 0.1; r.beams = 40; r.rest = makeStraight(r.length, r.beams);
  r.material = {200e9, shearModulusOf(200e9, 0.3), 7800};
  r.section = circularSection(1e-3, 0.3);
  r.constraints.push_back({0, kAllDofs});
  double EI = 200e9 * r.section.iy;
  r.loads.push_back({40, Vec3::Zero(), Vec3(0, 2 * M_PI * EI / 0.1, 0)});
  d.rods.push_back(r);
  Model m = compileModel(d);
  State s = makeState(m);
  StaticOptions o; o.loadSteps = 20;
  auto rep = solveStatic(m, s, o);
  ASSERT_TRUE(rep.converged) << rep.message;
  printf("tip %g %g %g iters %d incr %d\n", s.rods[0].x[40].x(), s.rods[0].x[40].y(), s.rods[0].x[40].z(), rep.iterations, rep.increments);
}
TEST(Smoke, Dynamic) {
  ModelDef d;
  RodDef r; r.length = 0.1; r.beams = 100; r.rest = makeHelix(r.length, r.beams, 0.007, 0.001, true);
  r.material = {7.5e9, shearModulusOf(7.5e9, 0.39), 21450};
  r.section = circularSection(0.3556e-3, 0.39);
  r.constraints.push_back({0, kAllDofs});
  d.rods.push_back(r);
  d.effects.push_back(EffectRegistry::global().use("gravity"));
  d.damping.massCoeff = 1.0;
  Model m = compileModel(d);
  State s = makeState(m);
  for (int i = 0; i < 2000; ++i) { auto rep = step(m, s); ASSERT_TRUE(rep.ok()) << rep.message; }
  auto e = computeEnergy(m, s);
  printf("t %g tip %g %g %g  E %g %g %g  step %g us\n", s.time, s.rods[0].x[100].x(), s.rods[0].x[100].y(), s.rods[0].x[100].z(), e.kinetic, e.elastic, e.potential, 1e6*s.stats.totalStepSeconds/s.stats.steps);
}
