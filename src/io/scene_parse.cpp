// Scene file -> SceneSpec: types, required keys, unknown keys and per-field
// ranges. Values stay in the file's units; compileScene converts them.
#include <cstdint>
#include <filesystem>
#include <string>

#include "io/scene.h"
#include "io/quantity_reader.h"

namespace coilsim::io {
namespace {

Vec3 toVec3(const std::array<double, 3>& a) { return Vec3(a[0], a[1], a[2]); }

// Bounds of each field, declared once here and quoted in error messages.
const Bounds kPositive = Bounds::positive();
double read(const JsonNode& n, const rodq::Quantity& q) { return readEdge(n, q); }
const Bounds kNonNegative = Bounds::nonNegative();
const Bounds kAny = Bounds::any();

NodeRef readNode(const JsonNode& n) {
  constexpr const char* what = "a node index (an integer >= 0) or \"last\"";
  if (n.exists() && n.value().is_string()) {
    if (n.value().get<std::string>() != "last") n.expected(what);
    return {true, 0};
  }
  if (!n.exists() || !n.value().is_number()) n.expected(what);
  return {false, n.integer(0, 10'000'000)};
}

RestShapeSpec readRestShape(const JsonNode& n) {
  RestShapeSpec r;
  if (!n.isObject()) n.expected("an object with a \"type\"");
  const std::string type = n.child("type").oneOf({"straight", "helix", "polyline", "birdcage"});
  if (type == "straight") {
    n.allowKeys({"type"});
    r.type = RestShapeSpec::Type::Straight;
  } else if (type == "helix") {
    n.allowKeys({"type", "loop_diameter_mm", "pitch_mm", "handedness"});
    r.type = RestShapeSpec::Type::Helix;
    r.loopDiameterMm = read(n, rodq::kLoopDiameter);
    r.pitchMm = read(n, rodq::kPitch);
    r.rightHanded = n.child("handedness").oneOf({"right", "left"}) == "right";
  } else if (type == "polyline") {
    n.allowKeys({"type", "points_mm", "frames", "twist_deg_per_mm"});
    r.type = RestShapeSpec::Type::Polyline;
    for (const JsonNode& p : n.child("points_mm").items(2, SIZE_MAX, "an array of at least 2 points [x, y, z]"))
      r.pointsMm.push_back(toVec3(p.vec3(kAny)));
    if (auto f = n.optional("frames"))
      r.frames = f->oneOf({"frenet", "parallel_transport"}) == "frenet" ? FrameRule::Frenet
                                                                         : FrameRule::ParallelTransport;
    if (auto t = n.optional("twist_deg_per_mm")) r.twistDegPerMm = t->number(kAny);
  } else {
    n.allowKeys({"type", "sphere_diameter_mm", "plane_turn_per_loop_deg"});
    r.type = RestShapeSpec::Type::Birdcage;
    r.sphereDiameterMm = n.child("sphere_diameter_mm").number(kPositive);
    r.planeTurnPerLoopDeg = n.child("plane_turn_per_loop_deg").number(Bounds::closed(-180, 180, "deg"));
  }
  return r;
}

MaterialSpec readMaterial(const JsonNode& n) {
  n.allowKeys({"young_modulus_gpa", "poisson_ratio", "density_g_cm3"});
  MaterialSpec m;
  m.youngModulusGpa = read(n, rodq::kYoungModulus);
  m.poissonRatio = read(n, rodq::kPoissonRatio);
  m.densityGcm3 = read(n, rodq::kDensity);
  return m;
}

SectionSpec readSection(const JsonNode& n) {
  SectionSpec s;
  if (!n.isObject()) n.expected("an object: {\"wire_radius_mm\"} or explicit section constants");
  if (n.has("wire_radius_mm")) {
    n.allowKeys({"wire_radius_mm"});
    s.circular = true;
    s.wireRadiusMm = read(n, rodq::kWireRadius);
    return s;
  }
  n.allowKeys({"wire_radius_mm", "area_mm2", "inertia_mm4", "torsion_mm4", "shear_factor", "outer_radius_mm"});
  if (n.keys().empty())
    n.fail("expected {\"wire_radius_mm\"} (solid circular wire) or {\"area_mm2\", \"inertia_mm4\", "
           "\"torsion_mm4\", \"shear_factor\", \"outer_radius_mm\"}");
  s.circular = false;
  s.areaMm2 = read(n, rodq::kArea);
  s.inertiaMm4 = read(n, rodq::kInertia);
  s.torsionMm4 = read(n, rodq::kTorsion);
  s.shearFactor = read(n, rodq::kShearFactor);
  s.outerRadiusMm = read(n, rodq::kOuterRadius);
  return s;
}

PlacementSpec readPlacement(const JsonNode& n) {
  n.allowKeys({"position_mm", "direction", "normal"});
  PlacementSpec p;
  p.positionMm = toVec3(n.child("position_mm").vec3(kAny));
  p.direction = toVec3(n.child("direction").vec3(kAny));
  p.normal = toVec3(n.child("normal").vec3(kAny));
  return p;
}

BoundarySpec readBoundary(const JsonNode& n) {
  n.allowKeys({"node", "type", "velocity_mm_s", "angular_velocity_deg_s"});
  BoundarySpec b;
  b.node = readNode(n.child("node"));
  b.clamped = n.child("type").oneOf({"clamped", "pinned"}) == "clamped";
  if (auto v = n.optional("velocity_mm_s")) b.velocityMmS = toVec3(v->vec3(kAny));
  if (auto w = n.optional("angular_velocity_deg_s")) b.angularVelocityDegS = toVec3(w->vec3(kAny));
  return b;
}

LoadSpec readLoad(const JsonNode& n) {
  n.allowKeys({"node", "force_N", "moment_N_mm"});
  LoadSpec l;
  l.node = readNode(n.child("node"));
  if (!n.has("force_N") && !n.has("moment_N_mm")) n.fail("a load needs \"force_N\", \"moment_N_mm\" or both");
  if (auto f = n.optional("force_N")) l.forceN = toVec3(f->vec3(kAny));
  if (auto m = n.optional("moment_N_mm")) l.momentNmm = toVec3(m->vec3(kAny));
  return l;
}

RodSpecMm readRod(const JsonNode& n) {
  n.allowKeys({"name", "role", "length_mm", "beams", "rest_shape", "material", "section", "placement", "boundary",
               "loads"});
  RodSpecMm r;
  r.name = n.child("name").string();
  if (auto role = n.optional("role")) {
    const std::string s = role->oneOf({"coil", "catheter", "wire"});
    r.role = s == "coil" ? RodRole::Coil : s == "catheter" ? RodRole::Catheter : RodRole::Wire;
  }
  r.lengthMm = read(n, rodq::kLength);
  r.beams = int(n.child("beams").integer(1, rodq::kMaxBeams));
  r.rest = readRestShape(n.child("rest_shape"));
  r.material = readMaterial(n.child("material"));
  r.section = readSection(n.child("section"));
  if (auto p = n.optional("placement")) r.placement = readPlacement(*p);
  if (auto b = n.optional("boundary"))
    for (const JsonNode& item : b->items(0, SIZE_MAX, "an array of boundary conditions"))
      r.boundary.push_back(readBoundary(item));
  if (auto l = n.optional("loads"))
    for (const JsonNode& item : l->items(0, SIZE_MAX, "an array of loads")) r.loads.push_back(readLoad(item));
  return r;
}

// The coil of a deployment: a rod's name, length, beams, rest shape,
// material and section, read by the same sub-readers as rods.
void readCoil(const JsonNode& n, DeploymentSpec& d) {
  n.allowKeys({"name", "length_mm", "beams", "rest_shape", "material", "section"});
  if (auto name = n.optional("name")) d.coilName = name->string();
  d.lengthMm = read(n, rodq::kLength);
  d.beams = int(n.child("beams").integer(2, rodq::kMaxBeams));
  d.rest = readRestShape(n.child("rest_shape"));
  d.material = readMaterial(n.child("material"));
  d.section = readSection(n.child("section"));
}

// A steam-shaped tip: {"type": "straight"}, {"type": "angled", "angle_deg",
// "radius_mm"}, {"type": "j", "radius_mm", "angle_deg" (180 by default)},
// {"type": "s", "angle_deg", "radius_mm"}.
CatheterRestSpec readCatheterRest(const JsonNode& n) {
  if (!n.isObject()) n.expected("an object with a \"type\"");
  CatheterRestSpec r;
  const std::string type = n.child("type").oneOf({"straight", "angled", "j", "s"});
  if (type == "straight") {
    n.allowKeys({"type"});
    return r;
  }
  n.allowKeys({"type", "angle_deg", "radius_mm"});
  r.type = type == "angled" ? CatheterShape::Type::Angled : type == "j" ? CatheterShape::Type::J : CatheterShape::Type::S;
  const Bounds angle{0, 180, true, false, "deg"};
  if (type == "j") r.angleDeg = n.has("angle_deg") ? n.child("angle_deg").number(angle) : 180.0;
  else r.angleDeg = n.child("angle_deg").number(angle);
  r.radiusMm = n.child("radius_mm").number(kPositive);
  return r;
}

CatheterSpec readCatheter(const JsonNode& n) {
  if (!n.isObject()) n.expected("an object with a \"type\": \"rigid\" or \"flexible\"");
  CatheterSpec c;
  // Rigid: a straight tip held in place. Flexible: a polymer beam chain with a rest shape.
  c.flexible = n.child("type").oneOf({"rigid", "flexible"}) == "flexible";
  if (c.flexible)
    n.allowKeys({"type", "tip_position_mm", "direction", "reference_normal", "outer_diameter_mm", "inner_diameter_mm",
                 "material", "rest_shape", "held_length_mm", "free_length_mm", "beams", "composite_weighting"});
  else
    n.allowKeys({"type", "tip_position_mm", "direction", "reference_normal", "outer_diameter_mm", "draw_length_mm"});
  c.tipPositionMm = toVec3(n.child("tip_position_mm").vec3(kAny));
  c.direction = toVec3(n.child("direction").vec3(kAny));
  c.referenceNormal = toVec3(n.child("reference_normal").vec3(kAny));
  if (auto d = n.optional("outer_diameter_mm")) c.outerDiameterMm = d->number(kPositive);
  if (!c.flexible) {
    if (auto l = n.optional("draw_length_mm")) c.drawLengthMm = l->number(kPositive);
    return c;
  }
  if (auto d = n.optional("inner_diameter_mm")) c.innerDiameterMm = d->number(kNonNegative);
  c.material = readMaterial(n.child("material"));
  c.rest = readCatheterRest(n.child("rest_shape"));
  c.heldLengthMm = n.child("held_length_mm").number(kNonNegative);
  c.freeLengthMm = n.child("free_length_mm").number(kPositive);
  c.beams = int(n.child("beams").integer(2, 10'000));
  if (auto w = n.optional("composite_weighting"))
    c.weighting = w->oneOf({"bending_stiffness", "young_modulus"}) == "bending_stiffness"
                      ? CompositeWeighting::BendingStiffness
                      : CompositeWeighting::YoungModulus;
  return c;
}

DeploymentSpec readDeployment(const JsonNode& n) {
  n.allowKeys({"coil", "catheter", "initial_deployed_mm", "initial_twist_deg", "max_push_speed_mm_s",
               "max_twist_rate_deg_s"});
  DeploymentSpec d;
  readCoil(n.child("coil"), d);
  d.catheter = readCatheter(n.child("catheter"));
  if (auto l = n.optional("initial_deployed_mm")) d.initialDeployedMm = l->number(kNonNegative);
  if (auto t = n.optional("initial_twist_deg")) d.initialTwistDeg = t->number(kAny);
  // A hand pushes a few mm/s and twists a few turns a second; these limits
  // may be set generous, never off.
  if (auto v = n.optional("max_push_speed_mm_s")) d.maxPushSpeedMmS = v->number({0, 1000, true, false, "mm/s"});
  if (auto w = n.optional("max_twist_rate_deg_s")) d.maxTwistRateDegS = w->number({0, 36000, true, false, "deg/s"});
  return d;
}

// Parameter keys, bounds and defaults come from each Effect's ParamSpecs.
EffectSpec readEffect(const JsonNode& n, const std::string& name) {
  const Effect* effect = EffectRegistry::global().find(name);
  if (!effect) {
    std::string known;
    for (const Effect* e : EffectRegistry::global().all()) known += (known.empty() ? "" : ", ") + std::string(e->name());
    n.fail("unknown effect; registered effects: " + known);
  }
  std::vector<std::string_view> allowed{"enabled"};
  for (const ParamSpec& p : effect->params()) allowed.push_back(p.name);
  n.allowKeys(allowed);
  EffectSpec e;
  e.name = name;
  if (auto en = n.optional("enabled")) e.enabled = en->boolean();
  for (const ParamSpec& p : effect->params()) {
    const auto v = n.optional(p.name);
    e.values.push_back(v ? v->number(Bounds::closed(p.min, p.max, p.unit)) : p.defaultValue);
  }
  return e;
}

std::string fileStem(const std::string& file) { return std::filesystem::path(file).stem().string(); }

}  // namespace

SceneSpec parseScene(const nlohmann::json& document, const std::string& file) {
  const JsonNode root(document, file);
  if (!root.isObject()) root.expected("a JSON object (a coilsim scene)");
  root.allowKeys({"format", "name", "description", "gravity_m_s2", "solve", "time_step_s", "duration_s",
                  "newton_iterations", "damping", "sleep", "load_steps", "max_newton_iterations", "effects", "rods",
                  "deployment", "obstacles"});
  root.child("format").oneOf({kSceneFormat});
  SceneSpec s;
  s.file = file;
  s.name = root.has("name") ? root.child("name").string() : fileStem(file);
  if (auto d = root.optional("description")) s.description = d->string(true);
  // Earth is 9.81; a centrifuge bench might reach a few g: beyond 100 m/s2 is a unit slip.
  s.gravityMS2 = toVec3(root.child("gravity_m_s2").vec3(Bounds::closed(-100, 100, "m/s2")));
  s.solve = root.child("solve").oneOf({"dynamic", "static"}) == "dynamic" ? SolveMode::Dynamic : SolveMode::Static;
  const bool dynamic = s.solve == SolveMode::Dynamic;

  // Keys of the other solve mode are still checked, and reported as unused.
  const auto unused = [&](const char* key) {
    if (root.has(key))
      s.warnings.push_back(root.child(key).where() + ": not used by a " + (dynamic ? "dynamic" : "static") + " solve");
  };
  if (dynamic || root.has("time_step_s")) s.timeStepS = root.child("time_step_s").number({0, rodq::kMaxTimeStepS, true, false, "s"});
  if (dynamic || root.has("duration_s")) s.durationS = root.child("duration_s").number(kPositive);
  if (auto it = root.optional("newton_iterations")) s.newtonIterations = int(it->integer(1, 100));
  if (auto d = root.optional("damping")) {
    d->allowKeys({"rayleigh_mass_1_s", "rayleigh_stiffness_s"});
    if (auto a = d->optional("rayleigh_mass_1_s")) s.rayleighMass = a->number(kNonNegative);
    if (auto b = d->optional("rayleigh_stiffness_s")) s.rayleighStiffness = b->number(kNonNegative);
  }
  // Sleeping rods (physics/sleep.h): the keys and bounds are kSleepParams'.
  for (const ParamSpec& p : kSleepParams) s.sleepValues.push_back(p.defaultValue);
  if (auto z = root.optional("sleep")) {
    std::vector<std::string_view> allowed{"enabled"};
    for (const ParamSpec& p : kSleepParams) allowed.push_back(p.name);
    z->allowKeys(allowed);
    if (auto en = z->optional("enabled")) s.sleep = en->boolean();
    for (size_t i = 0; i < std::size(kSleepParams); ++i)
      if (auto v = z->optional(kSleepParams[i].name))
        s.sleepValues[i] = v->number(Bounds::closed(kSleepParams[i].min, kSleepParams[i].max, kSleepParams[i].unit));
  }
  if (auto l = root.optional("load_steps")) s.loadSteps = int(l->integer(1, 100'000));
  if (auto m = root.optional("max_newton_iterations")) s.maxNewtonIterations = int(m->integer(1, 10'000));
  if (dynamic) {
    unused("load_steps");
    unused("max_newton_iterations");
  } else {
    for (const char* key : {"time_step_s", "duration_s", "newton_iterations", "damping", "sleep"}) unused(key);
  }

  if (auto effects = root.optional("effects")) {
    if (!effects->isObject()) effects->expected("an object {\"effect name\": {parameters}}");
    for (const std::string& name : effects->keys()) s.effects.push_back(readEffect(effects->child(name), name));
  }
  // A scene needs something to simulate: rods, a deployment, or both.
  const bool deployment = root.has("deployment");
  if (deployment || root.has("rods")) {
    if (auto rods = root.optional("rods"))
      for (const JsonNode& rod : rods->items(deployment ? 0 : 1, SIZE_MAX,
                                             deployment ? "an array of rods" : "an array of at least one rod"))
        s.rods.push_back(readRod(rod));
  } else {
    root.child("rods").expected("an array of at least one rod (or a \"deployment\" block)");
  }
  if (deployment) s.deployment = readDeployment(root.child("deployment"));
  if (auto o = root.optional("obstacles")) s.obstacles = readObstacles(*o, file);
  return s;
}

}  // namespace coilsim::io
