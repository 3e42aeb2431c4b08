// Bending moment per node against the elastica: a straight rod bent to a
// circle of radius R carries M = E I / R with I = pi r^4 / 4 (Euler-Bernoulli;
// the Timoshenko element agrees exactly for end rotations that are equal and
// opposite), and a pure twist carries no bending moment at all.
#include "ui/node_colours.h"

#include <gtest/gtest.h>

#include <cmath>

#include "scenes.h"

namespace coilsim::ui {
namespace {

constexpr double kE = 7.5e9, kRadius = 0.25e-3;  // straightRodModel: platinum, r = 0.25 mm

TEST(NodeColours, ArcCarriesEIOverR) {
  const Model model = testing::straightRodModel();  // 10 mm along x, 20 beams
  State state = makeState(model);
  const double R = 0.02, h = 0.01 / 20;
  RodState& r = state.rods[0];
  for (int i = 0; i <= 20; ++i) {
    const double phi = i * h / R;
    r.x[i] = Vec3(R * std::sin(phi), R * (1 - std::cos(phi)), 0);
    r.q[i] = Quat(Eigen::AngleAxisd(phi, Vec3::UnitZ()));
  }
  std::vector<double> m;
  bendingMoments(state, 0, m);
  ASSERT_EQ(m.size(), 21u);
  const double expected = kE * M_PI * std::pow(kRadius, 4) / 4 / R;
  for (size_t i = 0; i < m.size(); ++i) EXPECT_NEAR(m[i], expected, 1e-6 * expected) << "node " << i;

  // The picture: every node of a uniform arc is fully red at scale M.
  DrawData data;
  fillDrawData(model, state, data);
  const double largest = colourByBendingMoment(state, expected, data);
  EXPECT_NEAR(largest, expected, 1e-6 * expected);
  for (const Colour& c : data.tubes[0].colours) EXPECT_NEAR((c - heatColour(defaultColour(RodRole::Coil), 1.0)).norm(), 0, 1e-4);
}

TEST(NodeColours, TwistIsNotBending) {
  const Model model = testing::straightRodModel();
  State state = makeState(model);
  const double rate = 20.0;  // rad/m of twist
  for (int i = 0; i <= 20; ++i) state.rods[0].q[i] = Quat(Eigen::AngleAxisd(rate * i * 0.0005, Vec3::UnitX()));
  std::vector<double> m;
  bendingMoments(state, 0, m);
  // G J tau is the torsional moment, for scale.
  const double torsion = kE / (2 * 1.39) * M_PI * std::pow(kRadius, 4) / 2 * rate;
  for (double v : m) EXPECT_LT(v, 1e-9 * torsion);
}

TEST(NodeColours, RestIsBaseColourAndRampEnds) {
  const Model model = testing::straightRodModel();
  const State state = makeState(model);
  DrawData data;
  fillDrawData(model, state, data);
  EXPECT_EQ(colourByBendingMoment(state, 0, data), 0.0);
  const Colour base = defaultColour(RodRole::Coil);
  for (const Colour& c : data.tubes[0].colours) EXPECT_NEAR((c - base).norm(), 0, 1e-6);
  EXPECT_NEAR((heatColour(base, 2.0) - Colour(0.95f, 0.1f, 0.05f, base.w())).norm(), 0, 1e-6);  // clamped
  EXPECT_NEAR((heatColour(base, NAN) - heatColour(base, 1.0)).norm(), 0, 1e-6);  // never garbage
}

}  // namespace
}  // namespace coilsim::ui
