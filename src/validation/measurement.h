#pragma once
// One bench experiment (coil-measurement/1, ../shared/formats/coil-measurement.md)
// as plain data in SI: the coil, the setup, and the captured stages. Filled
// by io::readMeasurement (files) or by tests and the generator (synthetic
// data); the validation maths only reads it.
#include <string>
#include <vector>

#include "physics/math.h"
#include "physics/rest_shape.h"
#include "physics/rod_spec.h"

namespace coilsim::validation {

struct PushSample {
  double time = 0;      // s
  double deployed = 0;  // m
  double twist = 0;     // rad
};

struct Stage {
  std::string name;
  double deployed = 0;          // l, m
  double twist = 0;             // rad about the exit direction (right-hand rule)
  double pointSigma = 0;        // m; 0 when the file gives none
  std::vector<Vec3> centerline; // m, from the catheter tip outward
  std::vector<PushSample> pushHistory;  // empty: static equilibrium after a slow push
  double captureTime = 0;       // s (with pushHistory)
  bool dynamic() const { return !pushHistory.empty(); }
};

struct Measurement {
  std::string file;  // where it was read from (labels messages), may be empty
  std::string name, description;
  // The bench coil, a solid circular wire (physics/rod_spec.h): a polyline
  // rest shape from its proximal end, as a deployment's coil; Young's
  // modulus 0 when the file gives none, Poisson's ratio 0.3 then.
  RodSpec coil = [] {
    RodSpec c;
    c.poissonRatio = 0.3;
    return c;
  }();
  bool givesPoissonRatio = false;  // the file gave coil.poissonRatio (the writer writes it back only then)
  Vec3 gravity = Vec3(0, 0, -9.81);  // m/s^2
  double mediumDensity = 1.2;        // kg/m^3 (air unless the file says otherwise)
  double mediumViscosity = 1.8e-5;   // Pa s
  Placement tip;                     // position, unit exit direction, reference normal (d1 at zero twist)
  std::vector<Stage> stages;
};

}  // namespace coilsim::validation
