#include "validation/generate.h"
#include "validation/random_vector.h"

#include <random>
#include <stdexcept>

namespace coilsim::validation {
namespace {

// Position at arc length s on the node chain: cubic Hermite between nodes
// with chord-scaled tangents (Catmull-Rom), so samples between nodes stay on
// the smooth curve rather than on the chords.
Vec3 along(const StageSim& r, double s) {
  const size_t n = r.x.size();
  size_t k = 0;
  while (k + 2 < n && r.s[k + 1] < s) ++k;
  const double h = r.s[k + 1] - r.s[k];
  const double u = std::clamp((s - r.s[k]) / h, 0.0, 1.0);
  auto tangent = [&](size_t i) {
    const size_t a = i == 0 ? 0 : i - 1, b = std::min(n - 1, i + 1);
    return Vec3((r.x[b] - r.x[a]) / (r.s[b] - r.s[a]));
  };
  const Vec3 t0 = tangent(k) * h, t1 = tangent(k + 1) * h;
  const double u2 = u * u, u3 = u2 * u;
  return (2 * u3 - 3 * u2 + 1) * r.x[k] + (u3 - 2 * u2 + u) * t0 + (-2 * u3 + 3 * u2) * r.x[k + 1] + (u3 - u2) * t1;
}

}  // namespace

Measurement generateMeasurement(const Measurement& skeleton, const ModelParams& truth, const GenerateOptions& o) {
  Measurement m = skeleton;
  StageSimulator sim(m, o.sim);
  const std::vector<StageSim> runs = sim.run(truth, false);
  std::mt19937 rng(o.seed);
  std::normal_distribution<double> noise(0.0, o.sigma);
  std::uniform_real_distribution<double> gap(o.minGap, o.maxGap);
  for (size_t k = 0; k < m.stages.size(); ++k) {
    if (!runs[k].ok()) throw std::runtime_error("stage '" + m.stages[k].name + "' failed: " + runs[k].message());
    Stage& st = m.stages[k];
    st.pointSigma = o.sigma;
    st.centerline.clear();
    const double end = runs[k].s.back();
    // From the catheter tip to the coil's distal end, both included (the
    // centre line of the whole deployed part, as the format says): a curve
    // stopping up to a gap short of the end left the comparison to
    // extrapolate its last millimetre along the spline's end tangent (0.43 mm
    // error at the last node of the shipped example's stages 1 and 2).
    double s = 0;
    for (; s < end - 0.25 * o.minGap; s += gap(rng)) {
      const Vec3 e = drawVec3(noise, rng);
      st.centerline.push_back(along(runs[k], s) + (o.sigma > 0 ? e : Vec3::Zero()));
    }
    const Vec3 e = drawVec3(noise, rng);
    st.centerline.push_back(along(runs[k], end) + (o.sigma > 0 ? e : Vec3::Zero()));
  }
  return m;
}

}  // namespace coilsim::validation
