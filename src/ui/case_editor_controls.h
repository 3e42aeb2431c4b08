#pragma once
// What the case editor window does with the user's keys and mouse, apart
// from the window: drags, clicks and keys become calls of the
// CaseEditorHooks; the camera orbits, pans and zooms; Save and Close ask
// first when they would overwrite the case or lose edits. GL-free, so that
// tests drive it with events directly; case_editor_window.cpp feeds it the
// window's events in the order they came.
#include <string>

#include "render/camera.h"
#include "render/renderer.h"
#include "ui/case_editor_window.h"

namespace coilsim::ui {

enum class EditorKey { Up, Down, PageUp, PageDown, TiltUp, TiltDown, TiltLeft, TiltRight, AimTip, Fit, Save, No,
                       Enter, Escape };

struct EditorMods {
  bool shift = false, ctrl = false;
};

// The question the window puts before acting.
enum class EditorAsk { None, Overwrite, Unsaved };

class CaseEditorControls {
 public:
  explicit CaseEditorControls(const CaseEditorHooks& hooks);

  // The 3D view's place in the window (pixels, origin at the top left) and
  // its camera; the camera is fitted the first time, looking across the neck normal.
  void setArea(int x, int y, int width, int height);
  render::Camera& camera() { return camera_; }
  const render::Camera& camera() const { return camera_; }
  // The ray under window pixel (x, y): origin at the eye, unit direction.
  void rayAt(double x, double y, Vec3& origin, Vec3& direction) const;
  // The window pixel where `p` (m) shows: rayAt's inverse; NaN behind the eye.
  void pixelOf(const Vec3& p, double& x, double& y) const;
  bool inArea(double x, double y) const;

  // Events, in the order they happened; positions in window pixels.
  void key(EditorKey k, EditorMods mods);
  void press(int button, double x, double y, EditorMods mods);  // 0 left, 1 right
  void move(double x, double y);
  void release(int button, double x, double y);
  void scroll(double dy);
  // The window's close button: close now, or ask when there are unsaved edits.
  void closeRequested();

  // Buttons of the panel and of its questions.
  void save();             // asks first when it would overwrite the case
  void confirm();          // the question's yes: overwrite, or save and close
  void discard();          // Unsaved: close without saving
  void cancel();           // the question's no
  void aimTip();
  void fit();

  const CaseEditorHooks& hooks() const { return hooks_; }
  const CaseEditorView& view() const { return view_; }
  EditorAsk asking() const { return ask_; }
  bool closing() const { return close_; }
  // The last thing that happened, in words; `refused` when it was a refusal.
  const std::string& message() const { return message_; }
  bool refused() const { return refused_; }

 private:
  void outcome(const std::string& what, const std::string& why);  // why empty: done
  void writeCase(bool thenClose);

  CaseEditorHooks hooks_;
  CaseEditorView view_;
  render::Camera camera_;
  int ax_ = 0, ay_ = 0, aw_ = 1, ah_ = 1;
  bool fitted_ = false;
  // The left button's drag: the neck along its normal (shift), the tip (from the tip) or the camera.
  bool leftDown_ = false, neckDrag_ = false, tipDrag_ = false, orbiting_ = false, rightDown_ = false;
  double pressX_ = 0, pressY_ = 0, lastX_ = 0, lastY_ = 0, dragApplied_ = 0;
  EditorMods pressMods_;
  EditorAsk ask_ = EditorAsk::None;
  bool close_ = false;
  std::string message_;
  bool refused_ = false;
};

}  // namespace coilsim::ui
