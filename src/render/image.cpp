#include "render/image.h"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>

// The one translation unit holding the stb implementations (Debian libstb-dev
// headers). Static, so they cannot clash with the shared libstb that
// Debian's libimgui.a links to for fonts.
#define STB_IMAGE_STATIC
#define STB_IMAGE_WRITE_STATIC
#define STB_IMAGE_WRITE_IMPLEMENTATION
#define STB_IMAGE_IMPLEMENTATION
#define STBI_ONLY_PNG
#if defined(__GNUC__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wunused-parameter"
#pragma GCC diagnostic ignored "-Wsign-compare"
#endif
#include <stb/stb_image.h>
#include <stb/stb_image_write.h>
#if defined(__GNUC__)
#pragma GCC diagnostic pop
#endif

namespace coilsim::render {

bool writePng(const std::string& path, const Image& image, std::string& error) {
  if (image.empty() || image.pixels.size() != size_t(image.width) * image.height * 4) {
    error = "cannot write " + path + ": the image is empty";
    return false;
  }
  // stb reports failure only as 0; fopen first to say why.
  FILE* probe = std::fopen(path.c_str(), "wb");
  if (!probe) {
    error = "cannot write " + path + ": " + std::strerror(errno);
    return false;
  }
  std::fclose(probe);
  if (!stbi_write_png(path.c_str(), image.width, image.height, 4, image.pixels.data(), image.width * 4)) {
    error = "cannot write " + path + ": PNG encoding failed";
    return false;
  }
  return true;
}

bool readPng(const std::string& path, Image& image, std::string& error) {
  int w = 0, h = 0, n = 0;
  unsigned char* data = stbi_load(path.c_str(), &w, &h, &n, 4);
  if (!data) {
    error = "cannot read " + path + ": " + (stbi_failure_reason() ? stbi_failure_reason() : "unknown error");
    return false;
  }
  image.width = w;
  image.height = h;
  image.pixels.assign(data, data + size_t(w) * h * 4);
  stbi_image_free(data);
  return true;
}

ImageDiff compareImages(const Image& expected, const Image& actual, int threshold) {
  ImageDiff d;
  d.sameSize = expected.width == actual.width && expected.height == actual.height && !expected.empty();
  if (!d.sameSize) return d;
  const int w = expected.width, h = expected.height;
  d.diff.width = w;
  d.diff.height = h;
  d.diff.pixels.resize(size_t(w) * h * 4);
  d.x0 = w;
  d.y0 = h;
  double sum = 0;
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const std::uint8_t* a = expected.at(x, y);
      const std::uint8_t* b = actual.at(x, y);
      int worst = 0;
      for (int c = 0; c < 3; ++c) {
        const int delta = std::abs(int(a[c]) - int(b[c]));
        sum += delta;
        worst = std::max(worst, delta);
      }
      d.maxAbs = std::max(d.maxAbs, worst);
      std::uint8_t* o = d.diff.at(x, y);
      if (worst > threshold) {
        ++d.pixelsOff;
        d.x0 = std::min(d.x0, x);
        d.y0 = std::min(d.y0, y);
        d.x1 = std::max(d.x1, x);
        d.y1 = std::max(d.y1, y);
        o[0] = 255;
        o[1] = o[2] = 0;
      } else {
        // The expected image, dimmed to grey, so the red marks stand out.
        const std::uint8_t g = std::uint8_t((a[0] + a[1] + a[2]) / 9);
        o[0] = o[1] = o[2] = g;
      }
      o[3] = 255;
    }
  }
  const double n = double(w) * h;
  d.fractionOff = d.pixelsOff / n;
  d.meanAbs = sum / (3 * n);
  return d;
}

std::string describe(const ImageDiff& d, int threshold) {
  if (!d.sameSize) return "the images differ in size (or are empty)";
  char buf[256];
  const long total = long(d.diff.width) * d.diff.height;
  int n = std::snprintf(buf, sizeof buf, "%ld of %ld pixels (%.3f%%) differ by more than %d, mean |diff| %.3f, max %d",
                        d.pixelsOff, total, 100.0 * d.fractionOff, threshold, d.meanAbs, d.maxAbs);
  if (d.pixelsOff > 0 && n > 0 && n < int(sizeof buf))
    std::snprintf(buf + n, sizeof buf - n, ", in x %d..%d, y %d..%d", d.x0, d.x1, d.y0, d.y1);
  return buf;
}

}  // namespace coilsim::render
