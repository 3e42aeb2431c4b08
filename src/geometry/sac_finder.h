#pragma once
// Finds an aneurysm sac and its neck on a closed vessel surface (a sidewall
// or bifurcation aneurysm on a parent vessel with capped ends), from the
// geometry alone. Mesh units (millimetres for files and phantoms).
//
// 1. Inscribed balls (medial_balls.h): the vessels' centre lines and radii.
// 2. Peaks: the largest balls, each suppressing the balls centred inside it.
//    A vessel gives a chain of peaks of about its radius; the sac a peak
//    well above the typical (median) peak radius.
// 3. Openings: from a peak, rays whose free length exceeds `freeFactor`
//    times its radius, grouped by angular adjacency. A tube has two
//    openings (along its axis), a junction three, a capped end one with the
//    tube's radius, a sac one (its neck) with a radius above the vessels'.
// 4. Neck: the axis from the sac centre through its opening (mean free
//    direction) meets the parent vessel (the inscribed balls centred
//    outside the sac's deepest ball); the balls there are a straight tube
//    (principal direction, radius to the wall). The neck plane is parallel
//    to the tube and lies where the sac's axis comes within the tube's
//    radius of its axis: the vessel wall continued across the ostium, as a
//    phantom's sidecar defines it. Fall-backs and their reasons in
//    docs/planning.md, "Cases from a patient's surface".
// Unsure (several sacs, no opening, no vessel behind the opening) it says so
// and finds nothing: the caller asks for a point in the sac.
#include <optional>
#include <string>
#include <vector>

#include "geometry/medial_balls.h"
#include "geometry/volume.h"

namespace coilsim::geometry {

struct SacFinderOptions {
  std::optional<Vec3> sacPoint;  // a point in the sac: skip the search for candidates
  int samples = 6000;            // triangles sampled for inscribed balls
  int rays = 500;                // rays cast per candidate
  double freeFactor = 1.6;       // a ray is free when longer than this times the ball radius
  double sacOverVessel = 1.15;   // a sac's ball is at least this times the median peak radius
};

struct SacFinding {
  bool found = false;
  std::string problem;            // why nothing was found (empty when found)
  std::vector<Ball> candidates;   // sac-like peaks (several: ambiguous)
  Vec3 centre = Vec3::Zero();     // deepest point of the sac
  double radius = 0;              // its inscribed radius
  Vec3 axis = Vec3::UnitZ();      // unit, from the centre through the neck toward the parent vessel
  Plane neck;                     // normal into the sac
  Vec3 vesselPoint = Vec3::Zero();      // parent vessel centre line nearest the neck
  Vec3 vesselDirection = Vec3::UnitX(); // its unit tangent there
  double vesselRadius = 0;              // its radius there
  std::vector<Ball> centreLine;   // inscribed balls of the vessels (not of the sac), for drawing
};

// Never throws on a usable surface; an empty result says why in `problem`.
SacFinding findSac(const MeshQuery& query, const SacFinderOptions& options = {});

// The free rays of `centre` grouped into openings (each a list of unit
// directions), for a ball of `radius`.
std::vector<std::vector<Vec3>> openings(const MeshQuery& query, const Vec3& centre, double radius,
                                        int rays, double freeFactor);

}  // namespace coilsim::geometry
