#pragma once
// The pictures of `coilsim validate` / `diagnose`, drawn in software into an
// RGBA buffer (no GL, so they work on any machine, with or without a
// display): the node error along the arc length of every stage, and per
// stage the simulated coil coloured by its error beside the measured centre
// line, in two orthographic views (side: gravity down; top: looking along
// gravity).
#include <cstdint>
#include <string>
#include <vector>

#include "validation/compare.h"

namespace coilsim::app {

struct Canvas {
  int width = 0, height = 0;
  std::vector<std::uint8_t> pixels;  // (height x width x 4) RGBA, first row at the top
};

// |x_sim - x_meas| (mm) against s (mm), one curve per stage, and each
// stage's noise floor sqrt(3) point_sigma dashed.
Canvas plotErrorAlongArc(const std::vector<validation::StageComparison>& stages, const std::vector<std::string>& names,
                         int width = 900, int height = 500);

// The stage's simulated nodes coloured by |x_sim - x_meas| (blue 0 to red at
// the stage's largest error) over the measured points (grey) and their
// spline (black).
Canvas plotOverlay(const validation::StageComparison& stage, const validation::Stage& measured, const Vec3& gravity,
                   const Vec3& exitDirection, const std::string& title, int width = 1100, int height = 520);

// Writes a PNG; false with `error` naming the path on failure, or when this
// build has no PNG writer (built without graphics).
bool savePng(const std::string& path, const Canvas& canvas, std::string& error);

}  // namespace coilsim::app
