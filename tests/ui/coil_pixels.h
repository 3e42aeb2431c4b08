#pragma once
// Counts pixels that look like the platinum coil in a 3D-view screenshot:
// bright, nearly grey but warm (red >= green >= blue, red above blue). The
// background is a dark blue grey, the catheter blue, the vessel pink, ImGui
// text pure white and its widgets blue, an X-ray exactly grey. Used by the
// window check; tests/ui/coil_pixels_test.cpp runs it on the goldens.
#include <algorithm>

#include "render/image.h"

namespace coilsim::testing {

inline bool looksLikeCoil(const std::uint8_t* p) {
  const int r = p[0], g = p[1], b = p[2];
  const int lo = std::min({r, g, b}), hi = std::max({r, g, b});
  return lo > 110 && hi < 252 && hi - lo < 45 && r - b >= 5 && r >= g - 2 && g >= b - 2;
}

// Pixels like the coil with x >= x0 (to the right of the panel).
inline long countCoilPixels(const render::Image& image, int x0 = 0) {
  long n = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = std::max(x0, 0); x < image.width; ++x) n += looksLikeCoil(image.at(x, y));
  return n;
}

// Where the coil-like pixels with x >= x0 are: their count and centroid.
struct CoilSpot {
  long count = 0;
  double x = 0, y = 0;  // pixels, first row at the top
};
inline CoilSpot coilSpot(const render::Image& image, int x0 = 0) {
  CoilSpot s;
  for (int y = 0; y < image.height; ++y)
    for (int x = std::max(x0, 0); x < image.width; ++x)
      if (looksLikeCoil(image.at(x, y))) ++s.count, s.x += x, s.y += y;
  if (s.count) s.x /= double(s.count), s.y /= double(s.count);
  return s;
}

}  // namespace coilsim::testing
