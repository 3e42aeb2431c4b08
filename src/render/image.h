#pragma once
// RGBA8 images in memory, PNG files (stb_image / stb_image_write) and the
// tolerant comparison used by the screenshot tests. No GL here.
#include <cstdint>
#include <string>
#include <vector>

namespace coilsim::render {

struct Image {
  int width = 0, height = 0;
  std::vector<std::uint8_t> pixels;  // (height x width x 4) RGBA, first row at the top
  bool empty() const { return width <= 0 || height <= 0; }
  const std::uint8_t* at(int x, int y) const { return &pixels[(size_t(y) * width + x) * 4]; }
  std::uint8_t* at(int x, int y) { return &pixels[(size_t(y) * width + x) * 4]; }
};

// Writes `image` as a PNG. Returns false and names the path in `error` if it
// cannot be written (missing directory, no permission, empty image).
bool writePng(const std::string& path, const Image& image, std::string& error);

// Reads any PNG as RGBA8. Returns false and names the path in `error`.
bool readPng(const std::string& path, Image& image, std::string& error);

struct ImageDiff {
  bool sameSize = false;
  long pixelsOff = 0;       // pixels with a channel differing by more than the threshold
  double fractionOff = 0;   // pixelsOff / all pixels
  double meanAbs = 0;       // mean absolute difference over all channels, 0-255
  int maxAbs = 0;           // largest channel difference, 0-255
  int x0 = 0, y0 = 0, x1 = -1, y1 = -1;  // bounding box of the pixels off (x1 < x0: none)
  Image diff;               // red where off, the expected image dimmed elsewhere
};

// Per-pixel comparison with a per-channel threshold (0-255). RGB only: alpha
// is ignored since screenshots are opaque.
ImageDiff compareImages(const Image& expected, const Image& actual, int threshold);

// "12 of 76800 pixels (0.016%) differ by more than 24, mean |diff| 0.31, max 80,
// in x 10..40, y 3..9" for test output.
std::string describe(const ImageDiff& d, int threshold);

}  // namespace coilsim::render
