#pragma once
// The view the user looks through: the mode (3d, xray, biplane) and one
// camera for the 3D view and one for the X-ray views (the C-arm), so that
// switching back and forth keeps each where the user left it. GL-free.
#include "render/camera.h"
#include "render/renderer.h"

namespace coilsim::ui {

class Views {
 public:
  explicit Views(render::ViewMode mode = render::ViewMode::Shaded) : mode_(mode) {}

  render::ViewMode mode() const { return mode_; }
  // Ignored for the 3D view while X-ray only (practice as in the real procedure).
  void setMode(render::ViewMode mode) {
    if (!(xrayOnly_ && mode == render::ViewMode::Shaded)) mode_ = mode;
  }
  void setXrayOnly(bool on) { xrayOnly_ = on; }
  bool xrayOnly() const { return xrayOnly_; }
  // The camera of the current mode (the frontal one in biplane).
  render::Camera& camera() { return mode_ == render::ViewMode::Shaded ? shaded_ : xray_; }
  const render::Camera& camera() const { return mode_ == render::ViewMode::Shaded ? shaded_ : xray_; }

  // Fits both cameras to the scene the first time, and the current one
  // whenever asked (the F key, the Fit button).
  void fitIfNew(const render::Bounds& bounds, int width, int height);
  void fit(const render::Bounds& bounds, int width, int height);

  // C-arm angles of the X-ray camera from AP, degrees: rotation about the
  // vertical (towards +x positive) and angulation (upwards positive).
  double rotationDeg() const;
  double angulationDeg() const;

 private:
  render::ViewMode mode_;
  render::Camera shaded_;
  render::Camera xray_ = render::apView(render::Camera{});
  bool fitted_ = false;
  bool xrayOnly_ = false;
};

}  // namespace coilsim::ui
