// Software-drawn charts of the validation workbench (see validate_plots.h).
#include "app/validate_plots.h"
#include "app/format.h"
#include "io/units.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>


// Debian's libstb-dev header: text as quads, which we fill as rectangles.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#include <stb/stb_easy_font.h>
#pragma GCC diagnostic pop

namespace coilsim::app {
namespace {

using Colour = std::array<std::uint8_t, 3>;
constexpr Colour kBlack{0, 0, 0}, kGrey{150, 150, 150}, kLight{225, 225, 225};
// Stage colours, distinct on white.
constexpr Colour kStageColours[] = {{31, 119, 180}, {214, 39, 40}, {44, 160, 44}, {148, 103, 189}, {255, 127, 14},
                                    {140, 86, 75},  {227, 119, 194}, {23, 190, 207}};

class Painter {
 public:
  Painter(int w, int h) {
    c_.width = w, c_.height = h;
    c_.pixels.assign(size_t(w) * size_t(h) * 4, 255);
  }
  Canvas take() { return std::move(c_); }

  void dot(int x, int y, const Colour& col) {
    if (x < 0 || y < 0 || x >= c_.width || y >= c_.height) return;
    std::uint8_t* p = &c_.pixels[(size_t(y) * size_t(c_.width) + size_t(x)) * 4];
    p[0] = col[0], p[1] = col[1], p[2] = col[2], p[3] = 255;
  }
  void disc(double x, double y, double r, const Colour& col) {
    const int R = int(std::ceil(r));
    for (int dy = -R; dy <= R; ++dy)
      for (int dx = -R; dx <= R; ++dx)
        if (dx * dx + dy * dy <= r * r + 0.25) dot(int(std::lround(x)) + dx, int(std::lround(y)) + dy, col);
  }
  // A line of width 2 r + 1; dashed: 8 pixels on, 6 off.
  void line(double x0, double y0, double x1, double y1, const Colour& col, double r = 0.0, bool dashed = false) {
    const double len = std::hypot(x1 - x0, y1 - y0);
    const int n = std::max(1, int(std::ceil(len)));
    for (int i = 0; i <= n; ++i) {
      if (dashed && (i % 14) >= 8) continue;
      const double t = double(i) / n;
      disc(x0 + t * (x1 - x0), y0 + t * (y1 - y0), r, col);
    }
  }
  void rect(int x0, int y0, int x1, int y1, const Colour& col) {
    for (int y = y0; y < y1; ++y)
      for (int x = x0; x < x1; ++x) dot(x, y, col);
  }
  // Text at (x, y) top-left, each font pixel drawn as scale x scale.
  void text(double x, double y, const std::string& s, const Colour& col, int scale = 1) {
    static char buffer[60000];
    std::string copy = s;
    const int quads = stb_easy_font_print(0, 0, copy.data(), nullptr, buffer, sizeof buffer);
    for (int q = 0; q < quads; ++q) {
      const float* v0 = reinterpret_cast<const float*>(buffer + q * 64);
      const float* v2 = reinterpret_cast<const float*>(buffer + q * 64 + 32);
      rect(int(x + scale * v0[0]), int(y + scale * v0[1]), int(x + scale * v2[0]), int(y + scale * v2[1]), col);
    }
  }
  static int textWidth(const std::string& s, int scale = 1) {
    std::string copy = s;
    return scale * stb_easy_font_width(copy.data());
  }

 private:
  Canvas c_;
};

// A "nice" tick step (1, 2 or 5 times a power of ten) giving about `n` ticks over `range`.
double tickStep(double range, int n) {
  const double raw = range / std::max(1, n);
  const double p = std::pow(10.0, std::floor(std::log10(raw)));
  for (double m : {1.0, 2.0, 5.0, 10.0})
    if (m * p >= raw) return m * p;
  return 10 * p;
}

// Blue (0) -> cyan -> yellow -> red (1): the error scale's colours.
Colour heat(double t) {
  const std::array<float, 3> c = errorScaleColour(t);
  return {std::uint8_t(std::lround(255 * c[0])), std::uint8_t(std::lround(255 * c[1])),
          std::uint8_t(std::lround(255 * c[2]))};
}

// A plot frame mapping data (x, y) to pixels inside a box, with ticks.
struct Frame {
  double x0, x1, y0, y1;  // data range
  int left, top, right, bottom;  // pixels
  double px(double x) const { return left + (x - x0) / (x1 - x0) * (right - left); }
  double py(double y) const { return bottom - (y - y0) / (y1 - y0) * (bottom - top); }
  void draw(Painter& p, const std::string& xLabel, const std::string& yLabel, bool grid) const {
    const double sx = tickStep(x1 - x0, 8), sy = tickStep(y1 - y0, 6);
    for (double x = std::ceil(x0 / sx) * sx; x <= x1 + 1e-9 * sx; x += sx) {
      if (grid) p.line(px(x), top, px(x), bottom, kLight);
      p.line(px(x), bottom, px(x), bottom + 5, kBlack);
      const std::string t = fmt("%g", std::abs(x) < 1e-9 * sx ? 0.0 : x);
      p.text(px(x) - Painter::textWidth(t) / 2.0, bottom + 8, t, kBlack);
    }
    for (double y = std::ceil(y0 / sy) * sy; y <= y1 + 1e-9 * sy; y += sy) {
      if (grid) p.line(left, py(y), right, py(y), kLight);
      p.line(left - 5, py(y), left, py(y), kBlack);
      const std::string t = fmt("%g", std::abs(y) < 1e-9 * sy ? 0.0 : y);
      p.text(left - 8 - Painter::textWidth(t), py(y) - 3, t, kBlack);
    }
    p.line(left, top, left, bottom, kBlack);
    p.line(left, bottom, right, bottom, kBlack);
    p.line(right, top, right, bottom, kBlack);
    p.line(left, top, right, top, kBlack);
    p.text((left + right) / 2.0 - Painter::textWidth(xLabel) / 2.0, bottom + 24, xLabel, kBlack);
    p.text(left, top - 14, yLabel, kBlack);
  }
};

}  // namespace

double errorScalePosition(double errorMm) {
  if (!std::isfinite(errorMm) || errorMm <= kErrorColourLowMm) return 0.0;
  if (errorMm >= kErrorColourHighMm) return 1.0;
  return std::log10(errorMm / kErrorColourLowMm) / std::log10(kErrorColourHighMm / kErrorColourLowMm);
}

std::array<float, 3> errorScaleColour(double t) {
  t = std::clamp(std::isfinite(t) ? t : 0.0, 0.0, 1.0);
  const double r = std::clamp(2.0 * t - 0.5, 0.0, 1.0), b = std::clamp(1.5 - 2.0 * t, 0.0, 1.0);
  const double g = std::clamp(1.0 - std::abs(2.0 * t - 1.0) * 0.8, 0.0, 1.0) * (220.0 / 255.0);
  return {float(r), float(g), float(b)};
}

std::string errorScaleLegend() {
  return fmt("node error: fixed log scale, blue <= %g mm, ", kErrorColourLowMm) + fmt("red >= %g mm", kErrorColourHighMm);
}

Canvas plotErrorAlongArc(const std::vector<validation::StageComparison>& stages, const std::vector<std::string>& names,
                         int width, int height) {
  Painter p(width, height);
  double sMax = 1e-3, eMax = 1e-6;
  for (const auto& st : stages) {
    if (!st.ok()) continue;
    for (size_t i = 0; i < st.s.size(); ++i) {
      sMax = std::max(sMax, units::mToMm(st.s[i]));
      eMax = std::max(eMax, units::mToMm((st.sim[i] - st.meas[i]).norm()));
    }
    eMax = std::max(eMax, units::mToMm(std::sqrt(3.0) * st.sigma));
  }
  const Frame f{0, sMax, 0, 1.1 * eMax, 80, 40, width - 200, height - 50};
  f.draw(p, "arc length s from the catheter tip (mm)", "node error |x_sim - x_meas| (mm)", true);
  int legendY = f.top;
  for (size_t k = 0; k < stages.size(); ++k) {
    const auto& st = stages[k];
    const Colour col = kStageColours[k % std::size(kStageColours)];
    const std::string name = k < names.size() ? names[k] : "stage " + std::to_string(k + 1);
    p.line(f.right + 15, legendY + 4, f.right + 40, legendY + 4, col, 1.0);
    p.text(f.right + 46, legendY, st.ok() ? name : name + " (failed)", kBlack);
    legendY += 16;
    if (!st.ok()) continue;
    for (size_t i = 1; i < st.s.size(); ++i)
      p.line(f.px(units::mToMm(st.s[i - 1])), f.py(units::mToMm((st.sim[i - 1] - st.meas[i - 1]).norm())), f.px(units::mToMm(st.s[i])),
             f.py(units::mToMm((st.sim[i] - st.meas[i]).norm())), col, 1.0);
    const double floor = units::mToMm(std::sqrt(3.0) * st.sigma);
    p.line(f.left, f.py(floor), f.right, f.py(floor), col, 0.0, true);
  }
  p.line(f.right + 15, legendY + 4, f.right + 40, legendY + 4, kGrey, 0.0, true);
  p.text(f.right + 46, legendY, "noise floor", kBlack);
  p.text(f.right + 46, legendY + 12, "sqrt(3) point_sigma", kBlack);
  return p.take();
}

Canvas plotOverlay(const validation::StageComparison& st, const validation::Stage& measured, const Vec3& gravity,
                   const Vec3& exitDirection, const std::string& title, int width, int height) {
  Painter p(width, height);
  // View axes: h along the exit direction made horizontal, v up (against gravity), w = h x v.
  const Vec3 down = gravity.norm() > 0 ? Vec3(gravity.normalized()) : Vec3(0, 0, -1);
  Vec3 h = exitDirection - exitDirection.dot(down) * down;
  if (h.norm() < 1e-6) h = (std::abs(down.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY()) - down * down.x();
  h.normalize();
  const Vec3 up = -down, w = h.cross(up);
  std::vector<Vec3> all = st.sim;
  all.insert(all.end(), measured.centerline.begin(), measured.centerline.end());
  // The same scale in both views, so that the two pictures compare.
  struct Range { double lo = 1e30, hi = -1e30; void add(double v) { lo = std::min(lo, v), hi = std::max(hi, v); } };
  Range rh, rv, rw;
  for (const Vec3& x : all) rh.add(units::mToMm(x.dot(h))), rv.add(units::mToMm(x.dot(up))), rw.add(units::mToMm(x.dot(w)));
  const int panelW = (width - 220) / 2, panelH = height - 90;
  const double span = std::max({rh.hi - rh.lo, (rv.hi - rv.lo) * panelW / double(panelH),
                                (rw.hi - rw.lo) * panelW / double(panelH), 1.0}) * 1.08;
  auto frameFor = [&](int left, const Range& vert) {
    const double cx = 0.5 * (rh.lo + rh.hi), cy = 0.5 * (vert.lo + vert.hi);
    const double spanY = span * panelH / double(panelW);
    return Frame{cx - span / 2, cx + span / 2, cy - spanY / 2, cy + spanY / 2, left, 50, left + panelW, 50 + panelH};
  };
  const Frame side = frameFor(70, rv), top = frameFor(70 + panelW + 60, rw);
  p.text(10, 8, title, kBlack, 2);
  side.draw(p, "side view: along the exit direction (mm), gravity down", "height (mm)", false);
  top.draw(p, "top view, looking along gravity (mm)", "sideways (mm)", false);
  for (int view = 0; view < 2; ++view) {
    const Frame& f = view == 0 ? side : top;
    const Vec3& vAxis = view == 0 ? up : w;
    auto P = [&](const Vec3& x, double& px, double& py) { px = f.px(units::mToMm(x.dot(h))), py = f.py(units::mToMm(x.dot(vAxis))); };
    double ax, ay, bx, by;
    for (const Vec3& x : measured.centerline) {
      P(x, ax, ay);
      p.disc(ax, ay, 1.5, kGrey);
    }
    for (size_t i = 1; i < st.meas.size(); ++i) {
      P(st.meas[i - 1], ax, ay), P(st.meas[i], bx, by);
      p.line(ax, ay, bx, by, kBlack);
    }
    for (size_t i = 1; i < st.sim.size(); ++i) {
      const double e = 0.5 * ((st.sim[i - 1] - st.meas[i - 1]).norm() + (st.sim[i] - st.meas[i]).norm());
      P(st.sim[i - 1], ax, ay), P(st.sim[i], bx, by);
      p.line(ax, ay, bx, by, heat(errorScalePosition(units::mToMm(e))), 1.5);
    }
  }
  // Legend and colour bar.
  const int lx = width - 130;
  p.text(lx, 60, "measured points", kBlack);
  p.disc(lx - 10, 63, 2, kGrey);
  p.text(lx, 76, "measured spline", kBlack);
  p.line(lx - 22, 79, lx - 4, 79, kBlack);
  p.text(lx, 92, "simulated, coloured", kBlack);
  p.text(lx, 104, "by node error (mm),", kBlack);
  p.text(lx, 116, "fixed log scale", kBlack);
  const int barTop = 137, barBottom = height - 60;
  for (int y = barTop; y <= barBottom; ++y) p.line(lx, y, lx + 18, y, heat(double(barBottom - y) / (barBottom - barTop)));
  // Ticks at each decade and its 3s, labelled in mm; the ends say "or less" / "or more".
  const double decades = std::log10(kErrorColourHighMm / kErrorColourLowMm);
  for (double d = 0; d <= decades + 1e-9; d += 1.0)
    for (double m : {1.0, 3.0}) {
      const double mm = kErrorColourLowMm * std::pow(10.0, d) * m;
      if (mm > kErrorColourHighMm * (1 + 1e-9)) continue;
      const double y = barBottom - errorScalePosition(mm) * (barBottom - barTop);
      p.line(lx + 18, y, lx + 22, y, kBlack);
      const bool end = mm <= kErrorColourLowMm * (1 + 1e-9) || mm >= kErrorColourHighMm * (1 - 1e-9);
      p.text(lx + 25, y - 3, fmt("%g", mm) + (end ? (mm <= kErrorColourLowMm * 1.001 ? " or less" : " or more") : ""),
             kBlack);
    }
  return p.take();
}

}  // namespace coilsim::app
