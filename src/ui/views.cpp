#include "ui/views.h"

#include <cmath>

#include "io/units.h"

namespace coilsim::ui {

void Views::fitIfNew(const render::Bounds& bounds, int width, int height) {
  if (fitted_ || bounds.empty()) return;
  render::fitCamera(shaded_, bounds, render::ViewMode::Shaded, width, height);
  const bool biplane = mode_ == render::ViewMode::Biplane;
  render::fitCamera(xray_, bounds, biplane ? render::ViewMode::Biplane : render::ViewMode::XRay, width, height);
  fitted_ = true;
}

void Views::fit(const render::Bounds& bounds, int width, int height) {
  render::fitCamera(camera(), bounds, mode_, width, height);
  fitted_ = true;
}

// The AP camera sits at yaw -90 degrees.
double Views::rotationDeg() const { return units::radToDeg(std::remainder(xray_.yaw + 0.5 * M_PI, 2 * M_PI)); }
double Views::angulationDeg() const { return units::radToDeg(xray_.pitch); }

}  // namespace coilsim::ui
