// Running a scenario with the reference rod and sampling its measurements
// (experiment.h).
#include "experiment.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "noise.h"

namespace refrod {

Vec3 tiltedGravity(const Vec3& g, double aDeg, double bDeg) {
  const Vec3 u = g.normalized();
  Vec3 e1 = Vec3::UnitX() - u.x() * u;
  if (e1.norm() < 1e-6) e1 = Vec3::UnitY() - u.y() * u;
  e1.normalize();
  const Vec3 e2 = u.cross(e1);
  const Vec3 w = (aDeg * e1 + bDeg * e2) * M_PI / 180;
  if (w.norm() == 0) return g;
  return Eigen::AngleAxisd(w.norm(), w.normalized()) * g;
}

void lighthillDrag(double mu, double Lambda, double r, double& cn, double& ct) {
  const double lg = std::log(0.18 * Lambda / r);
  cn = 4 * M_PI * mu / (lg + 0.5);
  ct = 2 * M_PI * mu / lg;
}

RodSpec trueSpec(const Scenario& sc) {
  RodSpec s;
  const double r = sc.wireRadiusMm * 1e-3, rho = sc.densityGcm3 * 1e3;
  const double rhoF = sc.buoyancy ? sc.mediumDensityGcm3 * 1e3 : 0.0;
  const Vec3 g = tiltedGravity(sc.gravity, sc.tiltADeg, sc.tiltBDeg);
  s.length = sc.lengthMm * 1e-3;
  s.coilEdges = int(std::lround(sc.lengthMm / sc.edgeMm));
  s.coil = wireSection(r, sc.trueYoungGpa * 1e9, sc.poisson, rho, rhoF, g);
  const double R = sc.loopDiameterMm * 0.5e-3, c = sc.pitchMm * 1e-3 / (2 * M_PI), den = R * R + c * c;
  s.restDarboux = Vec3(0, R / den, (sc.rightHanded ? 1 : -1) * c / den);
  s.tip = sc.tipMm * 1e-3;
  s.direction = sc.direction.normalized();
  s.normal = sc.referenceNormal.normalized();
  s.contact = sc.contact;
  if (sc.drag) lighthillDrag(sc.mediumViscosityPas, M_PI * 2 * R, r, s.dragNormal, s.dragTangent);
  if (sc.tube.lengthMm > 0) {
    const TubeDef& t = sc.tube;
    s.tubeLength = t.lengthMm * 1e-3;
    s.tubeEdges = t.edges;
    s.tube = tubeSection(t.outerDiameterMm * 0.5e-3, t.innerDiameterMm * 0.5e-3, t.youngGpa * 1e9, t.poisson,
                         t.densityGcm3 * 1e3, s.coil, r, rho, rhoF, g);
  }
  return s;
}

namespace {

StageResult collect(const RodSpec& spec, const Rod& rod) {
  StageResult out;
  out.nodesM = centerline(rod, &out.nodeS);
  int J = 0;
  while (rod.key[J + 1] < 0) ++J;
  out.exitMm = rod.x[J] * 1e3;
  out.exitDirection = rod.q[J] * Vec3::UnitZ();
  // How far the loads moved the coil from its rest shape at the declared clamp.
  const Quat Rc = spec.clampFrame(rod.twist);
  for (size_t i = 0; i < out.nodesM.size(); ++i)
    out.maxSagMm = std::max(out.maxSagMm, 1e3 * (out.nodesM[i] - spec.tip - Rc * restPosition(spec, out.nodeS[i])).norm());
  // Contact statistics: edge pairs far apart along the rod, their distance
  // from 8 points on each edge (1/16 of an edge from the true closest points).
  const double r = spec.coil.radius, exclude = std::max(10 * r, 2 * spec.h());
  const auto& x = out.nodesM;
  out.minGapMm = 1e9;
  for (size_t i = 1; i < x.size(); ++i)
    for (size_t j = i + 1; j < x.size(); ++j) {
      if (out.nodeS[j - 1] - out.nodeS[i] < exclude) continue;
      const double reach = 0.5 * ((x[i] - x[i - 1]).norm() + (x[j] - x[j - 1]).norm());
      if ((0.5 * (x[i] + x[i - 1] - x[j] - x[j - 1])).norm() > reach + 2 * r + out.minGapMm * 1e-3) continue;
      double d = 1e9;
      for (int a = 0; a < 8; ++a)
        for (int b = 0; b < 8; ++b)
          d = std::min(d, (x[i - 1] + (a + 0.5) / 8 * (x[i] - x[i - 1]) - x[j - 1] - (b + 0.5) / 8 * (x[j] - x[j - 1])).norm());
      out.minGapMm = std::min(out.minGapMm, (d - 2 * r) * 1e3);
      out.contactPairs += d < 2 * r;
    }
  return out;
}

double round3(double v) {
  const double r = std::round(v * 1000) / 1000;
  return r == 0 ? 0.0 : r;  // no "-0.0" in the files
}

// Uneven samples along the arc (gaps drawn uniformly in [0.4, 1.6] of the
// mean), snapped to distinct nodes, then Gaussian noise on each coordinate.
void sample(const StageDef& st, uint64_t seed, StageResult& res) {
  Rng rng(seed);
  const int n = std::min<int>(st.points, int(res.nodesM.size()));
  std::vector<double> cum(1, 0.0);
  for (int i = 1; i < n; ++i) cum.push_back(cum.back() + 0.4 + 1.2 * rng.uniform());
  const double sEnd = res.nodeS.back();
  int prev = -1;
  for (int i = 0; i < n; ++i) {
    const double target = sEnd * cum[i] / cum.back();
    int k = int(std::lower_bound(res.nodeS.begin(), res.nodeS.end(), target) - res.nodeS.begin());
    if (k > 0 && (k == int(res.nodeS.size()) || target - res.nodeS[k - 1] < res.nodeS[k] - target)) --k;
    // Distinct and increasing, leaving room for the points still to come.
    k = std::clamp(k, prev + 1, int(res.nodeS.size()) - (n - i));
    prev = k;
    Vec3 p = res.nodesM[k] * 1e3;
    for (int c = 0; c < 3; ++c) p[c] = round3(p[c] + st.sigmaMm * rng.normal());
    res.sampledMm.push_back(p);
  }
}

}  // namespace

Scenario withoutHidden(const Scenario& sc) {
  Scenario s = sc;
  for (const std::string& h : sc.hidden) {
    if (h == "buoyancy") s.buoyancy = false;
    if (h == "drag") s.drag = false;
    if (h == "self_contact") s.contact = false;
    if (h == "catheter_compliance") s.tube.lengthMm = 0;
    if (h == "gravity_tilt") s.tiltADeg = s.tiltBDeg = 0;
  }
  return s;
}

std::vector<double> effectSizes(const std::vector<StageResult>& truth, const std::vector<StageResult>& without) {
  std::vector<double> out;
  for (size_t i = 0; i < truth.size(); ++i) {
    double d = 0;
    const size_t n = std::min(truth[i].nodesM.size(), without[i].nodesM.size());
    for (size_t k = 0; k < n; ++k) d = std::max(d, (truth[i].nodesM[k] - without[i].nodesM[k]).norm() * 1e3);
    out.push_back(d);
  }
  return out;
}

std::vector<StageResult> runExperiment(const Scenario& sc) {
  const RodSpec spec = trueSpec(sc);
  std::vector<StageResult> out(sc.stages.size());
  const double dl = spec.h();
  const auto fail = [&](const StageDef& st, const SolveReport& r) {
    if (!r.converged) throw std::runtime_error(sc.name + ", " + st.name + ": " + r.message);
  };
  // Static stages by twist, then deployed length, each continuing the last.
  std::vector<size_t> order;
  for (size_t i = 0; i < sc.stages.size(); ++i)
    if (sc.stages[i].history.empty()) order.push_back(i);
  std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) {
    const StageDef &A = sc.stages[a], &B = sc.stages[b];
    return A.twistDeg != B.twistDeg ? A.twistDeg < B.twistDeg : A.deployedMm < B.deployedMm;
  });
  Rod rod;
  bool have = false;
  for (const size_t i : order) {
    const StageDef& st = sc.stages[i];
    const double l = st.deployedMm * 1e-3, tw = st.twistDeg * M_PI / 180;
    SolveReport rep;
    if (!have || tw != rod.twist || l < rod.deployed) {
      rod = deployStatic(spec, l, tw, dl, &rep);
      have = true;
    } else {
      rep = pushStatic(spec, rod, l, tw, dl);
    }
    fail(st, rep);
    out[i] = collect(spec, rod);
  }
  for (size_t i = 0; i < sc.stages.size(); ++i) {
    const StageDef& st = sc.stages[i];
    if (st.history.empty()) continue;
    SolveReport rep;
    Rod d = deployStatic(spec, st.history.front().l, st.history.front().twist, dl, &rep);
    fail(st, rep);
    rep = pushDynamic(spec, d, st.history, st.captureS, sc.timeStepS, Newmark{});
    fail(st, rep);
    out[i] = collect(spec, d);
  }
  for (size_t i = 0; i < sc.stages.size(); ++i) sample(sc.stages[i], sc.seed * 1000 + i, out[i]);
  return out;
}

}  // namespace refrod
