// The first-coil rule against its own statement worked by hand: loop
// diameter = mean sac diameter, length = 8 % of the sac volume over the
// primary coil's cross-section pi r^2; catalogue neighbours by loop first.
#include "planning/first_coil.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace coilsim::planning {
namespace {

io::CoilSpec coil(const char* name, io::CoilFamily family, double loop, double length, double primary) {
  io::CoilSpec c;
  c.name = name, c.family = family, c.loopDiameterMm = loop, c.lengthMm = length, c.primaryDiameterMm = primary;
  return c;
}

TEST(FirstCoil, SizedFromTheMeanDiameterAndTheVolume) {
  const std::vector<io::CoilSpec> catalogue = {
      coil("frame-5x100", io::CoilFamily::Framing, 5, 100, 0.30), coil("frame-7x150", io::CoilFamily::Framing, 7, 150, 0.30),
      coil("frame-10x300", io::CoilFamily::Framing, 10, 300, 0.30), coil("fill-7x150", io::CoilFamily::Filling, 7, 150, 0.25),
      coil("frame-20x500", io::CoilFamily::Framing, 20, 500, 0.36)};
  geometry::SacMorphology m;
  m.meanDiameter = 7.2;
  m.volume = 4.0 / 3.0 * M_PI * 3.6 * 3.6 * 3.6;  // a 7.2 mm ball, 195.4 mm^3
  const FirstCoil f = recommendFirstCoil(m, catalogue);
  EXPECT_DOUBLE_EQ(f.loopDiameterMm, 7.2);
  EXPECT_DOUBLE_EQ(f.primaryDiameterMm, 0.30);  // median of the framing coils' 0.30, 0.30, 0.30, 0.36
  // 0.08 * 195.43 / (pi * 0.15^2) = 221.2 mm
  EXPECT_NEAR(f.lengthMm, 221.2, 0.1);
  ASSERT_EQ(f.neighbours.size(), 3u);
  EXPECT_EQ(f.best, "frame-7x150");
  EXPECT_EQ(f.neighbours[0], "frame-7x150");
  for (const std::string& n : f.neighbours) EXPECT_NE(n, "fill-7x150");  // framing coils only
  EXPECT_NE(f.rule.find("Sluzewski"), std::string::npos);
}

TEST(FirstCoil, ASacWithoutVolumeIsRefused) {
  geometry::SacMorphology m;
  EXPECT_THROW(recommendFirstCoil(m, {}), std::invalid_argument);
}

}  // namespace
}  // namespace coilsim::planning
