#pragma once
// The validation panel's charts, drawn with ImGui's draw list: a line chart
// with ticks and units on both axes, and the legend of the 3D coil's fixed
// error colour scale.
#include <string>
#include <utility>
#include <vector>

#include "physics/draw_data.h"

namespace coilsim::ui {

// The fixed colour scale of node error (the app's, stated in its legend):
// colours sampled evenly from its low to its high end, and tick labels at
// positions in [0, 1] along it.
struct ErrorColourScale {
  std::string legend;                               // "node error: fixed log scale, blue <= 0.01 mm, red >= 1 mm"
  std::vector<Colour> colours;                      // low .. high
  std::vector<std::pair<float, std::string>> ticks; // position, label ("0.1 mm")
};

struct ChartAxes {
  std::string xLabel, yLabel;  // with units: "arc length s (mm)"
  float xMin = 0, xMax = 1, yMin = 0, yMax = 1;
  bool integerX = false;  // x counts (evaluations): ticks at whole numbers
};

// A "nice" tick step (1, 2 or 5 times a power of ten) giving about n ticks over range.
float niceTickStep(float range, int n);

// One chart of `height` pixels across the panel: the curve (x, y), an
// optional dashed level line (noise floor, <= 0: none), a title in the top
// left corner, ticks with values on both axes and the axes' labels.
void drawLineChart(const char* id, const std::vector<float>& x, const std::vector<float>& y, const ChartAxes& axes,
                   const std::string& title, float level, float height);

// The colour bar with its ticks and legend line (nothing for an empty scale).
void drawErrorColourScale(const ErrorColourScale& scale);

}  // namespace coilsim::ui
