#include <gtest/gtest.h>
#include <chrono>
#include <fstream>
#include "io/measurement.h"
#include "validation/identify.h"
namespace coilsim::validation {
TEST(Explore, Control) {
  const std::string path = COILSIM_SOURCE_DIR "/../shared/data/measurements/control-helix-a.json";
  const Measurement m = io::readMeasurement(path);
  for (double sp : {4e-3, 2e-3, 1e-3}) {
    SimOptions o; o.spacing = sp; o.pushIncrement = sp;
    StageSimulator sim(m, o);
    Comparison cmp(m);
    auto t0 = std::chrono::steady_clock::now();
    auto sims = sim.run(ModelParams::nominal(m));
    double dt = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    auto c = cmp.compare(sims);
    printf("spacing %g: run %.3f s\n", sp, dt);
    for (auto& s : c) printf("  ok %d %s err %.4f disp %.3f mm dist %.3f mm\n", s.ok, s.message.c_str(), s.metrics.stageError, s.metrics.meanDisplacement*1e3, s.metrics.meanDistance*1e3);
    FitOptions fo; fo.params = {"young_modulus"};
    t0 = std::chrono::steady_clock::now();
    FitResult f = identify(sim, cmp, ModelParams::nominal(m), fo);
    dt = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    printf("  fit ok %d %s E %.4g +- %.3g GPa, evals %d, %.2f s\n", f.ok, f.message.c_str(), f.fitted[0].value/1e9, f.fitted[0].sigma/1e9, f.evaluations, dt);
    auto c2 = cmp.compare(sim.run(f.params));
    for (auto& s : c2) printf("  after: err %.4f dist %.3f mm\n", s.metrics.stageError, s.metrics.meanDistance*1e3);
  }
}
}
namespace coilsim::validation {
TEST(Explore, ControlResidual) {
  const std::string path = COILSIM_SOURCE_DIR "/../shared/data/measurements/control-helix-a.json";
  const Measurement m = io::readMeasurement(path);
  SimOptions o;
  StageSimulator sim(m, o);
  Comparison cmp(m);
  for (size_t k = 0; k < m.stages.size(); ++k) printf("stage %zu spline length %.3f mm deployed %.1f sigma %.3f rms %.3f\n", k, cmp.spline(k).length()*1e3, m.stages[k].deployed*1e3, cmp.stageSigma(k)*1e3, cmp.spline(k).residualRms()*1e3);
  for (auto fit : {std::vector<std::string>{"young_modulus"}, std::vector<std::string>{"young_modulus","loop_diameter","pitch"}, std::vector<std::string>{"young_modulus","poisson_ratio"}}) {
    FitOptions fo; fo.params = fit;
    FitResult f = identify(sim, cmp, ModelParams::nominal(m), fo);
    for (auto& v : f.fitted) printf("  %s = %.5g +- %.3g\n", v.name.c_str(), v.value / v.toSI, v.sigma / v.toSI);
    auto c2 = cmp.compare(sim.run(f.params));
    for (auto& s : c2) printf("  after: err %.4f dist %.3f mm\n", s.metrics.stageError, s.metrics.meanDistance*1e3);
    if (fit.size() == 1) { auto& s = c2[2]; for (size_t i = 0; i < s.s.size(); i += 3) printf("    s %.1f  sim-meas %.3f %.3f %.3f\n", s.s[i]*1e3, (s.sim[i]-s.meas[i]).x()*1e3, (s.sim[i]-s.meas[i]).y()*1e3, (s.sim[i]-s.meas[i]).z()*1e3); }
  }
}
}
