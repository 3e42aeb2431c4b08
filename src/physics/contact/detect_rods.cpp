#include <algorithm>
#include <cmath>
#include <cstdint>

#include "physics/contact/detect.h"
#include "physics/contact/geometry.h"

namespace coilsim {
namespace {

struct GridSegment {
  std::uint64_t cell = 0;
  int rod = 0, segment = 0;
};

// Integer cell coordinates packed in 21 bits each (about 2 million cells per
// axis: kilometres at millimetre cells).
std::uint64_t cellKey(long ix, long iy, long iz) {
  constexpr long kOffset = 1L << 20, kMask = (1L << 21) - 1;
  return (std::uint64_t((ix + kOffset) & kMask) << 42) | (std::uint64_t((iy + kOffset) & kMask) << 21) |
         std::uint64_t((iz + kOffset) & kMask);
}

bool takesPart(const RodState& r) { return r.active && r.activeNodes >= 2; }

}  // namespace

void detectRodContacts(const Model& model, State& state, bool sameRod, double margin, const ContactLaw& law,
                       const ContactLaw& catheterLaw) {
  static thread_local std::vector<GridSegment> grid;
  grid.clear();
  // Fresh lists for this step: the old ones move to a per-rod previous buffer.
  static thread_local std::vector<std::vector<ContactPoint>> previous;
  previous.resize(state.rods.size());
  for (size_t k = 0; k < state.rods.size(); ++k) {
    std::vector<ContactPoint>& list = sameRod ? state.rods[k].contact.self : state.rods[k].contact.rod;
    std::swap(previous[k], list);
    list.clear();
  }

  // Cells at least as large as the reach of any two capsules, so every pair
  // that can touch lies in neighbouring cells.
  // The reach includes what a segment sweeps in the step at its start
  // velocity, so a pair that would meet within the step is found (response.h).
  const double h = model.timeStep;
  double reach = 0;
  for (size_t k = 0; k < state.rods.size(); ++k) {
    const RodState& r = state.rods[k];
    if (!takesPart(r)) continue;
    for (int e = 0; e + 1 < r.activeNodes; ++e)
      reach = std::max(reach, 0.5 * (r.x[e + 1] - r.x[e]).norm() + std::max(r.nodes[e].radius, r.nodes[e + 1].radius) +
                                  h * std::max(r.v[e].norm(), r.v[e + 1].norm()));
  }
  const double cell = 2 * reach + margin;
  const bool usable = cell > 0 && std::isfinite(cell);  // else no rod takes part (or positions are not finite)
  for (size_t k = 0; k < state.rods.size() && usable; ++k) {
    const RodState& r = state.rods[k];
    if (!takesPart(r)) continue;
    for (int e = 0; e + 1 < r.activeNodes; ++e) {
      const Vec3 m = 0.5 * (r.x[e] + r.x[e + 1]) / cell;
      grid.push_back({cellKey(std::lround(std::floor(m.x())), std::lround(std::floor(m.y())), std::lround(std::floor(m.z()))),
                      int(k), e});
    }
  }
  std::sort(grid.begin(), grid.end(), [](const GridSegment& a, const GridSegment& b) { return a.cell < b.cell; });

  for (const GridSegment& gi : grid) {
    const RodState& ri = state.rods[gi.rod];
    const Vec3 &a0 = ri.x[gi.segment], &a1 = ri.x[gi.segment + 1];
    const Vec3 m = 0.5 * (a0 + a1) / cell;
    const long cx = std::lround(std::floor(m.x())), cy = std::lround(std::floor(m.y())), cz = std::lround(std::floor(m.z()));
    for (long dx = -1; dx <= 1; ++dx)
      for (long dy = -1; dy <= 1; ++dy)
        for (long dz = -1; dz <= 1; ++dz) {
          const std::uint64_t key = cellKey(cx + dx, cy + dy, cz + dz);
          auto it = std::lower_bound(grid.begin(), grid.end(), key,
                                     [](const GridSegment& g, std::uint64_t k) { return g.cell < k; });
          for (; it != grid.end() && it->cell == key; ++it) {
            const GridSegment& gj = *it;
            // Each pair once: i before j.
            if (gj.rod < gi.rod || (gj.rod == gi.rod && gj.segment <= gi.segment)) continue;
            if (sameRod != (gj.rod == gi.rod)) continue;
            if (sameRod && gj.segment - gi.segment <= 1) continue;
            const RodModel &mi = model.rods[gi.rod], &mj = model.rods[gj.rod];
            if (mi.role == RodRole::Catheter && mj.role == RodRole::Catheter) continue;
            const RodState& rj = state.rods[gj.rod];
            const Vec3 &b0 = rj.x[gj.segment], &b1 = rj.x[gj.segment + 1];
            const double ra = 0.5 * (ri.nodes[gi.segment].radius + ri.nodes[gi.segment + 1].radius);
            const double rb = 0.5 * (rj.nodes[gj.segment].radius + rj.nodes[gj.segment + 1].radius);
            const double touch = 1e-3 * std::min(ra, rb);
            if (!sameRod && ((a0 - b0).norm() < touch || (a0 - b1).norm() < touch || (a1 - b0).norm() < touch ||
                             (a1 - b1).norm() < touch))
              continue;
            const SegmentPair p = closestSegmentSegment(a0, a1, b0, b1);
            const double gap = p.distance - ra - rb;
            if (p.distance <= 1e-12 * ra) continue;
            // Closing speed of the pair along the line of centres, at the start of the step.
            const Vec3 normal = (p.p - p.q) / p.distance;
            const Vec3 va = (1 - p.s) * ri.v[gi.segment] + p.s * ri.v[gi.segment + 1];
            const Vec3 vb = (1 - p.t) * rj.v[gj.segment] + p.t * rj.v[gj.segment + 1];
            const bool closing = -gap - h * normal.dot(va - vb) > 0;
            if (gap > margin && !closing) continue;
            ContactPoint c;
            c.segment = gi.segment, c.other = gj.rod, c.otherSegment = gj.segment;
            c.s = p.s;
            c.normal = normal;
            c.anchor = p.q;
            c.radius = ra + rb;
            c.gap = gap;
            c.otherVelocity = vb;
            c.closing[0] = closing;
            ContactPoint d = c;
            d.segment = gj.segment, d.other = gi.rod, d.otherSegment = gi.segment;
            d.s = p.t;
            d.normal = -c.normal;
            d.anchor = p.p;
            d.otherVelocity = va;
            auto& li = sameRod ? state.rods[gi.rod].contact.self : state.rods[gi.rod].contact.rod;
            auto& lj = sameRod ? state.rods[gj.rod].contact.self : state.rods[gj.rod].contact.rod;
            li.push_back(c);
            lj.push_back(d);
          }
        }
  }
  for (size_t k = 0; k < state.rods.size(); ++k) {
    RodState& r = state.rods[k];
    std::vector<ContactPoint>& list = sameRod ? r.contact.self : r.contact.rod;
    std::sort(list.begin(), list.end(), [](const ContactPoint& x, const ContactPoint& y) {
      return x.segment != y.segment ? x.segment < y.segment : x.otherSegment < y.otherSegment;
    });
    for (ContactPoint& c : list) {
      const bool catheter = model.rods[k].role == RodRole::Catheter || model.rods[c.other].role == RodRole::Catheter;
      const ContactLaw& l = catheter ? catheterLaw : law;
      updateContact(c, findPrevious(previous[k], c, r), r, l, h);
    }
    // Per-node report with the pair law (the catheter law differs only in friction).
    reportContacts(list, r, law, sameRod ? r.contact.selfForce : r.contact.rodForce);
  }
}

}  // namespace coilsim
