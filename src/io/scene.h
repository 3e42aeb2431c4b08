#pragma once
// Scene files ("coilsim-scene/1", docs/scene-format.md): parsed into a plain
// SceneSpec in the file's units (mm, GPa, g/cm3, deg), checked, then compiled
// into a physics ModelDef in SI. Every error is an InputError naming the
// file, the JSON path and what was expected.
#include <optional>
#include <string>
#include <vector>

#include "io/json_reader.h"
#include "io/scene_obstacles.h"
#include "physics/deployment.h"
#include "physics/integrator.h"
#include "physics/model.h"
#include "physics/rod_spec.h"

namespace coilsim::io {

inline constexpr const char* kSceneFormat = "coilsim-scene/1";

enum class SolveMode { Dynamic, Static };

// The file's rest shape (mm, deg); compiled into a RestShapeDef of the same type.
struct RestShapeSpec {
  using Type = RestShapeDef::Type;
  Type type = Type::Straight;
  // helix
  double loopDiameterMm = 0, pitchMm = 0;
  bool rightHanded = true;
  // polyline
  std::vector<Vec3> pointsMm;
  FrameRule frames = FrameRule::Frenet;
  double twistDegPerMm = 0;
  // birdcage
  double sphereDiameterMm = 0, planeTurnPerLoopDeg = 0;
};

struct MaterialSpec {
  double youngModulusGpa = 0, poissonRatio = 0, densityGcm3 = 0;
};

// Either a solid circular wire (wireRadiusMm) or explicit section constants.
struct SectionSpec {
  bool circular = true;
  double wireRadiusMm = 0;
  double areaMm2 = 0, inertiaMm4 = 0, torsionMm4 = 0, shearFactor = 0, outerRadiusMm = 0;
};

struct PlacementSpec {
  Vec3 positionMm = Vec3::Zero();
  Vec3 direction = Vec3::UnitX();  // tangent of the first node
  Vec3 normal = Vec3::UnitY();     // material normal d1 of the first node
};

// A node of a rod: an index, or "last" (resolved against the beam count).
struct NodeRef {
  bool last = false;
  long index = 0;
  int resolve(int beams) const { return last ? beams : int(index); }
};

struct BoundarySpec {
  NodeRef node;
  bool clamped = true;  // false: pinned (position held, rotation free)
  Vec3 velocityMmS = Vec3::Zero();
  Vec3 angularVelocityDegS = Vec3::Zero();
};

struct LoadSpec {
  NodeRef node;
  Vec3 forceN = Vec3::Zero();
  Vec3 momentNmm = Vec3::Zero();
};

// One rod of a scene file as the file gives it (millimetres, GPa, g/cm3,
// its boundary conditions and loads); compileScene makes it the physics
// RodSpec (physics/rod_spec.h, SI) and the model's rod.
struct RodSpecMm {
  std::string name;
  RodRole role = RodRole::Coil;
  double lengthMm = 0;
  int beams = 0;
  RestShapeSpec rest;
  MaterialSpec material;
  SectionSpec section;
  PlacementSpec placement;
  std::vector<BoundarySpec> boundary;
  std::vector<LoadSpec> loads;
};

// A coil pushed out of a catheter ("deployment" block). The coil's rest
// shape runs, as for any rod, from its proximal (pushed) end to the distal tip.
// The catheter's tip keys hold for both types: where the tip is at rest.
// A flexible catheter adds its polymer tube, rest shape and held/free parts.
struct CatheterRestSpec {
  CatheterShape::Type type = CatheterShape::Type::Straight;
  double angleDeg = 0, radiusMm = 0;
};

struct CatheterSpec {
  bool flexible = false;
  Vec3 tipPositionMm = Vec3::Zero();
  Vec3 direction = Vec3::UnitX();        // exit direction at the tip
  Vec3 referenceNormal = Vec3::UnitY();  // coil d1 at the tip at zero twist; orthogonal to direction
  double outerDiameterMm = 0.6;
  double drawLengthMm = 20;  // rigid only
  // flexible only
  double innerDiameterMm = 0.42;
  MaterialSpec material;
  CatheterRestSpec rest;
  double heldLengthMm = 0, freeLengthMm = 0;
  int beams = 0;
  CompositeWeighting weighting = CompositeWeighting::BendingStiffness;
};

struct DeploymentSpec {
  std::string coilName = "coil";
  double lengthMm = 0;
  int beams = 0;
  RestShapeSpec rest;
  MaterialSpec material;
  SectionSpec section;
  CatheterSpec catheter;
  double initialDeployedMm = 0, initialTwistDeg = 0;
  double maxPushSpeedMmS = 50, maxTwistRateDegS = 720;
};

// One effect switched on by the scene; values in the edge unit of each of the
// effect's ParamSpecs, in their order (defaults where the file gave none).
struct EffectSpec {
  std::string name;
  bool enabled = true;
  std::vector<double> values;
};

struct SceneSpec {
  std::string file;  // where it was read from, for messages
  std::string name, description;
  Vec3 gravityMS2 = Vec3::Zero();
  SolveMode solve = SolveMode::Dynamic;
  // dynamic
  double timeStepS = 0, durationS = 0;
  int newtonIterations = 1;
  double rayleighMass = 0, rayleighStiffness = 0;  // 1/s, s
  // static
  int loadSteps = 10;
  int maxNewtonIterations = 60;
  std::vector<EffectSpec> effects;
  // "sleep": {"enabled": bool, and physics/sleep.h's kSleepParams}: off
  // unless a scene asks; values in their edge units, one per kSleepParams.
  bool sleep = false;
  std::vector<double> sleepValues;
  std::vector<RodSpecMm> rods;
  std::optional<DeploymentSpec> deployment;  // rods of the deployment come after `rods`
  std::vector<ObstacleSpec> obstacles;       // walls (scene_obstacles.h)
  std::vector<std::string> warnings;  // harmless oddities found while reading (unused keys...)
};

// Reads the document's fields with type and per-field range checks.
// Throws InputError (file, JSON path, expectation).
SceneSpec parseScene(const nlohmann::json& document, const std::string& file);

// Cross-field checks that a per-field reader cannot make: node indices in
// range, polyline length within 1 % of length_mm, placement vectors, unique
// names, what a static solve needs. Throws InputError naming the JSON path.
void checkScene(const SceneSpec& spec);

// Converts to SI and builds the physics definition, the deployment (when
// the scene has one) in ModelDef::device. Expects a checked spec; throws
// InputError naming the JSON path if a rest shape or the deployment cannot
// be built.
ModelDef compileScene(const SceneSpec& spec);

// Static solver settings of the scene.
StaticOptions staticOptions(const SceneSpec& spec);

// Number of dynamic steps covering duration_s (rounded up, at least 1).
long stepCount(double durationS, double timeStepS);

// readJsonFile + parseScene + checkScene.
SceneSpec loadScene(const std::string& path);
// parseJson + parseScene + checkScene, for scenes held in memory (tests).
SceneSpec sceneFromText(std::string_view text, const std::string& label);

}  // namespace coilsim::io
