#pragma once
// Held keys and gamepad axes as device commands: a push/pull lever and a
// twist lever, each in [-1, 1] of the panel's speed. Commands go out only
// when a lever moves (in 5 % steps), so a held key or a resting trigger
// does not flood the controller or repeat a refusal every frame; letting
// go stops the motion. GL-free, tested in tests/ui.
#include "ui/panel.h"
#include "ui/session.h"

namespace coilsim::ui {

class DeviceInput {
 public:
  // push: + pushes, - pulls; twist: + right-hand about the exit direction.
  void update(Session& session, const DeviceControls& controls, double push, double twist);
  // Forget the levers (after a reset: the controller was recreated).
  void clear() { push_ = twist_ = 0; }

 private:
  int push_ = 0, twist_ = 0;  // lever levels in 5 % steps, -20..20
};

}  // namespace coilsim::ui
