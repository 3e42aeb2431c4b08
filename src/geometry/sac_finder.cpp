#include "geometry/sac_finder.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include <Eigen/Eigenvalues>

#include "geometry/sac_morphology.h"

namespace coilsim::geometry {
namespace {

// Largest balls first, each keeping only the balls whose centres lie outside it.
std::vector<Ball> peaks(std::vector<Ball> balls) {
  std::sort(balls.begin(), balls.end(), [](const Ball& a, const Ball& b) { return a.radius > b.radius; });
  std::vector<Ball> kept;
  for (const Ball& b : balls) {
    bool covered = false;
    for (const Ball& k : kept)
      if ((b.centre - k.centre).norm() < k.radius) {
        covered = true;
        break;
      }
    if (!covered) kept.push_back(b);
  }
  return kept;
}

double median(std::vector<double> v) {
  if (v.empty()) return 0;
  std::nth_element(v.begin(), v.begin() + long(v.size() / 2), v.end());
  return v[v.size() / 2];
}

Vec3 meanDirection(const std::vector<Vec3>& dirs) {
  Vec3 s = Vec3::Zero();
  for (const Vec3& d : dirs) s += d;
  return s.norm() > 0 ? Vec3(s.normalized()) : Vec3::UnitZ();
}

std::string mm(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.2f", x);
  return buf;
}

std::string at(const Vec3& p) { return "(" + mm(p.x()) + ", " + mm(p.y()) + ", " + mm(p.z()) + ")"; }

// The parent vessel behind the neck and the neck plane, for a sac ball and its axis.
bool placeNeck(const MeshQuery& query, const std::vector<Ball>& balls, SacFinding& s) {
  const Vec3 c = s.centre, d = s.axis;
  s.centreLine.clear();
  for (const Ball& b : balls)
    if ((b.centre - c).norm() > s.radius && b.radius < s.radius) s.centreLine.push_back(b);
  // Entry of the axis ray into the vessel balls: the first is where the
  // parent vessel begins.
  double entry = INFINITY;
  const Ball* first = nullptr;
  for (const Ball& b : s.centreLine) {
    const Vec3 oc = c - b.centre;
    const double along = oc.dot(d), disc = along * along - (oc.squaredNorm() - b.radius * b.radius);
    if (disc < 0) continue;
    const double t = -along - std::sqrt(disc);
    if (t > 0 && t < entry) entry = t, first = &b;
  }
  if (!first || entry > 4 * s.radius) return false;
  // The parent vessel there as a straight tube: the axis of the vessel
  // balls about the entry (principal direction of their centres), its
  // radius the distance from that axis, at the foot of the sac's axis, to the
  // wall. The neck plane is parallel to the tube's axis and lies where the
  // sac's axis comes within that radius of it: the vessel wall continued
  // across the ostium. (The union of the balls would put it higher: the
  // medial axis runs on from the vessel up through the ostium into the sac.)
  const Vec3 entered = c + entry * d;
  std::vector<const Ball*> about;
  for (const Ball& b : s.centreLine)
    if ((b.centre - entered).norm() < 3 * first->radius) about.push_back(&b);
  if (about.size() < 3) return false;
  Vec3 mean = Vec3::Zero();
  for (const Ball* b : about) mean += b->centre;
  mean /= double(about.size());
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
  for (const Ball* b : about) cov += (b->centre - mean) * (b->centre - mean).transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(cov);
  const Vec3 e = eig.eigenvectors().col(2).normalized();
  s.vesselDirection = e;
  s.vesselPoint = mean + (c - mean).dot(e) * e;
  s.vesselRadius = query.closest(s.vesselPoint).distance;
  // The sac's axis across the tube (its part along the tube is the opening's
  // lean along the vessel, not the ostium's).
  const Vec3 across = d - d.dot(e) * e;
  if (across.norm() > 0.5) s.axis = across.normalized();
  const Vec3 a = c - s.vesselPoint, n = s.axis;
  // |a + t n| across e equals the radius; a has no part along e.
  const double B = 2 * a.dot(n), C = a.squaredNorm() - s.vesselRadius * s.vesselRadius;
  const double disc = B * B - 4 * C;
  entry = disc >= 0 ? 0.5 * (-B - std::sqrt(disc)) : -1;
  if (!(entry > 0)) {
    // The sac sits on the vessel's axis (a bifurcation aneurysm on a wide
    // junction): no tube to continue. The neck is then where the inscribed
    // radius along the axis has fallen to the vessel's (the balls' median).
    std::vector<double> radii;
    for (const Ball* b : about) radii.push_back(b->radius);
    const double vessel = median(radii);
    s.vesselRadius = vessel;
    entry = -1;
    for (double t = 0; t < 4 * s.radius; t += 0.02 * s.radius)
      if (query.closest(c + t * n).distance <= vessel) {
        entry = t;
        break;
      }
  }
  if (!(entry > 0) || entry > 4 * s.radius) return false;
  s.neck = Plane{c + entry * n, -n};
  // A plane that grazes a curved parent vessel cuts a sliver off its wall,
  // and the ostium then runs along the vessel: move the plane toward the
  // dome until the ostium is no wider than the sac's inscribed diameter
  // (plus a fifth: a saccular neck is narrower than its dome).
  for (int step = 0; step < 40; ++step) {
    const SacMorphology m = measureSac(query.mesh(), s.neck, c, 0, true);
    if (m.neckWidth <= 2.4 * s.radius) break;
    s.neck.point += 0.05 * s.radius * s.neck.normal;
    if (!(s.neck.side(c) > 0)) return false;
  }
  return true;
}

}  // namespace

std::vector<std::vector<Vec3>> openings(const MeshQuery& query, const Vec3& centre, double radius, int rays,
                                        double freeFactor) {
  const std::vector<Vec3> dirs = sphereDirections(rays);
  std::vector<int> free;
  for (int i = 0; i < int(dirs.size()); ++i)
    if (freeLength(query, centre, dirs[i], 1.05 * freeFactor * radius) > freeFactor * radius) free.push_back(i);
  // Union-find over neighbouring free directions (about twice the lattice spacing apart).
  const double near = std::cos(2.2 * std::sqrt(4 * M_PI / std::max(rays, 1)));
  std::vector<int> parent(free.size());
  std::iota(parent.begin(), parent.end(), 0);
  const auto root = [&](int i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  };
  for (size_t i = 0; i < free.size(); ++i)
    for (size_t j = i + 1; j < free.size(); ++j)
      if (dirs[free[i]].dot(dirs[free[j]]) > near) parent[root(int(i))] = root(int(j));
  std::vector<std::vector<Vec3>> groups;
  std::vector<int> slot(free.size(), -1);
  for (size_t i = 0; i < free.size(); ++i) {
    const int r = root(int(i));
    if (slot[r] < 0) slot[r] = int(groups.size()), groups.emplace_back();
    groups[slot[r]].push_back(dirs[free[i]]);
  }
  // A handful of rays slipping through a seam are not an opening.
  std::erase_if(groups, [](const std::vector<Vec3>& g) { return g.size() < 3; });
  return groups;
}

SacFinding findSac(const MeshQuery& query, const SacFinderOptions& o) {
  SacFinding s;
  const std::vector<Ball> balls = medialBalls(query, o.samples);
  if (balls.empty()) {
    s.problem = "no inscribed ball found: the surface encloses no volume";
    return s;
  }
  std::vector<Vec3> axisDirs;
  if (o.sacPoint) {
    // The user's point: the deepest ball near it, its largest opening.
    Vec3 c = *o.sacPoint;
    if (!query.inside(c)) {
      s.problem = "the sac point " + at(c) + " is not inside the surface";
      return s;
    }
    const double r = deepestNear(query, c, std::max(0.25 * query.closest(c).distance, 1e-3));
    auto groups = openings(query, c, r, o.rays, o.freeFactor);
    if (groups.empty()) {
      s.problem = "no opening seen from the sac point: the sac at " + at(c) + " shows no neck";
      return s;
    }
    std::sort(groups.begin(), groups.end(), [](const auto& a, const auto& b) { return a.size() > b.size(); });
    s.candidates.push_back({c, r});
    axisDirs = groups.front();
  } else {
    const std::vector<Ball> top = peaks(balls);
    std::vector<double> radii;
    for (const Ball& b : top) radii.push_back(b.radius);
    const double typical = median(radii);
    // A sac: one opening, and wider than the vessel behind it (a capped
    // vessel end also has one opening, but its own vessel's width).
    std::vector<SacFinding> sacs;
    for (const Ball& p : top) {
      if (p.radius < o.sacOverVessel * typical) break;  // sorted by radius
      SacFinding trial;
      trial.centre = p.centre;
      trial.radius = deepestNear(query, trial.centre, 0.25 * p.radius);
      bool seen = false;
      for (const SacFinding& q : sacs) seen = seen || (q.centre - trial.centre).norm() < q.radius + trial.radius;
      if (seen) continue;
      const auto groups = openings(query, trial.centre, trial.radius, o.rays, o.freeFactor);
      if (groups.size() != 1) continue;
      trial.axis = meanDirection(groups.front());
      const bool placed = placeNeck(query, balls, trial);
      if (!placed || trial.radius < o.sacOverVessel * trial.vesselRadius) continue;
      trial.candidates.push_back({trial.centre, trial.radius});
      sacs.push_back(std::move(trial));
    }
    for (const SacFinding& b : sacs) s.candidates.push_back(b.candidates.front());
    if (sacs.empty()) {
      s.problem = "no sac found: no inscribed ball is both " + mm(o.sacOverVessel) + " times wider than the vessel behind it " +
                  "(median vessel radius " + mm(typical) + ") and open on that side only";
      return s;
    }
    if (sacs.size() > 1) {
      s.problem = std::to_string(sacs.size()) + " candidate sacs:";
      for (const SacFinding& b : sacs) s.problem += " " + at(b.centre) + " (inscribed radius " + mm(b.radius) + ")";
      return s;
    }
    s = std::move(sacs.front());
    s.found = true;
    return s;
  }
  s.centre = s.candidates.front().centre;
  s.radius = s.candidates.front().radius;
  s.axis = meanDirection(axisDirs);
  if (!placeNeck(query, balls, s)) {
    s.problem = "no clear neck: no parent vessel behind the opening of the sac at " + at(s.centre);
    return s;
  }
  s.found = true;
  return s;
}

}  // namespace coilsim::geometry
