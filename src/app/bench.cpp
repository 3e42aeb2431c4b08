// `coilsim bench`: timings with ratios against baselines measured in the same
// run, so the figures mean something on any machine. Not a test: nothing here
// passes or fails on time.
#include "app/bench.h"

#include <Eigen/SparseCholesky>
#include <Eigen/SparseLU>
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <functional>
#include <map>
#include <string>

#include "app/bench_contact.h"
#include "app/progress.h"
#include "app/graphics.h"
#include "app/run_scene.h"
#include "app/bench_dense.h"
#include "io/units.h"
#include "physics/run.h"
#include "physics/integrator.h"
#include "physics/model.h"

#include "app/bench_render.h"
#include "app/bench_validation.h"

namespace coilsim {
namespace {

using Clock = std::chrono::steady_clock;

// Best over `repeats` of the mean time of `inner` calls, in microseconds.
double timeUs(const std::function<void()>& f, int inner, int repeats = 5) {
  std::vector<double> samples;
  for (int r = 0; r < repeats; ++r) {
    const auto t0 = Clock::now();
    for (int i = 0; i < inner; ++i) f();
    samples.push_back(std::chrono::duration<double, std::micro>(Clock::now() - t0).count() / inner);
  }
  std::sort(samples.begin(), samples.end());
  return samples.front();  // the least disturbed repeat: other processes only ever add time
}

// The paper's coil (150 mm, wire radius 0.3556 mm, 7 mm loops, E 7.5 GPa,
// nu 0.39, platinum) with `beams` beams, clamped at its first node, under gravity.
Model paperCoil(int beams) {
  ModelDef d;
  RodDef r;
  r.name = "coil";
  r.length = 0.150;
  r.beams = beams;
  r.rest = makeHelix(r.length, beams, 0.007, 0.001, true);
  r.material = {7.5e9, shearModulusOf(7.5e9, 0.39), 21450};
  r.section = circularSection(0.3556e-3, 0.39);
  r.constraints.push_back({0, kAllDofs});
  d.rods.push_back(r);
  d.effects.push_back(EffectRegistry::global().use("gravity"));
  d.damping = {1.0, 1e-4};
  d.timeStep = 1e-3;
  return compileModel(d);
}

Eigen::SparseMatrix<double> toSparse(const BlockTridiagonal& a) {
  std::vector<Eigen::Triplet<double>> t;
  const int n = a.size();
  auto put = [&](int bi, int bj, const Mat6& m, bool transpose) {
    for (int r = 0; r < 6; ++r)
      for (int c = 0; c < 6; ++c) {
        const double v = transpose ? m(c, r) : m(r, c);
        if (v != 0.0) t.emplace_back(6 * bi + r, 6 * bj + c, v);
      }
  };
  for (int i = 0; i < n; ++i) {
    put(i, i, a.diag[i], false);
    if (i + 1 < n) put(i + 1, i, a.lower[i], false), put(i, i + 1, a.lower[i], true);
  }
  Eigen::SparseMatrix<double> s(6 * n, 6 * n);
  s.setFromTriplets(t.begin(), t.end());
  return s;
}

struct Figures {
  std::map<std::string, double> values;
  std::vector<std::string> order;
  void set(const std::string& k, double v) {
    if (!values.count(k)) order.push_back(k);
    values[k] = v;
  }
};

void benchSolver(Figures& fig, int beams, bool quick) {
  Model m = paperCoil(beams);
  State s = makeState(m);
  for (int i = 0; i < 20; ++i) step(m, s);  // leave the rest shape so the matrix is generic
  const int inner = std::max(1, (quick ? 20000 : 100000) / beams);
  const std::string n = "_n" + std::to_string(beams);
  fig.set("step_us" + n, timeUs([&] { step(m, s); }, inner));

  const BlockTridiagonal A = s.rods[0].work.system;  // the last implicit matrix, constraints applied
  std::vector<Vec6> rhs(A.size(), Vec6::Ones()), x;
  BlockTridiagonalSolver solver;
  solver.resize(A.size());
  fig.set("block_solve_us" + n, timeUs([&] {
            solver.factorize(A);
            x = rhs;
            solver.solve(x);
          }, inner));

  const Eigen::SparseMatrix<double> S = toSparse(A);
  const Eigen::VectorXd b = Eigen::VectorXd::Ones(S.rows());
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt;
  ldlt.analyzePattern(S);  // the pattern is fixed for a run: analyse once, as a simulator would
  fig.set("simplicial_ldlt_us" + n, timeUs([&] {
            ldlt.factorize(S);
            Eigen::VectorXd y = ldlt.solve(b);
          }, std::max(1, inner / 4), 3));
  Eigen::SparseLU<Eigen::SparseMatrix<double>> lu;
  lu.analyzePattern(S);
  fig.set("sparse_lu_us" + n, timeUs([&] {
            lu.factorize(S);
            Eigen::VectorXd y = lu.solve(b);
          }, std::max(1, inner / 20), 3));
  fig.set("ldlt_over_block" + n, fig.values["simplicial_ldlt_us" + n] / fig.values["block_solve_us" + n]);
  fig.set("sparselu_over_block" + n, fig.values["sparse_lu_us" + n] / fig.values["block_solve_us" + n]);
}

// Deployment of the paper's 150 mm coil out of the catheter tip at a
// clinical push speed, with gravity, buoyancy and drag: simulated seconds per
// wall-clock second (above 1: faster than real time).
void benchDeployment(Figures& fig, int beams, double speedMmS, bool quick) {
  ModelDef def;
  for (const char* e : {"gravity", "buoyancy", "drag"}) def.effects.push_back(EffectRegistry::global().use(e));
  def.damping = {1.0, 0.0};
  def.timeStep = 1e-3;
  DeploymentDef d;
  // The paper's coil: 150 mm of platinum wire of radius 0.3556 mm in 7 mm helical loops.
  d.coil.length = 0.150;
  d.coil.rest.type = RestShapeDef::Type::Helix;
  d.coil.rest.loopDiameter = 0.007, d.coil.rest.pitch = 0.00096;
  d.coil.youngModulus = 7.5e9, d.coil.poissonRatio = 0.39, d.coil.density = 21450;
  d.coil.wireRadius = 0.3556e-3;
  d.coilBeams = beams;
  d.tip.normal = Vec3(0, 0, 1);
  def.device = d;
  const Model m = compileModel(def);
  State s = makeState(m);
  const double v = units::mmPerSToMPerS(speedMmS), simulated = (quick ? 0.25 : 1.0) * d.coil.length / v;
  const auto t0 = Clock::now();
  const TimelineRun run = runTimeline(m, s, {{0.0, {DeviceCommand::Kind::Push, v, 0}}}, simulated);
  const double wall = std::chrono::duration<double>(Clock::now() - t0).count();
  const std::string key = "deploy_realtime_ratio_n" + std::to_string(beams) + "_" + std::to_string(int(speedMmS)) + "mm_s";
  fig.set(key, run.ok() ? simulated / wall : 0.0);
}

void printJson(Figures& fig) {
  std::printf("{");
  for (size_t i = 0; i < fig.order.size(); ++i)
    std::printf("%s\"%s\": %.4g", i ? ", " : "", fig.order[i].c_str(), fig.values[fig.order[i]]);
  std::printf("}\n");
}

}  // namespace

int runBench(const std::vector<std::string>& args) {
  bool json = false, quick = false, contactOnly = false, practiceOnly = false;
  for (const std::string& a : args) {
    if (a == "--json") json = true;
    else if (a == "--quick") quick = true;
    else if (a == "--contact") contactOnly = true;
    else if (a == "--practice") practiceOnly = true;
    else {
      std::fprintf(stderr, "coilsim bench: unknown option '%s' (known: --json, --quick, --contact, --practice)\n",
                   a.c_str());
      return 2;
    }
  }
  Figures fig;
  // The practice window's line alone (issue 16).
  if (practiceOnly) {
    if (app::haveUi()) benchPracticeWindowFigures([&](const std::string& k, double v) { fig.set(k, v); }, quick, json);
    if (json) printJson(fig);
    return 0;
  }
  // The contact figures alone: what a profile of detection wants to see.
  if (contactOnly) {
    benchContactFigures([&](const std::string& k, double v) { fig.set(k, v); }, quick, json);
    benchDenseFigures([&](const std::string& k, double v) { fig.set(k, v); }, quick, json);
    if (json) printJson(fig);
    return 0;
  }
  // Phases: four solver sizes, four deployments, validation, contact (and rendering).
  app::Progress progress("bench", app::haveUi() ? 11 : 10, "phases");
  int phase = 0;
  auto record = [&](const std::string& k, double v) {
    fig.set(k, v);
    progress.update(phase, k);
  };
  for (int beams : {100, 300, 1000, 3000}) {
    if (!json) progress.line("bench: " + std::to_string(beams) + " beams...");
    benchSolver(fig, beams, quick);
    progress.update(++phase);
  }
  for (int beams : {150, 300})
    for (double speed : {1.0, 10.0}) {
      if (!json)
        progress.line("bench: deploying the 150 mm coil, " + std::to_string(beams) + " beams, " +
                      std::to_string(int(speed)) + " mm/s...");
      benchDeployment(fig, beams, speed, quick);
      progress.update(++phase);
    }
  fig.set("step_cost_ratio_n3000_over_n100_per_beam",
          fig.values["step_us_n3000"] / 3000.0 / (fig.values["step_us_n100"] / 100.0));
  benchValidationFigures(record, quick, json);
  ++phase;
  benchContactFigures(record, quick, json);
  benchDenseFigures(record, quick, json);
  ++phase;
  if (app::haveUi()) {
    benchRenderFigures(record, quick, json);
    benchPracticeWindowFigures(record, quick, json);
  }
  progress.finish();
  if (json) {
    printJson(fig);
    return 0;
  }
  std::printf("%-10s %12s %14s %16s %14s %10s %10s\n", "beams", "step_us", "block_solve_us", "simplicial_ldlt", "sparse_lu_us",
              "ldlt/blk", "lu/blk");
  for (int beams : {100, 300, 1000, 3000}) {
    const std::string n = "_n" + std::to_string(beams);
    std::printf("%-10d %12.2f %14.2f %16.2f %14.2f %10.1f %10.1f\n", beams, fig.values["step_us" + n],
                fig.values["block_solve_us" + n], fig.values["simplicial_ldlt_us" + n], fig.values["sparse_lu_us" + n],
                fig.values["ldlt_over_block" + n], fig.values["sparselu_over_block" + n]);
  }
  std::printf("step cost per beam, n=3000 relative to n=100: %.2f (1.0 = linear)\n",
              fig.values["step_cost_ratio_n3000_over_n100_per_beam"]);
  std::printf("deploying the 150 mm coil (gravity, buoyancy, drag; 1 ms steps), simulated / wall time:\n");
  for (int beams : {150, 300})
    for (int speed : {1, 10}) {
      const std::string k = "deploy_realtime_ratio_n" + std::to_string(beams) + "_" + std::to_string(speed) + "mm_s";
      std::printf("  %3d beams at %2d mm/s: %.1fx real time\n", beams, speed, fig.values[k]);
    }
  return 0;
}

}  // namespace coilsim
