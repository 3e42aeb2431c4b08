#include "physics/sleep.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "physics/model.h"
#include "physics/state.h"

namespace coilsim {
namespace {

// What a UI or a validation stage may change in a Model between steps and
// that changes the forces on a resting rod: gravity, damping, time step,
// every effect's switch and values.
std::vector<double> modelFingerprint(const Model& model) {
  std::vector<double> f{model.gravity.x(), model.gravity.y(), model.gravity.z(), model.damping.massCoeff,
                        model.damping.stiffnessCoeff, model.timeStep};
  for (const EffectUse& u : model.effects) {
    f.push_back(u.enabled ? 1.0 : 0.0);
    f.insert(f.end(), u.values.begin(), u.values.end());
  }
  return f;
}

// Whether every active node of r moves slower than `speed`: translation,
// and rotation times half the longer neighbouring segment (how fast the
// rotation alone carries the segment's ends).
bool still(const RodState& r, double speed) {
  const double speed2 = speed * speed;
  for (int i = 0; i < r.activeNodes; ++i) {
    if (!(r.v[i].squaredNorm() < speed2)) return false;
    const double left = i > 0 ? r.beams[i - 1].length : 0.0, right = i + 1 < r.activeNodes ? r.beams[i].length : 0.0;
    const double arm = 0.5 * std::max(left, right);
    if (!(r.w[i].squaredNorm() * arm * arm < speed2)) return false;
  }
  return true;
}

// The total normal force the rod's pair contacts (with awake rods only:
// pairs of two sleeping rods are not detected) put on it at detection.
double pressedByOthers(const RodState& r) {
  double total = 0;
  for (const ContactPoint& c : r.contact.rod) total += std::max(0.0, c.normalForce);
  return total;
}

}  // namespace

SleepSettings sleepSettings(bool enabled, std::span<const double> si) {
  if (si.size() != std::size(kSleepParams))
    throw std::invalid_argument("sleep: expected " + std::to_string(std::size(kSleepParams)) + " values");
  for (size_t i = 0; i < si.size(); ++i)
    if (!std::isfinite(si[i]) || si[i] < 0)
      throw std::invalid_argument("sleep: " + std::string(kSleepParams[i].name) + " must be finite and >= 0");
  SleepSettings s;
  s.enabled = enabled;
  s.speed = si[paramIndex(kSleepParams, "speed_mm_s")];
  s.time = si[paramIndex(kSleepParams, "time_s")];
  s.wakeForce = si[paramIndex(kSleepParams, "wake_force_mn")];
  return s;
}

void setSleeping(Model& model, bool on) { model.sleep.enabled = on; }

bool canSleep(const Model& model, const State& state, int k) {
  const RodState& r = state.rods[size_t(k)];
  const RodModel& rm = model.rods[size_t(k)];
  if (!r.active || r.activeNodes < 2 || rm.role == RodRole::Catheter || !rm.constraints.empty()) return false;
  return !model.device || (k != model.device->chainRod && k != model.device->catheterRod);
}

void wakeRod(RodState& r) {
  r.asleep = false;
  r.stillTime = 0;
  std::fill(r.v.begin(), r.v.end(), Vec3::Zero());
  std::fill(r.w.begin(), r.w.end(), Vec3::Zero());
}

int sleepingRods(const State& state) {
  int n = 0;
  for (const RodState& r : state.rods) n += r.asleep;
  return n;
}

void updateSleep(const Model& model, State& state) {
  const SleepSettings& s = model.sleep;
  if (!s.enabled) {
    // Nothing to do in a run that never slept (every shipped scene): no cost, no change.
    if (state.sleep.seen.empty()) return;
    for (RodState& r : state.rods)
      if (r.asleep) wakeRod(r), ++state.sleep.wakes;
    for (RodState& r : state.rods) r.stillTime = 0;
    state.sleep.seen.clear();
    return;
  }
  std::vector<double> now = modelFingerprint(model);
  const bool changed = !state.sleep.seen.empty() && now != state.sleep.seen;
  state.sleep.seen = std::move(now);
  for (size_t k = 0; k < state.rods.size(); ++k) {
    RodState& r = state.rods[k];
    if (!canSleep(model, state, int(k))) {
      if (r.asleep) wakeRod(r), ++state.sleep.wakes;
      r.stillTime = 0;
      continue;
    }
    if (r.asleep) {
      if (changed || pressedByOthers(r) > s.wakeForce) wakeRod(r), ++state.sleep.wakes;
      continue;
    }
    if (changed || !still(r, s.speed)) {
      r.stillTime = 0;
      continue;
    }
    r.stillTime += model.timeStep;
    // (A tolerance of a hundredth of a step: the time is a sum of steps.)
    if (r.stillTime >= s.time - 0.01 * model.timeStep) {
      r.asleep = true;
      std::fill(r.v.begin(), r.v.end(), Vec3::Zero());
      std::fill(r.w.begin(), r.w.end(), Vec3::Zero());
      ++state.sleep.sleeps;
    }
  }
}

}  // namespace coilsim
