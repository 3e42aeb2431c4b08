#include "physics/rod_spec.h"

namespace coilsim {

Material materialOf(const RodSpec& rod) {
  return {rod.youngModulus, shearModulusOf(rod.youngModulus, rod.poissonRatio), rod.density};
}

Section sectionOf(const RodSpec& rod) {
  return rod.wireRadius > 0 ? circularSection(rod.wireRadius, rod.poissonRatio) : rod.explicitSection;
}

double massPerLength(const RodSpec& rod) { return rod.density * sectionOf(rod).area; }

}  // namespace coilsim
