#pragma once
// Mouse, keyboard and gamepad in the window: camera (orbit, pan, zoom) and
// the simulation keys. Discrete keys arrive through GLFW callbacks (installed
// before ImGui's, which chain to them); held keys, drags and the gamepad
// are polled once per frame.
#include <string>

#include "ui/device_input.h"
#include "ui/panel.h"
#include "ui/session.h"
#include "ui/views.h"

struct GLFWwindow;

namespace coilsim::ui {

class WindowInput {
 public:
  WindowInput(GLFWwindow* window, Session& session, Views& views, PanelContext& panel);
  // Applies this frame's input; ImGui's wishes keep the mouse or keys for it.
  void update(double dt, bool imguiWantsMouse, bool imguiWantsKeyboard);
  // F12 was pressed since the last call.
  bool screenshotRequested();
  std::string nextScreenshotName();

  // Called from the GLFW callbacks.
  void onKey(int key, int mods);
  void onScroll(double dy);

 private:
  // Returns the gamepad's device levers (push, twist), zero without one.
  void gamepad(double dt, double& push, double& twist);

  GLFWwindow* window_;
  Session& session_;
  Views& views_;
  PanelContext& panel_;
  bool keyboardFree_ = true, mouseFree_ = true;
  bool dragging_ = false, dragPan_ = false;
  double lastX_ = 0, lastY_ = 0;
  double scroll_ = 0;
  bool screenshot_ = false;
  int screenshots_ = 0;
  unsigned char buttons_[15] = {};  // gamepad buttons last frame
  DeviceInput device_;
  double twistSteps_ = 0;  // Ctrl + wheel notches not yet sent
};

}  // namespace coilsim::ui
