#pragma once
// Coil wires as physics::RodSpec (SI) for the tests that deploy one: a rest
// shape on a length, the material constants and a solid circular wire.
#include "physics/rest_shape.h"
#include "physics/rod_spec.h"

namespace coilsim::test {

// A right-handed helix of loop diameter `loop` and rise `pitch` per turn, m.
inline RestShapeDef helixRest(double loop, double pitch) {
  RestShapeDef r;
  r.type = RestShapeDef::Type::Helix;
  r.loopDiameter = loop;
  r.pitch = pitch;
  r.rightHanded = true;
  return r;
}

// `length` m of solid wire of radius `radius` m with rest shape `rest`.
inline RodSpec wireSpec(double length, const RestShapeDef& rest, double youngModulus, double poissonRatio,
                        double density, double radius) {
  RodSpec s;
  s.length = length;
  s.rest = rest;
  s.youngModulus = youngModulus;
  s.poissonRatio = poissonRatio;
  s.density = density;
  s.wireRadius = radius;
  return s;
}

}  // namespace coilsim::test
