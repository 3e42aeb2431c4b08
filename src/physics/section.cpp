#include "physics/section.h"

#include <cmath>

namespace coilsim {

Section circularSection(double radius, double poisson) {
  Section s;
  s.radius = radius;
  s.area = M_PI * radius * radius;
  s.iy = s.iz = M_PI * std::pow(radius, 4) / 4.0;
  s.torsion = 2.0 * s.iy;
  s.shearFactor = 6.0 * (1.0 + poisson) / (7.0 + 6.0 * poisson);
  return s;
}

}  // namespace coilsim
