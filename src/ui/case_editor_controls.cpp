#include "ui/case_editor_controls.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "io/units.h"

namespace coilsim::ui {
namespace {

// A press and release closer than this (pixels) is a click, not a drag.
constexpr double kClickSlop = 3.0;

}  // namespace

CaseEditorControls::CaseEditorControls(const CaseEditorHooks& hooks) : hooks_(hooks) {
  if (hooks_.view) view_ = hooks_.view();
}

void CaseEditorControls::setArea(int x, int y, int width, int height) {
  ax_ = x, ay_ = y, aw_ = std::max(width, 1), ah_ = std::max(height, 1);
  if (!fitted_) fit();
}

void CaseEditorControls::fit() {
  // Looking across the neck normal, a little from above it: the plane shows
  // nearly edge-on, so a move along the normal is a move on the screen.
  const Vec3& n = view_.neckNormal;
  if (std::hypot(n.x(), n.y()) > 1e-6) camera_.yaw = std::atan2(n.y(), n.x()) + 0.5 * M_PI;
  camera_.pitch = 0.3;
  camera_.fit(render::boundsOf(view_.scene), double(aw_) / ah_);
  fitted_ = true;
}

bool CaseEditorControls::inArea(double x, double y) const {
  return x >= ax_ && x < ax_ + aw_ && y >= ay_ && y < ay_ + ah_;
}

void CaseEditorControls::rayAt(double x, double y, Vec3& origin, Vec3& direction) const {
  // The perspective camera of render::Camera::projection: fovY vertically, the area's aspect.
  const double t = std::tan(0.5 * camera_.fovY), aspect = double(aw_) / ah_;
  const double u = 2.0 * (x - ax_) / aw_ - 1.0, v = 1.0 - 2.0 * (y - ay_) / ah_;
  origin = camera_.eye();
  direction = (camera_.forward() + u * t * aspect * camera_.right() + v * t * camera_.up()).normalized();
}

void CaseEditorControls::pixelOf(const Vec3& p, double& x, double& y) const {
  const double t = std::tan(0.5 * camera_.fovY), aspect = double(aw_) / ah_;
  const Vec3 r = p - camera_.eye();
  const double z = r.dot(camera_.forward());
  if (!(z > 0)) {  // behind the eye: on no pixel
    x = y = NAN;
    return;
  }
  x = ax_ + 0.5 * (r.dot(camera_.right()) / (z * t * aspect) + 1.0) * aw_;
  y = ay_ + 0.5 * (1.0 - r.dot(camera_.up()) / (z * t)) * ah_;
}

void CaseEditorControls::outcome(const std::string& what, const std::string& why) {
  if (why.empty()) {
    message_ = what;
    refused_ = false;
    if (hooks_.view) view_ = hooks_.view();
    return;
  }
  const std::string text = what + " refused: " + why;
  // A drag asks again at every pixel: say it once.
  if (!(refused_ && message_ == text)) std::fprintf(stderr, "case edit: %s\n", text.c_str());
  message_ = text;
  refused_ = true;
}

void CaseEditorControls::key(EditorKey k, EditorMods mods) {
  if (ask_ != EditorAsk::None) {
    if (k == EditorKey::Enter) confirm();
    else if (k == EditorKey::Escape) cancel();
    else if (k == EditorKey::No && ask_ == EditorAsk::Unsaved) discard();
    return;
  }
  const auto neck = [this](double mm) {
    if (!hooks_.moveNeck) return;
    char what[64];
    std::snprintf(what, sizeof what, "neck plane %+.2f mm", mm);
    outcome(what, hooks_.moveNeck(mm));
  };
  const auto tilt = [this](const Vec3& axis, double deg) {
    if (!hooks_.tiltNeck) return;
    char what[64];
    std::snprintf(what, sizeof what, "neck plane tilted %+.0f deg", deg);
    outcome(what, hooks_.tiltNeck(axis, units::degToRad(deg)));
  };
  switch (k) {
    case EditorKey::Up: neck(kNeckKeyStepMm); break;
    case EditorKey::Down: neck(-kNeckKeyStepMm); break;
    case EditorKey::PageUp: neck(kNeckPageStepMm); break;
    case EditorKey::PageDown: neck(-kNeckPageStepMm); break;
    // Tilts turn the normal the way the key points on the screen.
    case EditorKey::TiltUp: tilt(camera_.right(), -kTiltKeyStepDeg); break;
    case EditorKey::TiltDown: tilt(camera_.right(), kTiltKeyStepDeg); break;
    case EditorKey::TiltLeft: tilt(camera_.forward(), -kTiltKeyStepDeg); break;
    case EditorKey::TiltRight: tilt(camera_.forward(), kTiltKeyStepDeg); break;
    case EditorKey::AimTip: aimTip(); break;
    case EditorKey::Fit: fit(); break;
    case EditorKey::Save:
      if (mods.ctrl) save();
      break;
    case EditorKey::Escape: closeRequested(); break;
    case EditorKey::No:
    case EditorKey::Enter: break;
  }
}

void CaseEditorControls::press(int button, double x, double y, EditorMods mods) {
  if (ask_ != EditorAsk::None || !inArea(x, y)) return;
  lastX_ = x, lastY_ = y;
  if (button == 1) {
    rightDown_ = true;
    return;
  }
  if (button != 0) return;
  leftDown_ = true, orbiting_ = false, neckDrag_ = mods.shift;
  pressX_ = x, pressY_ = y, dragApplied_ = 0, pressMods_ = mods;
  double tx = 0, ty = 0;
  pixelOf(view_.tip, tx, ty);
  tipDrag_ = !mods.shift && !mods.ctrl && std::hypot(x - tx, y - ty) <= kTipGrabPixels;
}

void CaseEditorControls::move(double x, double y) {
  const double dx = x - lastX_, dy = y - lastY_;
  lastX_ = x, lastY_ = y;
  if (rightDown_) camera_.pan(-dx / ah_, dy / ah_);
  if (!leftDown_) return;
  if (neckDrag_) {
    // Whole pixels upward from the press, so the plane moves by a known amount however the motion is split.
    const double target = std::round(pressY_ - y) * kNeckDragMmPerPixel;
    if (target == dragApplied_ || !hooks_.moveNeck) return;
    char what[64];
    std::snprintf(what, sizeof what, "neck plane dragged %+.2f mm", target);
    const std::string why = hooks_.moveNeck(target - dragApplied_);
    if (why.empty()) dragApplied_ = target;
    outcome(what, why);
    return;
  }
  if (tipDrag_) {
    // The tip follows the cursor, in the middle of the lumen under it.
    if (dx == 0 && dy == 0) return;
    Vec3 origin, direction;
    rayAt(x, y, origin, direction);
    if (hooks_.placeTip) outcome("catheter tip dragged", hooks_.placeTip(origin, direction));
    return;
  }
  if (!orbiting_ && std::hypot(x - pressX_, y - pressY_) > kClickSlop) orbiting_ = true;
  if (orbiting_) camera_.orbit(-0.01 * dx, 0.01 * dy);
}

void CaseEditorControls::release(int button, double x, double y) {
  if (button == 1) {
    rightDown_ = false;
    return;
  }
  if (button != 0 || !leftDown_) return;
  move(x, y);
  leftDown_ = false;
  if (neckDrag_ || orbiting_ || (tipDrag_ && std::hypot(x - pressX_, y - pressY_) > kClickSlop)) return;
  // A click: ctrl puts the neck plane through the surface point, else the tip mid-lumen.
  Vec3 origin, direction;
  rayAt(x, y, origin, direction);
  if (pressMods_.ctrl) {
    if (hooks_.placeNeck) outcome("neck plane through the point clicked", hooks_.placeNeck(origin, direction));
  } else if (hooks_.placeTip) {
    outcome("catheter tip placed", hooks_.placeTip(origin, direction));
  }
}

void CaseEditorControls::scroll(double dy) {
  if (dy != 0) camera_.zoom(std::pow(1.1, dy));
}

void CaseEditorControls::closeRequested() {
  if (view_.unsaved) ask_ = EditorAsk::Unsaved;
  else close_ = true;
}

void CaseEditorControls::save() {
  if (hooks_.saveOverwrites) ask_ = EditorAsk::Overwrite;
  else writeCase(false);
}

void CaseEditorControls::writeCase(bool thenClose) {
  ask_ = EditorAsk::None;
  if (!hooks_.save) return;
  const std::string why = hooks_.save();
  if (why.empty()) std::printf("case edit: saved %s\n", hooks_.savePath.c_str()), std::fflush(stdout);
  outcome("saved " + hooks_.savePath, why.empty() ? why : "could not write it: " + why);
  if (why.empty() && thenClose) close_ = true;
}

void CaseEditorControls::confirm() {
  if (ask_ == EditorAsk::Overwrite) writeCase(false);
  else if (ask_ == EditorAsk::Unsaved) writeCase(true);
}

void CaseEditorControls::discard() {
  ask_ = EditorAsk::None;
  close_ = true;
}

void CaseEditorControls::cancel() { ask_ = EditorAsk::None; }

void CaseEditorControls::aimTip() {
  if (hooks_.aimTip) outcome("catheter tip aimed at the neck's centre", hooks_.aimTip());
}

}  // namespace coilsim::ui
