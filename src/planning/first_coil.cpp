#include "planning/first_coil.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace coilsim::planning {

FirstCoil recommendFirstCoil(const geometry::SacMorphology& m, const std::vector<io::CoilSpec>& catalogue, int count) {
  if (!(m.volume > 0) || !(m.meanDiameter > 0)) throw std::invalid_argument("first coil: the sac has no volume");
  std::vector<const io::CoilSpec*> framing;
  for (const io::CoilSpec& c : catalogue)
    if (c.family == io::CoilFamily::Framing) framing.push_back(&c);
  FirstCoil f;
  std::vector<double> primaries;
  for (const io::CoilSpec* c : framing) primaries.push_back(c->primaryDiameterMm);
  std::sort(primaries.begin(), primaries.end());
  f.primaryDiameterMm = primaries.empty() ? 0.2921 : primaries[primaries.size() / 2];
  const double r = 0.5 * f.primaryDiameterMm;
  f.loopDiameterMm = m.meanDiameter;
  f.lengthMm = kFramingPacking * m.volume / (M_PI * r * r);
  char buf[320];
  std::snprintf(buf, sizeof buf,
                "framing coil: loop diameter = mean sac diameter %.1f mm; length for %.0f %% packing of %.0f mm^3 with a "
                "%.4f mm primary coil = %.0f mm (one third of the 24 %% of Sluzewski et al. 2004)",
                f.loopDiameterMm, 100 * kFramingPacking, m.volume, f.primaryDiameterMm, f.lengthMm);
  f.rule = buf;
  // Nearest by loop diameter (relative), then by length (relative, weighed less).
  std::sort(framing.begin(), framing.end(), [&](const io::CoilSpec* a, const io::CoilSpec* b) {
    const auto cost = [&](const io::CoilSpec* c) {
      return std::abs(std::log(c->loopDiameterMm / f.loopDiameterMm)) + 0.25 * std::abs(std::log(c->lengthMm / f.lengthMm));
    };
    return cost(a) < cost(b);
  });
  for (const io::CoilSpec* c : framing)
    if (int(f.neighbours.size()) < count) f.neighbours.push_back(c->name);
  if (!f.neighbours.empty()) f.best = f.neighbours.front();
  return f;
}

}  // namespace coilsim::planning
