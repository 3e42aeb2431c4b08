#pragma once
#include "physics/math.h"

namespace coilsim::validation {

// A vector of three draws from `dist`, the same on every compiler: the
// order in which Vec3(d(rng), d(rng), d(rng)) draws its arguments is
// unspecified (GCC draws z first, clang x). This is GCC's order, so that
// measurements generated before keep their values.
template <class Dist, class Rng>
Vec3 drawVec3(Dist& dist, Rng& rng) {
  const double z = dist(rng);
  const double y = dist(rng);
  const double x = dist(rng);
  return {x, y, z};
}

}  // namespace coilsim::validation
