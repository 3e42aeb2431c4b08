#include "physics/effects/builtin.h"

namespace coilsim {

// One line per effect: this is where a new effect is switched into coilsim.
void registerBuiltinEffects(EffectRegistry& r) {
  r.add(makeGravityEffect());
  r.add(makeBuoyancyEffect());
  r.add(makeDragEffect());
  r.add(makeGravityTiltEffect());
  r.add(makeCatheterComplianceEffect());
  r.add(makeWallContactEffect());
  r.add(makeSelfContactEffect());
  r.add(makeRodContactEffect());
}

}  // namespace coilsim
