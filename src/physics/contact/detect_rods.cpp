#include <algorithm>
#include <cmath>
#include <cstdint>

#include "physics/contact/detect.h"
#include "physics/contact/geometry.h"

namespace coilsim {
namespace {

// Integer cell coordinates packed in 21 bits each (about 2 million cells per
// axis: kilometres at millimetre cells).
std::uint64_t cellKey(long ix, long iy, long iz) {
  constexpr long kOffset = 1L << 20, kMask = (1L << 21) - 1;
  return (std::uint64_t((ix + kOffset) & kMask) << 42) | (std::uint64_t((iy + kOffset) & kMask) << 21) |
         std::uint64_t((iz + kOffset) & kMask);
}

// A coordinate in cells as an index cellKey can pack. Clamped in double
// first: a position far out (a catheter moved by 1e308 mm) must not
// overflow the integer conversion; cells beyond the clamp merely share the
// border cell, and every pair found is still measured exactly.
long cellIndex(double v) { return std::lround(std::floor(std::clamp(v, -1e6, 1e6))); }

bool takesPart(const RodState& r) { return r.active && r.activeNodes >= 2; }

// Whether r is searched for pairs: a sleeping rod is not for its own
// (self-contact: its last contacts are kept), only against awake rods
// (physics/sleep.h).
bool inSearch(const RodState& r, bool sameRod) { return takesPart(r) && !(sameRod && r.asleep); }

// Half the segment's length plus its larger node radius, and what it sweeps in `sweep` s at its start velocity.
double segmentSize(const RodState& r, int e) {
  return 0.5 * (r.x[e + 1] - r.x[e]).norm() + std::max(r.nodes[e].radius, r.nodes[e + 1].radius);
}
double segmentSweep(const RodState& r, int e, double sweep) { return sweep * std::max(r.v[e].norm(), r.v[e + 1].norm()); }

// A segment's reach in the pair search: half its length, its contact
// radius scaled by max(1, radiusScale), and what it sweeps in `sweep` s.
double reachOf(const RodState& r, int e, double scale, double sweep) {
  return segmentSize(r, e) + (scale - 1) * std::max(r.nodes[e].radius, r.nodes[e + 1].radius) + segmentSweep(r, e, sweep);
}

// Whether the candidates `c` still hold every pair the grid would find now
// (scratch.h, PairCandidates); fills c.midNow and c.extentNow.
bool stillHolds(PairCandidates& c, const State& state, bool sameRod, double margin, double scale, double sweep) {
  if (!c.valid || c.margin != margin || c.radiusScale != scale || c.nodes.size() != state.rods.size()) return false;
  double size = 0;
  for (size_t k = 0; k < state.rods.size(); ++k) {
    const RodState& r = state.rods[k];
    const int nodes = inSearch(r, sameRod) ? r.activeNodes : 0;
    if (nodes != c.nodes[k] || char(r.asleep) != c.asleep[k]) return false;
    for (int e = 0; e + 1 < nodes; ++e) size = std::max(size, segmentSize(r, e));
  }
  c.midNow.resize(c.mid.size());
  c.extentNow.resize(c.extent.size());
  for (size_t k = 0; k < state.rods.size(); ++k) {
    const RodState& r = state.rods[k];
    for (int e = 0; e + 1 < c.nodes[k]; ++e) {
      const size_t i = size_t(c.first[k] + e);
      // A fast segment is paired outside the grid (forEachNearPair).
      if (segmentSweep(r, e, sweep) > 0.25 * size) return false;
      c.midNow[i] = 0.5 * (r.x[e] + r.x[e + 1]);
      c.extentNow[i] = reachOf(r, e, scale, sweep);
      if ((c.midNow[i] - c.mid[i]).norm() + std::max(0.0, c.extentNow[i] - c.extent[i]) > 0.5 * c.skin) return false;
    }
  }
  return true;
}

// Records where the searched segments are as `c` is built with `skin`.
void startCandidates(PairCandidates& c, const State& state, bool sameRod, double margin, double scale, double sweep,
                     double skin) {
  c.valid = false;
  c.margin = margin, c.radiusScale = scale, c.skin = skin;
  c.first.assign(state.rods.size(), 0);
  c.nodes.assign(state.rods.size(), 0);
  c.asleep.assign(state.rods.size(), 0);
  c.mid.clear();
  c.extent.clear();
  c.found[0].clear();
  c.found[1].clear();
  for (size_t k = 0; k < state.rods.size(); ++k) {
    const RodState& r = state.rods[k];
    c.first[k] = int(c.mid.size());
    c.nodes[k] = inSearch(r, sameRod) ? r.activeNodes : 0;
    c.asleep[k] = char(r.asleep);
    for (int e = 0; e + 1 < c.nodes[k]; ++e) {
      c.mid.push_back(0.5 * (r.x[e] + r.x[e + 1]));
      c.extent.push_back(reachOf(r, e, scale, sweep));
    }
  }
}

// Calls visit(ri, si, rj, sj) once for every pair of segments (ri before rj,
// or si < sj - 1 in one rod) that can come within `margin` of each other
// in `sweep` s: their midpoints no farther apart than the reach of the two
// capsules (half a segment + radius + what the segment sweeps at its
// velocity) plus `margin`. Grid pairs farther apart than that, with the
// radii scaled by max(1, radiusScale), are not visited: two segments are at
// least their midpoints' distance less their half lengths apart, so such a
// pair is neither within the margin of touch nor closing within the step
// (in a packed sac five in six of the 27 cells' segments were such pairs,
// each measured by closestSegmentSegment for nothing). Slow
// segments go into a uniform grid with cells as large as the reach of any
// two of them, O(n) for a coil, not O(n^2); a segment that sweeps more than
// a quarter of its own size in the step (a tip jolted at the catheter, a
// loop snapping) is fast and is paired with every segment directly: one
// such segment used to set the cells of all, and in a packed sac a cell
// three times as wide holds 27 times as many segments.
// With `threads` (else on this thread alone), the grid's cells are split
// into two parts of about equal segments, visited on two threads: visit then
// gets the part (0 or 1; the fast segments' pairs are part 0) and must only
// write what that part owns.
// With `candidates`, the pairs are kept from step to step (a Verlet list,
// scratch.h): while they still hold, only they are measured against the
// reaches and the margin, the grid is neither sorted nor walked; when they
// no longer do, the grid is searched with a skin of a quarter of the
// largest segment's size added to the margin and its pairs kept. They are
// not kept while a segment is fast. The pairs visited are those of the grid
// search without them: the same contacts, bit for bit.
template <class Visit>
void forEachNearPair(const Model& model, const State& state, bool sameRod, double margin, double sweep,
                     double radiusScale, Visit visit, DetectionThreads* threads = nullptr,
                     PairCandidates* candidates = nullptr) {
  const double scale = std::max(1.0, radiusScale);
  if (candidates && stillHolds(*candidates, state, sameRod, margin, scale, sweep)) {
    PairCandidates& c = *candidates;
    ++c.reuses;
    const long n = long(c.pairs.size());
    const auto visitPart = [&](int part, ContactScratch&) {
      for (long q = part ? n / 2 : 0, end = part ? n : n / 2; q < end; ++q) {
        const CandidatePair& p = c.pairs[size_t(q)];
        const size_t i = size_t(c.first[p.ki] + p.si), j = size_t(c.first[p.kj] + p.sj);
        const double apart = c.extentNow[i] + c.extentNow[j] + margin;
        if ((c.midNow[j] - c.midNow[i]).squaredNorm() > apart * apart) continue;
        visit(part, p.ki, p.si, p.kj, p.sj);
      }
    };
    if (threads) {
      threads->run(threads->splits(long(c.mid.size())), state.contactScratch, visitPart);
    } else {
      visitPart(0, state.contactScratch);
      visitPart(1, state.contactScratch);
    }
    return;
  }
  std::vector<GridSegment>& grid = state.contactScratch.grid;
  std::vector<GridSegment>& fast = state.contactScratch.fast;
  grid.clear();
  fast.clear();
  double size = 0;
  for (size_t k = 0; k < state.rods.size(); ++k) {
    const RodState& r = state.rods[k];
    if (!inSearch(r, sameRod)) continue;
    for (int e = 0; e + 1 < r.activeNodes; ++e) size = std::max(size, segmentSize(r, e));
  }
  double reach = size;
  for (size_t k = 0; k < state.rods.size(); ++k) {
    const RodState& r = state.rods[k];
    if (!inSearch(r, sameRod)) continue;
    for (int e = 0; e + 1 < r.activeNodes; ++e) {
      const double swept = segmentSweep(r, e, sweep);
      if (swept > 0.25 * size) fast.push_back({0, int(k), e});  // in (rod, segment) order
      else reach = std::max(reach, segmentSize(r, e) + swept);
    }
  }
  // Kept only while no segment is fast; a quarter of the largest segment's
  // size of skin lets them hold for a few micrometres' moves per step.
  PairCandidates* keep = fast.empty() ? candidates : nullptr;
  if (candidates) candidates->valid = false;
  const double skin = keep ? 0.25 * size : 0.0, searched = margin + skin;
  if (keep) startCandidates(*keep, state, sameRod, margin, scale, sweep, skin);
  const double cell = 2 * reach + searched;
  if (!(cell > 0) || !std::isfinite(cell)) return;  // no rod takes part (or positions are not finite)
  const auto isFast = [&](int k, int e) {
    return std::binary_search(fast.begin(), fast.end(), GridSegment{0, k, e}, [](const GridSegment& a, const GridSegment& b) {
      return a.rod != b.rod ? a.rod < b.rod : a.segment < b.segment;
    });
  };
  // Each pair once, first before second; the same filters as the grid's.
  const auto pairUp = [&](int ki, int si, int kj, int sj) {
    if (kj < ki || (kj == ki && sj < si)) std::swap(ki, kj), std::swap(si, sj);
    if (sameRod != (ki == kj)) return;
    if (sameRod && sj - si <= 1) return;
    if (model.rods[ki].role == RodRole::Catheter && model.rods[kj].role == RodRole::Catheter) return;
    visit(0, ki, si, kj, sj);
  };
  for (const GridSegment& f : fast) {
    const RodState& rf = state.rods[f.rod];
    const Vec3 mf = 0.5 * (rf.x[f.segment] + rf.x[f.segment + 1]);
    const double reachF = segmentSize(rf, f.segment) + segmentSweep(rf, f.segment, sweep);
    for (size_t k = 0; k < state.rods.size(); ++k) {
      const RodState& r = state.rods[k];
      if (!inSearch(r, sameRod) || (sameRod && int(k) != f.rod) || (!sameRod && int(k) == f.rod)) continue;
      for (int e = 0; e + 1 < r.activeNodes; ++e) {
        if (int(k) == f.rod && e == f.segment) continue;
        // A fast pair is met from its first segment only.
        if ((int(k) < f.rod || (int(k) == f.rod && e < f.segment)) && isFast(int(k), e)) continue;
        const double apart = (0.5 * (r.x[e] + r.x[e + 1]) - mf).norm();
        if (apart > reachF + segmentSize(r, e) + segmentSweep(r, e, sweep) + margin) continue;
        pairUp(f.rod, f.segment, int(k), e);
      }
    }
  }
  for (size_t k = 0; k < state.rods.size(); ++k) {
    const RodState& r = state.rods[k];
    if (!inSearch(r, sameRod)) continue;
    for (int e = 0; e + 1 < r.activeNodes; ++e) {
      if (!fast.empty() && isFast(int(k), e)) continue;
      const Vec3 mid = 0.5 * (r.x[e] + r.x[e + 1]), m = mid / cell;
      const double extent = reachOf(r, e, scale, sweep);
      grid.push_back({cellKey(cellIndex(m.x()), cellIndex(m.y()), cellIndex(m.z())), int(k), e, mid, extent});
    }
  }
  // By cell, and within a cell by rod and segment: a segment's partners of
  // its own rod (self-contact) or of the rods after it (between rods) are
  // then one stretch of each neighbour cell, and the others are not walked.
  const auto before = [](const GridSegment& a, const GridSegment& b) {
    if (a.cell != b.cell) return a.cell < b.cell;
    return a.rod != b.rod ? a.rod < b.rod : a.segment < b.segment;
  };
  std::sort(grid.begin(), grid.end(), before);
  // The 27 neighbour cells are looked up once per occupied cell and rod,
  // not once per segment: in a packed sac a cell holds tens of segments
  // (the binary searches were a fifth of a multi-coil plan's time,
  // docs/contact.md).
  using Iterator = std::vector<GridSegment>::const_iterator;
  using Range = std::pair<Iterator, Iterator>;
  const auto byCell = [](const GridSegment& a, const GridSegment& b) { return a.cell < b.cell; };
  const auto byRod = [](const GridSegment& a, const GridSegment& b) { return a.rod < b.rod; };
  // The cells of the first half of the segments, and the rest.
  const bool split = threads && threads->splits(long(grid.size()));
  auto middle = grid.cbegin() + long(split ? grid.size() / 2 : grid.size());
  while (middle != grid.cbegin() && middle != grid.cend() && (middle - 1)->cell == middle->cell) ++middle;
  const auto visitCells = [&](int part, ContactScratch&) {
    Range cells[27], near[27];
    const Iterator end = part ? grid.cend() : middle;
    for (Iterator run = part ? middle : grid.cbegin(); run != end;) {
      Iterator runEnd = run;
      while (runEnd != grid.cend() && runEnd->cell == run->cell) ++runEnd;
      const RodState& r0 = state.rods[run->rod];
      const Vec3 m = 0.5 * (r0.x[run->segment] + r0.x[run->segment + 1]) / cell;
      const long cx = std::lround(std::floor(m.x())), cy = std::lround(std::floor(m.y())), cz = std::lround(std::floor(m.z()));
      int n = 0;
      for (long dx = -1; dx <= 1; ++dx)
        for (long dy = -1; dy <= 1; ++dy)
          for (long dz = -1; dz <= 1; ++dz)
            cells[n++] = std::equal_range(grid.cbegin(), grid.cend(), GridSegment{cellKey(cx + dx, cy + dy, cz + dz), 0, 0}, byCell);
      for (Iterator group = run; group != runEnd;) {
        // The segments of one rod in this cell, and their stretch of each neighbour cell.
        const GridSegment key{0, group->rod, 0};
        const Iterator groupEnd = std::upper_bound(group, runEnd, key, byRod);
        for (int c = 0; c < 27; ++c)
          near[c] = sameRod ? std::equal_range(cells[c].first, cells[c].second, key, byRod)
                            : Range{std::upper_bound(cells[c].first, cells[c].second, key, byRod), cells[c].second};
        const bool catheter = model.rods[group->rod].role == RodRole::Catheter;
        const bool asleep = state.rods[group->rod].asleep;
        for (Iterator gIt = group; gIt != groupEnd; ++gIt) {
          const GridSegment& gi = *gIt;
          for (const Range& range : near)
            for (Iterator it = range.first; it != range.second; ++it) {
              const GridSegment& gj = *it;
              // Each pair once, i before j; in one rod, not neighbours.
              if (sameRod && gj.segment - gi.segment <= 1) continue;
              if (catheter && model.rods[gj.rod].role == RodRole::Catheter) continue;
              // Two sleeping rods do not move: nothing between them changes.
              if (asleep && state.rods[gj.rod].asleep) continue;
              const double apart = gi.extent + gj.extent + searched, d2 = (gj.mid - gi.mid).squaredNorm();
              if (d2 > apart * apart) continue;
              if (keep) {
                keep->found[part].push_back({gi.rod, gi.segment, gj.rod, gj.segment});
                const double tight = gi.extent + gj.extent + margin;
                if (d2 > tight * tight) continue;
              }
              visit(part, gi.rod, gi.segment, gj.rod, gj.segment);
            }
        }
        group = groupEnd;
      }
      run = runEnd;
    }
  };
  if (threads) {
    threads->run(split, state.contactScratch, visitCells);
  } else {
    visitCells(0, state.contactScratch);
    visitCells(1, state.contactScratch);
  }
  if (keep) {
    keep->pairs.clear();
    for (const std::vector<CandidatePair>& f : keep->found) keep->pairs.insert(keep->pairs.end(), f.begin(), f.end());
    keep->valid = true;
    ++keep->builds;
  }
}

// Mean radius of segment e of r.
double segmentRadius(const RodState& r, int e) { return 0.5 * (r.nodes[e].radius + r.nodes[e + 1].radius); }

// Whether the segments share an end (a deploying coil leaving its catheter
// tip): such pairs are not contacts.
bool shareAnEnd(const Vec3& a0, const Vec3& a1, const Vec3& b0, const Vec3& b1, double touch) {
  return (a0 - b0).norm() < touch || (a0 - b1).norm() < touch || (a1 - b0).norm() < touch || (a1 - b1).norm() < touch;
}

}  // namespace

void detectRodContacts(const Model& model, State& state, double h, bool sameRod, double margin, const ContactLaw& law,
                       const ContactLaw& catheterLaw) {
  // Fresh lists for this step: the old ones move to a per-rod previous buffer.
  std::vector<std::vector<ContactPoint>>& previous = state.contactScratch.previous;
  previous.resize(state.rods.size());
  for (size_t k = 0; k < state.rods.size(); ++k) {
    if (sameRod && state.rods[k].asleep) continue;  // keeps its self contacts (physics/sleep.h)
    std::vector<ContactPoint>& list = sameRod ? state.rods[k].contact.self : state.rods[k].contact.rod;
    std::swap(previous[k], list);
    list.clear();
  }
  // No contact distance, no contacts: not even a closing pair's barrier,
  // which would stop centre lines from crossing.
  if (!(law.radiusScale > 0)) {
    for (RodState& r : state.rods)
      if (!(sameRod && r.asleep)) (sameRod ? r.contact.selfForce : r.contact.rodForce).assign(r.x.size(), 0.0);
    return;
  }
  // Between rods, a pair needs two rods taking part (a plan's first coil is alone in its sac).
  int rodsTakingPart = 0;
  for (const RodState& r : state.rods) rodsTakingPart += takesPart(r);
  const bool searched = sameRod || rodsTakingPart >= 2;
  // Whether the pair is in contact or closing within the step; its closest points in p.
  const auto inContact = [&](int ki, int si, int kj, int sj, SegmentPair& p) {
    const RodState &ri = state.rods[ki], &rj = state.rods[kj];
    const Vec3 &a0 = ri.x[si], &a1 = ri.x[si + 1], &b0 = rj.x[sj], &b1 = rj.x[sj + 1];
    const double ra = segmentRadius(ri, si), rb = segmentRadius(rj, sj);
    if (!sameRod && shareAnEnd(a0, a1, b0, b1, 1e-3 * std::min(ra, rb))) return false;
    p = closestSegmentSegment(a0, a1, b0, b1);
    const double gap = p.distance - law.radiusScale * (ra + rb);
    if (p.distance <= 1e-12 * ra) return false;
    // Closing speed of the pair along the line of centres, at the start of the step.
    const Vec3 normal = (p.p - p.q) / p.distance;
    const Vec3 va = (1 - p.s) * ri.v[si] + p.s * ri.v[si + 1];
    const Vec3 vb = (1 - p.t) * rj.v[sj] + p.t * rj.v[sj + 1];
    const bool closing = -gap - h * normal.dot(va - vb) > 0;
    return gap <= margin || closing;
  };
  // The two contacts of a pair in contact, one in each rod's list.
  const auto add = [&](int ki, int si, int kj, int sj, const SegmentPair& p) {
    const RodState &ri = state.rods[ki], &rj = state.rods[kj];
    const double ra = segmentRadius(ri, si), rb = segmentRadius(rj, sj);
    const double touch = law.radiusScale * (ra + rb);
    const double gap = p.distance - touch;
    const Vec3 normal = (p.p - p.q) / p.distance;
    const Vec3 va = (1 - p.s) * ri.v[si] + p.s * ri.v[si + 1];
    const Vec3 vb = (1 - p.t) * rj.v[sj] + p.t * rj.v[sj + 1];
    const bool closing = -gap - h * normal.dot(va - vb) > 0;
    ContactPoint c;
    c.segment = si, c.other = kj, c.otherSegment = sj;
    c.s = p.s, c.otherS = p.t;
    c.normal = normal;
    c.anchor = p.q;
    c.radius = touch;
    c.gap = gap;
    c.otherVelocity = vb;
    c.otherMass = (1 - p.t) * rj.nodes[sj].mass + p.t * rj.nodes[sj + 1].mass;
    c.closing[0] = closing;
    ContactPoint d = c;
    d.segment = sj, d.other = ki, d.otherSegment = si;
    d.s = p.t, d.otherS = p.s;
    d.normal = -c.normal;
    d.anchor = p.p;
    d.otherVelocity = va;
    d.otherMass = (1 - p.s) * ri.nodes[si].mass + p.s * ri.nodes[si + 1].mass;
    (sameRod ? state.rods[ki].contact.self : state.rods[ki].contact.rod).push_back(c);
    (sameRod ? state.rods[kj].contact.self : state.rods[kj].contact.rod).push_back(d);
  };
  // The reach includes what a segment sweeps in the step at its start
  // velocity, so a pair that would meet within the step is found (response.h).
  // On two threads each part keeps its pairs, added after in the parts'
  // order: the lists are sorted below by a total order anyway, so they come
  // out the same whatever the thread count.
  ContactScratch& scratch = state.contactScratch;
  scratch.parts[0].pairs.clear();
  scratch.parts[1].pairs.clear();
  const bool twoThreads = scratch.threads.count() > 1;
  if (searched)
    forEachNearPair(
        model, state, sameRod, margin, h, law.radiusScale,
        [&](int part, int ki, int si, int kj, int sj) {
          SegmentPair p;
          if (!inContact(ki, si, kj, sj, p)) return;
          if (twoThreads) scratch.parts[part].pairs.push_back({ki, si, kj, sj, p});
          else add(ki, si, kj, sj, p);
        },
        &scratch.threads,
        scratch.keepPairCandidates ? (sameRod ? &scratch.selfCandidates : &scratch.rodCandidates) : nullptr);
  for (const DetectionPart& part : scratch.parts)
    for (const FoundPair& f : part.pairs) add(f.ki, f.si, f.kj, f.sj, f.p);
  for (size_t k = 0; k < state.rods.size(); ++k) {
    RodState& r = state.rods[k];
    if (sameRod && r.asleep) continue;
    std::vector<ContactPoint>& list = sameRod ? r.contact.self : r.contact.rod;
    // A total order, so that the order pairs were found in does not matter
    // (two other rods can touch one segment at equal segment indices).
    std::sort(list.begin(), list.end(), [](const ContactPoint& x, const ContactPoint& y) {
      if (x.segment != y.segment) return x.segment < y.segment;
      return x.otherSegment != y.otherSegment ? x.otherSegment < y.otherSegment : x.other < y.other;
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

namespace {

// The contact of rod k's list between its segment si and segment sj of rod kj, if any.
const ContactPoint* listed(const State& state, bool sameRod, int k, int si, int kj, int sj) {
  const std::vector<ContactPoint>& list = sameRod ? state.rods[k].contact.self : state.rods[k].contact.rod;
  auto it = std::lower_bound(list.begin(), list.end(), si, [](const ContactPoint& c, int seg) { return c.segment < seg; });
  for (; it != list.end() && it->segment == si; ++it)
    if (it->other == kj && it->otherSegment == sj) return &*it;
  return nullptr;
}

}  // namespace

std::optional<Failure> checkRodContacts(const Model& model, const State& state, bool sameRod, double margin,
                                        double radiusScale) {
  // A pair left out at the start was more than `margin` apart: it can only
  // have gone deeper than the tolerance if its two segments together moved
  // more than margin + tolerance (the distance between two segments changes
  // by at most the largest displacement of their end points on each side).
  double moved = 0, smallest = INFINITY;
  for (const RodState& r : state.rods) {
    if (!takesPart(r) || r.work.x0.size() < size_t(r.activeNodes)) continue;
    for (int i = 0; i < r.activeNodes; ++i) moved = std::max(moved, (r.x[i] - r.work.x0[i]).norm());
    for (int i = 0; i < r.activeNodes; ++i) smallest = std::min(smallest, r.nodes[i].radius);
  }
  if (!(moved > 0)) return std::nullopt;
  const bool scan = 2 * moved > margin + 2 * kMissedContact * radiusScale * smallest;
  std::optional<Failure> missed;
  double deepest = 0;
  const auto check = [&](int, int ki, int si, int kj, int sj) {
    const RodState &ri = state.rods[ki], &rj = state.rods[kj];
    const Vec3 &a0 = ri.x[si], &a1 = ri.x[si + 1], &b0 = rj.x[sj], &b1 = rj.x[sj + 1];
    const double ra = segmentRadius(ri, si), rb = segmentRadius(rj, sj);
    if (!sameRod && shareAnEnd(a0, a1, b0, b1, 1e-3 * std::min(ra, rb))) return;
    const double touch = radiusScale * (ra + rb);
    const double depth = touch - closestSegmentSegment(a0, a1, b0, b1).distance;
    if (depth <= kMissedContact * touch || depth <= deepest) return;
    const ContactPoint* c = listed(state, sameRod, ki, si, kj, sj);
    // In the step's implicit solve: the penalty's business (one the solve let go of is not).
    if (c && c->entered[0] != Entry::Released && (c->gap < 0 || c->closing[0] || c->entered[0] != Entry::No)) return;
    deepest = depth;
    missed = badRod(model.rods[ki].name, "went " + std::to_string(int(std::lround(depth * 1e6))) + " um into rod '" +
                                             model.rods[kj].name + "' beam " + std::to_string(sj) +
                                             " within the step, outside its contacts");
    missed->kind = FailureKind::MissedContact;
    missed->beam = si;
    missed->quantity = "depth";
    missed->value = depth, missed->limit = kMissedContact * touch;
  };
  if (scan) {
    forEachNearPair(model, state, sameRod, 0.0, 0.0, radiusScale, check);
  } else {
    // Only the pairs found at the start but not touching nor closing can have been missed.
    for (size_t k = 0; k < state.rods.size(); ++k) {
      if (!inSearch(state.rods[k], sameRod)) continue;
      for (const ContactPoint& c : sameRod ? state.rods[k].contact.self : state.rods[k].contact.rod)
        if (int(k) < c.other || (int(k) == c.other && c.segment < c.otherSegment))
          if (takesPart(state.rods[c.other]) && c.otherSegment + 1 < state.rods[c.other].activeNodes)
            check(0, int(k), c.segment, c.other, c.otherSegment);
    }
  }
  return missed;
}

double safeStaticFraction(const State& state, int rod, std::span<const Vec3> dx, bool sameRod, double radiusScale) {
  const RodState& r = state.rods[rod];
  if (!takesPart(r) || !(radiusScale > 0)) return 1.0;
  const int n = r.activeNodes;
  // Each segment: how far it moves at most (as far as its farther node).
  std::vector<double>& moves = state.contactScratch.moves;
  moves.assign(n - 1, 0.0);
  for (int e = 0; e + 1 < n; ++e) moves[e] = std::max(dx[e].norm(), dx[e + 1].norm());
  double fraction = 1.0;
  // The closest points of two segments move relative to each other by a
  // convex combination of their end nodes' relative motions, so by at most
  // the largest of those: loops resting on each other and moving together
  // are not held back. `db` is the other segment's node motion (zero for a
  // rod held still). Pairs already within a quarter of r1 + r2 (a coil
  // inside its catheter) are the penalty's business: a limit would stall
  // the update there.
  const auto limit = [&](int i, const Vec3& b0, const Vec3& b1, const Vec3& db0, const Vec3& db1, double bound,
                         double touch) {
    const Vec3 &a0 = r.x[i], &a1 = r.x[i + 1];
    // A cheap lower bound of the distance first: most pairs are far apart.
    const double apart = (0.5 * (a0 + a1 - b0 - b1)).norm() - 0.5 * ((a1 - a0).norm() + (b1 - b0).norm());
    if (!(fraction * bound > 0.5 * apart)) return;
    const double move = std::max({(dx[i] - db0).norm(), (dx[i] - db1).norm(), (dx[i + 1] - db0).norm(),
                                  (dx[i + 1] - db1).norm()});
    if (!(fraction * move > 0.5 * apart)) return;
    const double d = closestSegmentSegment(a0, a1, b0, b1).distance;
    if (d > 0.25 * touch && fraction * move > 0.5 * d) fraction = 0.5 * d / move;
  };
  if (sameRod) {
    for (int i = 0; i + 1 < n; ++i)
      for (int j = i + 2; j + 1 < n; ++j)
        limit(i, r.x[j], r.x[j + 1], dx[j], dx[j + 1], moves[i] + moves[j],
              radiusScale * (segmentRadius(r, i) + segmentRadius(r, j)));
    return fraction;
  }
  const Vec3 still = Vec3::Zero();
  for (size_t k = 0; k < state.rods.size(); ++k) {
    const RodState& o = state.rods[k];
    if (int(k) == rod || !takesPart(o)) continue;
    for (int i = 0; i + 1 < n; ++i)
      for (int j = 0; j + 1 < o.activeNodes; ++j) {
        const double ra = segmentRadius(r, i), rb = segmentRadius(o, j);
        if (shareAnEnd(r.x[i], r.x[i + 1], o.x[j], o.x[j + 1], 1e-3 * std::min(ra, rb))) continue;
        limit(i, o.x[j], o.x[j + 1], still, still, moves[i], radiusScale * (ra + rb));
      }
  }
  return fraction;
}

}  // namespace coilsim
