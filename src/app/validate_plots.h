#pragma once
// The pictures of `coilsim validate` / `diagnose`, drawn in software into an
// RGBA buffer (no GL, so they work on any machine, with or without a
// display): the node error along the arc length of every stage, and per
// stage the simulated coil coloured by its error beside the measured centre
// line, in two orthographic views (side: gravity down; top: looking along
// gravity).
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "validation/compare.h"

namespace coilsim::app {

struct Canvas {
  int width = 0, height = 0;
  std::vector<std::uint8_t> pixels;  // (height x width x 4) RGBA, first row at the top
};

// The one colour scale of node error in every validation picture (the
// window's 3D coil and its legend, the overlay PNGs): fixed, not relative to
// the picture's largest error, so that a 0.003 mm fit never looks as red as
// a 1.3 mm miss. Logarithmic from kErrorColourLowMm (blue; anything below
// too) to kErrorColourHighMm (red; anything above too), cyan, yellow between.
constexpr double kErrorColourLowMm = 0.01, kErrorColourHighMm = 1.0;
// Where an error (mm) falls on the scale: 0 at or below low, 1 at or above
// high, log10-linear between; 0 for a non-finite or negative error.
double errorScalePosition(double errorMm);
// The scale's colour at a position in [0, 1] (clamped): RGB in [0, 1].
std::array<float, 3> errorScaleColour(double position);
// "node error: log scale, blue <= 0.01 mm, red >= 1 mm"
std::string errorScaleLegend();

// |x_sim - x_meas| (mm) against s (mm), one curve per stage, and each
// stage's noise floor sqrt(3) point_sigma dashed.
Canvas plotErrorAlongArc(const std::vector<validation::StageComparison>& stages, const std::vector<std::string>& names,
                         int width = 900, int height = 500);

// The stage's simulated nodes coloured by |x_sim - x_meas| on the fixed
// error scale above (its colour bar with ticks in mm beside) over the measured points (grey) and their
// spline (black).
Canvas plotOverlay(const validation::StageComparison& stage, const validation::Stage& measured, const Vec3& gravity,
                   const Vec3& exitDirection, const std::string& title, int width = 1100, int height = 520);

// Writes a PNG; false with `error` naming the path on failure, or when this
// build has no PNG writer (built without graphics).
bool savePng(const std::string& path, const Canvas& canvas, std::string& error);

}  // namespace coilsim::app
