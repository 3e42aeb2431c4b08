#pragma once
// What a clinician asks of a coil in a sac, computed from geometry, never
// guessed: packing density (coil volume in the sac / sac volume, the sac
// closed by the neck plane), neck coverage, protrusion into the parent
// vessel, wall forces, and a Raymond-Roy-like occlusion class. SI inside.
#include <optional>
#include <string>
#include <vector>

#include "physics/model.h"
#include "physics/state.h"
#include "planning/sac_geometry.h"

namespace coilsim::planning {

// Coil centre lines as metrics read them: one polyline per coil rod.
struct CoilLines {
  std::vector<std::vector<Vec3>> lines;  // m
  double radius = 0;                     // primary coil outer radius, m (the largest, when radii differ)
  std::vector<double> radii;             // per line, m (a sequence of coils of different primary
                                         // diameters); empty: every line has `radius`
  double radiusOf(size_t line) const { return line < radii.size() ? radii[line] : radius; }
};

// The active nodes of every coil-role rod of `model`. A deployment chain
// starts with catheter nodes (0..Deployment::tipNode); the coil leaves the
// catheter at the tip node, so its line starts there: pass skipNodes =
// tipNode to leave out the nodes before it (0 for the rigid tip).
CoilLines coilLines(const Model& model, const State& state, int chainRod = -1, int skipNodes = 0);

// The neck opening sampled once: centres of square cells of the neck plane
// that are inside the surface and connected to the cell nearest the plane's
// point (so a plane that also cuts the vessel elsewhere counts only the neck).
struct NeckGrid {
  Vec3 u = Vec3::UnitX(), v = Vec3::UnitY();  // in-plane axes
  std::vector<Vec3> cells;                    // m, on the plane
  double cellArea = 0;                        // m^2
  double area() const { return cellArea * double(cells.size()); }
};
// `resolution` cells along the larger side of the opening's bounding box.
// An empty grid means the plane does not meet the surface near its point.
NeckGrid sampleNeck(const Sac& sac, int resolution = 64);

struct MetricOptions {
  // A neck cell counts as covered when a coil within this height above the
  // plane, projected onto it, lies within one coil radius of the cell.
  double coverageBand = 1e-3;  // m
  // Coil on the vessel side of the neck plane (inside the surface) longer
  // than this counts as a protrusion (a loop, not a touch of the plane).
  double protrusionLength = 0.5e-3;  // m
};

struct SacMetrics {
  double sacVolume = 0;         // m^3, enclosed volume on the sac side of the neck plane
  double coilLengthInSac = 0;   // m
  double coilVolume = 0;        // m^3, pi r^2 times the length in the sac
  double packingDensity = 0;    // coilVolume / sacVolume
  double neckCoverage = 0;      // covered share of the neck opening, 0-1
  double protrudingLength = 0;  // m of coil inside the surface beyond the neck plane
  double maxProtrusionDepth = 0;  // m beyond the neck plane
  bool protruding = false;
};

// Measures one configuration. `sacVolume` is sacVolume(sac), computed once by the caller.
SacMetrics measureSac(const Sac& sac, double sacVolume, const NeckGrid& neck, const CoilLines& coil,
                      const MetricOptions& options = {});

// Raymond-Roy-like predicted occlusion class from packing density and neck
// coverage (thresholds and sources in docs/planning.md):
//  1 (complete): packing >= 0.24 and neck coverage >= 0.5
//  2 (residual neck): packing >= 0.24 and neck coverage < 0.5, or packing in [0.20, 0.24)
//  3 (residual aneurysm): packing < 0.20
int occlusionClass(double packingDensity, double neckCoverage);
std::string occlusionClassName(int cls);

// A run's wall load over time. The figure shown everywhere is the
// sustained load of the contact layer (physics/contact/wall_load.h: the
// largest node force the wall carried at every step of the last 5 ms),
// which the State keeps; this adds what a plan also tabulates: its mean
// over the steps it was not zero (the time the coil pressed on the wall)
// and the time it spent above a safety threshold. The mean is of the same
// figure as the maximum, so it never exceeds it (a mean of single-step
// node forces did, by the penalty's spikes: 25 mN beside a 0.1 mN maximum).
struct WallForceStats {
  double max = 0;         // N, largest sustained load (WallLoad::max)
  double peak = 0;        // N, largest node force in any single step (penalty spikes included)
  double sum = 0;         // N, the sustained load summed over the steps it was > 0
  long samples = 0;       // steps with a sustained load > 0
  double timeAbove = 0;   // s with the sustained load above the threshold
  double mean() const { return samples ? sum / double(samples) : 0.0; }
  // After a step taken: the state's sustained load (state.stats.wallLoad).
  void add(const State& state, double dt, double threshold);
};

}  // namespace coilsim::planning
