#pragma once
// Sleeping rods, as rigid-body engines put resting bodies to sleep (Box2D's
// b2_timeToSleep and linear/angular sleep tolerances; Bullet's deactivation
// time): a rod that nothing drives and that has stayed still for a while is
// frozen, so a coil already detached and at rest in the sac stops costing
// its share of every step (integration, wall and self-contact detection,
// pairs with other sleeping rods). Awake rods still collide with it, and it
// wakes when they press on it hard enough. The rule and its thresholds are
// argued in docs/contact.md, "Sleeping coils".
//
// Asleep, a rod keeps its pose exactly, with v = w = 0; it is not
// integrated; its wall and self contacts are not detected again (their last
// lists and per-node forces stay, for the read-outs: a frozen rod needs no
// force); its pairs with awake rods are detected each step (the awake side
// gets its force, the sleeping side does not move) and pairs between two
// sleeping rods are skipped. Waking happens at a step boundary, for the
// whole rod, from that frozen pose at rest.
#include <span>

#include "physics/param.h"

namespace coilsim {

struct Model;
struct State;
struct RodState;

// The thresholds, declared once: name (scene key), edge unit, meaning,
// default, bounds, SI factor.
inline constexpr ParamSpec kSleepParams[] = {
    {"speed_mm_s", "mm/s",
     "a free rod sleeps when every node moves slower than this (rotation: its angular speed times half a segment)",
     0.5, 0.0, 100.0, 1e-3},
    {"time_s", "s", "for this long without a break", 0.1, 0.0, 100.0, 1.0},
    {"wake_force_mn", "mN", "a sleeping rod wakes when awake rods press on it with more than this in total", 0.5, 0.0,
     1e4, 1e-3},
};

// Whether rods may sleep in a run, and the thresholds (SI). Off by default:
// a scene opts in (its "sleep" block), planning and practice switch it on.
struct SleepSettings {
  bool enabled = false;
  double speed = kSleepParams[paramIndex(kSleepParams, "speed_mm_s")].defaultValue * 1e-3;      // m/s
  double time = kSleepParams[paramIndex(kSleepParams, "time_s")].defaultValue;                  // s
  double wakeForce = kSleepParams[paramIndex(kSleepParams, "wake_force_mn")].defaultValue * 1e-3;  // N
};

// Settings from one value per kSleepParams entry, in SI. Throws
// std::invalid_argument naming the parameter if a value is not finite or
// is negative (the scene reader checks the bounds first).
SleepSettings sleepSettings(bool enabled, std::span<const double> si);

// Switches sleeping on or off for runs of `model` (practice, planning).
// Switching it off wakes every sleeping rod at the next step.
void setSleeping(Model& model, bool on);

// Whether rod k may sleep at all: active, not a catheter, held by no
// constraint, and not the device's chain (a coil still attached is driven).
bool canSleep(const Model& model, const State& state, int k);

// After a step that was taken: wakes a sleeping rod that awake rods pressed
// with more than the wake force (at this step's detection), or every rod
// when sleeping is off or the model's effects, gravity, damping or time
// step changed since the last call (a UI edit); then counts how long each
// rod that may sleep has stayed below the speed, and puts to sleep those
// still for the stated time (v = w = 0 from then on). Deterministic: it
// reads only the State and the Model. Never fails.
void updateSleep(const Model& model, State& state);

// Wakes rod r: awake from its frozen pose, at rest, its still time cleared.
void wakeRod(RodState& r);

// How many rods are asleep now.
int sleepingRods(const State& state);

}  // namespace coilsim
