#include "ui/input.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "io/units.h"

namespace coilsim::ui {
namespace {

WindowInput* self(GLFWwindow* w) { return static_cast<WindowInput*>(glfwGetWindowUserPointer(w)); }

void keyCallback(GLFWwindow* w, int key, int, int action, int mods) {
  if (action == GLFW_PRESS || action == GLFW_REPEAT) self(w)->onKey(key, mods);
}

void scrollCallback(GLFWwindow* w, double, double dy) { self(w)->onScroll(dy); }

double deadzone(double v) { return std::abs(v) < 0.15 ? 0.0 : v; }

render::ViewMode nextMode(render::ViewMode m) {
  switch (m) {
    case render::ViewMode::Shaded: return render::ViewMode::XRay;
    case render::ViewMode::XRay: return render::ViewMode::Biplane;
    case render::ViewMode::Biplane: return render::ViewMode::Shaded;
  }
  return render::ViewMode::Shaded;
}

}  // namespace

WindowInput::WindowInput(GLFWwindow* window, Session& session, Views& views, PanelContext& panel)
    : window_(window), session_(session), views_(views), panel_(panel) {
  glfwSetWindowUserPointer(window_, this);
  glfwSetKeyCallback(window_, keyCallback);
  glfwSetScrollCallback(window_, scrollCallback);
}

void WindowInput::onKey(int key, int mods) {
  // The detach confirmation is modal: it takes its keys first, and no other
  // but the screenshot.
  if (panel_.device.confirmDetach) {
    if (key == GLFW_KEY_F12)
      screenshot_ = true;
    else if (key == GLFW_KEY_D || key == GLFW_KEY_ENTER || key == GLFW_KEY_KP_ENTER)
      confirmDetach(session_, panel_.device);
    else if (key == GLFW_KEY_ESCAPE)
      panel_.device.confirmDetach = false;
    return;
  }
  // F1 or ? (Shift + / on a US layout) shows or hides the help; Esc hides it first.
  if (key == GLFW_KEY_F1 || (key == GLFW_KEY_SLASH && (mods & GLFW_MOD_SHIFT))) {
    panel_.helpOpen = !panel_.helpOpen;
    return;
  }
  if (key == GLFW_KEY_ESCAPE && panel_.helpOpen) {
    panel_.helpOpen = false;
    return;
  }
  // Esc closes the window even while a panel item has the keyboard (a
  // confirmation just closed by a key still holds it for a frame), except
  // while text is typed into a field: there it ends the typing.
  if (key == GLFW_KEY_ESCAPE) {
    if (!ImGui::GetIO().WantTextInput) panel_.closeRequested = true;
    return;
  }
  if (!keyboardFree_) return;
  switch (key) {
    case GLFW_KEY_SPACE: session_.setPlaying(!session_.playing()); break;
    case GLFW_KEY_N:
      if (!session_.playing()) session_.stepOnce();
      break;
    case GLFW_KEY_R:
      session_.reset();
      device_.clear();
      break;
    case GLFW_KEY_D: requestDetach(session_, panel_.device); break;
    case GLFW_KEY_1: views_.setMode(render::ViewMode::Shaded); break;
    case GLFW_KEY_2: views_.setMode(render::ViewMode::XRay); break;
    case GLFW_KEY_3: views_.setMode(render::ViewMode::Biplane); break;
    case GLFW_KEY_F: panel_.fitRequested = true; break;
    case GLFW_KEY_F12: screenshot_ = true; break;
    case GLFW_KEY_EQUAL:
    case GLFW_KEY_KP_ADD: views_.camera().zoom(1.15); break;
    case GLFW_KEY_MINUS:
    case GLFW_KEY_KP_SUBTRACT: views_.camera().zoom(1.0 / 1.15); break;
    default: break;
  }
}

void WindowInput::onScroll(double dy) {
  if (!mouseFree_) return;
  const bool ctrl = glfwGetKey(window_, GLFW_KEY_LEFT_CONTROL) == GLFW_PRESS ||
                    glfwGetKey(window_, GLFW_KEY_RIGHT_CONTROL) == GLFW_PRESS;
  (ctrl ? twistSteps_ : scroll_) += dy;
}

void WindowInput::update(double dt, bool imguiWantsMouse, bool imguiWantsKeyboard) {
  keyboardFree_ = !imguiWantsKeyboard;
  mouseFree_ = !imguiWantsMouse;
  render::Camera& cam = views_.camera();

  // Drags: left orbits, right or middle (or shift + left) pans.
  double x = 0, y = 0;
  glfwGetCursorPos(window_, &x, &y);
  const bool left = glfwGetMouseButton(window_, GLFW_MOUSE_BUTTON_LEFT) == GLFW_PRESS;
  const bool right = glfwGetMouseButton(window_, GLFW_MOUSE_BUTTON_RIGHT) == GLFW_PRESS ||
                     glfwGetMouseButton(window_, GLFW_MOUSE_BUTTON_MIDDLE) == GLFW_PRESS;
  const bool shift = glfwGetKey(window_, GLFW_KEY_LEFT_SHIFT) == GLFW_PRESS ||
                     glfwGetKey(window_, GLFW_KEY_RIGHT_SHIFT) == GLFW_PRESS;
  if (!dragging_ && (left || right) && mouseFree_) {
    dragging_ = true;  // a drag that starts on the panel stays the panel's
    dragPan_ = right || shift;
  } else if (dragging_ && !left && !right) {
    dragging_ = false;
  }
  if (dragging_) {
    int ww = 0, wh = 0;
    glfwGetWindowSize(window_, &ww, &wh);
    const double dx = x - lastX_, dy = y - lastY_;
    if (dragPan_)
      cam.pan(-dx / std::max(wh, 1), dy / std::max(wh, 1));
    else
      cam.orbit(-0.008 * dx, 0.008 * dy);
  }
  lastX_ = x;
  lastY_ = y;
  if (scroll_ != 0) {
    cam.zoom(std::pow(1.15, scroll_));
    scroll_ = 0;
  }

  // Held arrow keys orbit (pan with shift) at a steady rate.
  if (keyboardFree_) {
    const double h = (glfwGetKey(window_, GLFW_KEY_RIGHT) == GLFW_PRESS) - (glfwGetKey(window_, GLFW_KEY_LEFT) == GLFW_PRESS);
    const double v = (glfwGetKey(window_, GLFW_KEY_UP) == GLFW_PRESS) - (glfwGetKey(window_, GLFW_KEY_DOWN) == GLFW_PRESS);
    if (h != 0 || v != 0) {
      if (shift)
        cam.pan(0.6 * h * dt, 0.6 * v * dt);
      else
        cam.orbit(-1.5 * h * dt, 1.0 * v * dt);
    }
  }
  // The device: held keys and the gamepad's levers, Ctrl + wheel in steps.
  double push = 0, twist = 0;
  gamepad(dt, push, twist);
  if (keyboardFree_) {
    auto held = [&](int key) { return glfwGetKey(window_, key) == GLFW_PRESS ? 1.0 : 0.0; };
    push += held(GLFW_KEY_P) - held(GLFW_KEY_O);
    twist += held(GLFW_KEY_E) - held(GLFW_KEY_Q);
  }
  device_.update(session_, panel_.device, push, twist);
  if (twistSteps_ != 0) {
    const double angle = units::degToRad(panel_.device.twistStepDeg) * twistSteps_;
    DeviceCommand c;
    c.kind = DeviceCommand::Kind::Twist;
    c.rate = std::copysign(units::degPerSToRadPerS(panel_.device.twistRateDegS), angle);
    c.amount = std::abs(angle);
    session_.command(c);
    twistSteps_ = 0;
  }
}

void WindowInput::gamepad(double dt, double& push, double& twist) {
  for (int jid = GLFW_JOYSTICK_1; jid <= GLFW_JOYSTICK_LAST; ++jid) {
    GLFWgamepadstate pad;
    if (!glfwJoystickIsGamepad(jid) || !glfwGetGamepadState(jid, &pad)) continue;
    render::Camera& cam = views_.camera();
    // Left stick: orbit, or pan while LB is held.
    const double lx = deadzone(pad.axes[GLFW_GAMEPAD_AXIS_LEFT_X]), ly = deadzone(pad.axes[GLFW_GAMEPAD_AXIS_LEFT_Y]);
    if (pad.buttons[GLFW_GAMEPAD_BUTTON_LEFT_BUMPER] == GLFW_PRESS)
      cam.pan(0.6 * dt * lx, -0.6 * dt * ly);
    else
      cam.orbit(-2.0 * dt * lx, -1.5 * dt * ly);
    // Right stick: x twists the coil, y zooms.
    twist = deadzone(pad.axes[GLFW_GAMEPAD_AXIS_RIGHT_X]);
    const double zoom = -deadzone(pad.axes[GLFW_GAMEPAD_AXIS_RIGHT_Y]);
    if (zoom != 0) cam.zoom(std::pow(3.0, dt * zoom));
    // Triggers rest at -1: map to 0..1; right pushes, left pulls.
    const double in = 0.5 * (pad.axes[GLFW_GAMEPAD_AXIS_RIGHT_TRIGGER] + 1.0);
    const double out = 0.5 * (pad.axes[GLFW_GAMEPAD_AXIS_LEFT_TRIGGER] + 1.0);
    push = deadzone(in) - deadzone(out);
    auto pressed = [&](int b) { return pad.buttons[b] == GLFW_PRESS && buttons_[b] != GLFW_PRESS; };
    if (pressed(GLFW_GAMEPAD_BUTTON_A)) session_.setPlaying(!session_.playing());
    if (pressed(GLFW_GAMEPAD_BUTTON_B)) {
      session_.reset();
      device_.clear();
    }
    if (pressed(GLFW_GAMEPAD_BUTTON_X)) panel_.fitRequested = true;
    if (pressed(GLFW_GAMEPAD_BUTTON_Y)) {
      const render::ViewMode next = nextMode(views_.mode());
      views_.setMode(views_.xrayOnly() && next == render::ViewMode::Shaded ? nextMode(next) : next);
    }
    for (int b = 0; b <= GLFW_GAMEPAD_BUTTON_LAST; ++b) buttons_[b] = pad.buttons[b];
    return;  // the first gamepad found drives the view and the device
  }
}

bool WindowInput::screenshotRequested() {
  const bool r = screenshot_;
  screenshot_ = false;
  return r;
}

std::string WindowInput::nextScreenshotName() {
  char name[64];
  std::snprintf(name, sizeof name, "coilsim-%d.png", ++screenshots_);
  return name;
}

}  // namespace coilsim::ui
