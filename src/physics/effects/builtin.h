#pragma once
// Factories of the built-in effects, one per file in this folder.
#include <memory>

#include "physics/effect.h"

namespace coilsim {
std::unique_ptr<Effect> makeGravityEffect();
std::unique_ptr<Effect> makeBuoyancyEffect();
std::unique_ptr<Effect> makeDragEffect();
std::unique_ptr<Effect> makeWallContactEffect();
std::unique_ptr<Effect> makeSelfContactEffect();
std::unique_ptr<Effect> makeRodContactEffect();
std::unique_ptr<Effect> makeGravityTiltEffect();
std::unique_ptr<Effect> makeCatheterComplianceEffect();
}  // namespace coilsim
