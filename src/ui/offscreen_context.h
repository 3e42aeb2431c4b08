#pragma once
// What every off-screen picture of the ui starts and ends with: an OSMesa
// context of the picture's size, and the drawn frame read back.
#include <memory>
#include <string>

#include "render/backend.h"
#include "render/image.h"
#include "render/renderer.h"

namespace coilsim::ui {

// An off-screen context of width x height for one picture to `path`; null
// with `error` set when no path is given or no context can be made.
std::unique_ptr<render::Backend> offscreenContext(const std::string& path, int width, int height, std::string& error);

// The frame `renderer` just drew, into `image`; false with `error` set.
bool readBackFrame(render::Renderer& renderer, render::Image& image, std::string& error);

}  // namespace coilsim::ui
