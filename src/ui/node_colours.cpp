#include "ui/node_colours.h"

#include <algorithm>
#include <cmath>

#include "physics/beam.h"

namespace coilsim::ui {

void bendingMoments(const State& state, int rod, std::vector<double>& out) {
  out.clear();
  const RodState& r = state.rods[size_t(rod)];
  if (!r.active || r.activeNodes <= 0) return;
  const int n = r.activeNodes;
  out.assign(size_t(n), 0.0);
  std::vector<int> count(size_t(n), 0);
  BeamEval e;
  for (int i = 0; i + 1 < n; ++i) {
    evalBeam(r.beams[size_t(i)], r.x[size_t(i)], r.q[size_t(i)], r.x[size_t(i) + 1], r.q[size_t(i) + 1], false, e);
    // End moments in the element frame: x is the axis (torsion), y and z bend.
    const Vec3 a = e.frame.conjugate() * Vec3(e.forceA.tail<3>());
    const Vec3 b = e.frame.conjugate() * Vec3(e.forceB.tail<3>());
    const double ma = std::hypot(a.y(), a.z()), mb = std::hypot(b.y(), b.z());
    out[size_t(i)] += ma, ++count[size_t(i)];
    out[size_t(i) + 1] += mb, ++count[size_t(i) + 1];
  }
  for (int i = 0; i < n; ++i)
    if (count[size_t(i)]) out[size_t(i)] /= count[size_t(i)];
}

Colour heatColour(const Colour& base, double t) {
  t = std::clamp(std::isfinite(t) ? t : 1.0, 0.0, 1.0);
  const Colour yellow(1.0f, 0.85f, 0.1f, base.w()), red(0.95f, 0.1f, 0.05f, base.w());
  if (t < 0.5) return base + (yellow - base) * float(2 * t);
  return yellow + (red - yellow) * float(2 * t - 1);
}

double colourByBendingMoment(const State& state, double scale, DrawData& data) {
  std::vector<std::vector<double>> moments;
  double largest = 0;
  for (size_t k = 0; k < state.rods.size(); ++k) {
    if (!state.rods[k].active) continue;
    moments.emplace_back();
    bendingMoments(state, int(k), moments.back());
    for (double m : moments.back()) largest = std::max(largest, m);
  }
  const double full = scale > 0 ? scale : largest;
  for (size_t t = 0; t < data.tubes.size() && t < moments.size(); ++t) {
    DrawTube& tube = data.tubes[t];
    const Colour base = defaultColour(tube.role);
    for (size_t i = 0; i < tube.colours.size() && i < moments[t].size(); ++i)
      tube.colours[i] = heatColour(base, full > 0 ? moments[t][i] / full : 0.0);
  }
  return largest;
}

}  // namespace coilsim::ui
