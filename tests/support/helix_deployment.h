#pragma once
// A platinum helix (5 mm loops, 0.8 mm pitch, 0.15 mm wire) of `lengthMm`
// in a rigid catheter at the origin along +x, `initialMm` out, under
// gravity, 1 ms steps: the deployment the ui tests drive.
#include "support/coil_spec.h"
#include "physics/deployment.h"
#include "physics/effect.h"
#include "physics/model.h"
#include "physics/rest_shape.h"
#include "physics/section.h"
#include "physics/state.h"

namespace coilsim::test {

struct HelixDeployment {
  Model model;     // with the deployment as its device
  Deployment dep;  // model.device, for short
  State start;     // `initialMm` out
};

inline HelixDeployment makeHelixDeployment(double lengthMm = 40.0, double initialMm = 2.0) {
  HelixDeployment s;
  ModelDef def;
  def.effects.push_back(EffectRegistry::global().use("gravity"));
  def.damping = {1.0, 0.0};
  def.timeStep = 1e-3;
  DeploymentDef d;
  d.coil = wireSpec(lengthMm * 1e-3, helixRest(0.005, 0.0008), 7.5e9, 0.39, 21450, 0.15e-3);
  d.coilBeams = int(lengthMm);
  d.tip.normal = Vec3(0, 0, 1);
  d.maxPushSpeed = 0.05;
  d.initialDeployed = initialMm * 1e-3;
  def.device = d;
  s.model = compileModel(def);
  s.dep = *s.model.device;
  s.start = makeState(s.model);
  return s;
}

}  // namespace coilsim::test
