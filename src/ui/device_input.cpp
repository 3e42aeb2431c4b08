#include "ui/device_input.h"

#include <algorithm>
#include <cmath>

#include "io/units.h"

namespace coilsim::ui {
namespace {

int level(double lever) { return int(std::lround(20.0 * std::clamp(std::isfinite(lever) ? lever : 0.0, -1.0, 1.0))); }

}  // namespace

void DeviceInput::update(Session& session, const DeviceControls& c, double push, double twist) {
  using K = DeviceCommand::Kind;
  const int p = level(push), t = level(twist);
  if (p == push_ && t == twist_) return;
  // Stop is the controller's only way to end one motion; it ends all, so
  // the lever still held is started again.
  const bool released = (push_ != 0 && p == 0) || (twist_ != 0 && t == 0);
  if (released) session.command({K::Stop, 0, 0});
  if (p != 0 && (p != push_ || released)) {
    const double rate = units::mmPerSToMPerS(c.pushSpeedMmS) * std::abs(p) / 20.0;
    session.command({p > 0 ? K::Push : K::Pull, rate, 0});
  }
  if (t != 0 && (t != twist_ || released))
    session.command({K::Twist, units::degPerSToRadPerS(c.twistRateDegS) * t / 20.0, 0});
  push_ = p;
  twist_ = t;
}

}  // namespace coilsim::ui
