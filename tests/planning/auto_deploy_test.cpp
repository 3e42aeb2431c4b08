// The operator's rest after a twist ends when the felt force has decayed
// (ForceDecay), checked against the analytic free response of a damped
// spring-mass: the force it would feel is F_end + k x(t), x(0) = x0, x'(0) = 0.
#include "planning/auto_deploy.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <optional>

namespace coilsim::planning {
namespace {

constexpr double kDt = 1e-3;         // s, the plans' time step
constexpr double kLag = 0.01;        // s, AutoDeployOptions::decayWindow
constexpr double kTolerance = 0.5;   // mN (units do not matter to the rule)
constexpr double kStart = 20, kEnd = 3;  // mN: the felt force at the start of the rest, and where it goes

// First sample time at which the rule says settled, or nothing within `horizon` s.
std::optional<double> settledAt(const std::function<double(double)>& force, double horizon = 3) {
  ForceDecay rule(kLag, kTolerance, kDt);
  for (int k = 0; k * kDt <= horizon; ++k)
    if (rule.add(force(k * kDt))) return k * kDt;
  return std::nullopt;
}

// Largest deviation from the end value from t on (sampled finely, to the horizon).
double largestDeviationFrom(double t, const std::function<double(double)>& x, double horizon = 3) {
  double m = 0;
  for (double s = t; s <= horizon; s += 1e-5) m = std::max(m, std::abs(x(s)));
  return m;
}

// First time the envelope e(t) (decreasing) is at or below v.
double whenBelow(const std::function<double(double)>& e, double v) {
  double t = 0;
  while (e(t) > v) t += 1e-5;
  return t;
}

struct SpringMass {
  double zeta, omega0;  // damping ratio, undamped angular frequency (rad/s)
  double x0 = kStart - kEnd;
  double x(double t) const {
    if (zeta < 1) {
      const double wd = omega0 * std::sqrt(1 - zeta * zeta);
      return x0 * std::exp(-zeta * omega0 * t) * (std::cos(wd * t) + zeta / std::sqrt(1 - zeta * zeta) * std::sin(wd * t));
    }
    const double s = std::sqrt(zeta * zeta - 1), r1 = -omega0 * (zeta - s), r2 = -omega0 * (zeta + s);
    return x0 * (r2 * std::exp(r1 * t) - r1 * std::exp(r2 * t)) / (r2 - r1);
  }
  // A bound of |x| from t on: the exponential envelope (underdamped), x itself (overdamped, monotone).
  double envelope(double t) const {
    if (zeta < 1) return x0 * std::exp(-zeta * omega0 * t) / std::sqrt(1 - zeta * zeta);
    return x(t);
  }
};

// The rule must not stop while the response can still leave the tolerance
// band, and must stop within 2 lags of the envelope reaching half the band
// (its range test needs the peak-to-peak swing of the last 2 lags inside it).
void expectSettlesLikeTheAnalyticResponse(const SpringMass& m) {
  const auto force = [&](double t) { return kEnd + m.x(t); };
  const std::optional<double> stop = settledAt(force);
  ASSERT_TRUE(stop) << "never settled";
  EXPECT_LE(largestDeviationFrom(*stop, [&](double t) { return m.x(t); }), kTolerance)
      << "stopped at " << *stop << " s while the response was still outside the band";
  const double halfBand = whenBelow([&](double t) { return m.envelope(t); }, 0.5 * kTolerance);
  EXPECT_LE(*stop, std::max(halfBand, 0.0) + 2 * kLag + kDt) << "stopped late";
}

TEST(ForceDecay, UnderdampedSpringMassSettlesOnceItsEnvelopeIsInTheBand) {
  expectSettlesLikeTheAnalyticResponse({0.1, 2 * M_PI / 0.008});
  expectSettlesLikeTheAnalyticResponse({0.05, 2 * M_PI / 0.012});
  expectSettlesLikeTheAnalyticResponse({0.3, 2 * M_PI / 0.005});
}

TEST(ForceDecay, OverdampedSpringMassSettlesOnceWithinTheBand) {
  expectSettlesLikeTheAnalyticResponse({2.0, 2 * M_PI / 0.01});
  expectSettlesLikeTheAnalyticResponse({1.5, 300});
}

// A decay slower than the lag moves less than the band over 2 lags long
// before it is over; the geometric tail keeps the rule waiting, and is exact
// for an exponential: it stops within a step of x0 e^(-t/tau) = tolerance.
TEST(ForceDecay, SlowExponentialWaitsForItsTail) {
  for (const double tau : {0.03, 0.1}) {
    const double x0 = kStart - kEnd;
    const std::optional<double> stop = settledAt([&](double t) { return kEnd + x0 * std::exp(-t / tau); });
    ASSERT_TRUE(stop);
    const double analytic = tau * std::log(x0 / kTolerance);
    EXPECT_GE(*stop, analytic - kDt) << "tau " << tau;
    EXPECT_LE(*stop, analytic + kDt) << "tau " << tau;
  }
}

TEST(ForceDecay, ConstantSettlesAfterTwoLagsAndNoiseAboveTheBandNever) {
  EXPECT_NEAR(*settledAt([](double) { return kEnd; }), 2 * kLag, 0.5 * kDt);
  // Spikes of a contact every 7 ms, each larger than the band: never settled.
  EXPECT_FALSE(settledAt([](double t) { return kEnd + (std::fmod(t, 0.007) < kDt ? 2 * kTolerance : 0.0); }));
}

}  // namespace
}  // namespace coilsim::planning
