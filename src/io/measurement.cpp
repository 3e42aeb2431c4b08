// coil-measurement/1 reader and writer; units convert only through units.h.
#include "io/measurement.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "io/json_reader.h"
#include "io/json_writer.h"
#include "io/quantity_reader.h"
#include "io/units.h"

namespace coilsim::io {
namespace {

using validation::Measurement;
using validation::Stage;

std::string fmt(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

Vec3 vec(const JsonNode& n) {
  const auto a = n.vec3(Bounds::any());
  return Vec3(a[0], a[1], a[2]);
}

// A unit vector within a relative 1e-3 (files print a few digits).
Vec3 unitVec(const JsonNode& n) {
  const Vec3 v = vec(n);
  if (std::abs(v.norm() - 1.0) > 1e-3) n.expected("a unit vector [x, y, z] (length 1 within 1e-3), got length " + fmt(v.norm()));
  return v.normalized();
}

// Limits of what a bench measurement can hold (docs/input-limits.md): a
// value beyond them is a typo or a unit error, and would otherwise reach the
// fit as an ordinary, huge stage error.
constexpr double kMaxCoords = 1e6;         // |x|, |y|, |z| in mm
constexpr size_t kMaxPoints = 100'000;     // per centre line or polyline
constexpr double kMaxTwistDeg = 36'000;    // |twist| of a stage or a sample: 100 turns
constexpr double kMaxHistorySpanS = 3600;  // capture time after the first push sample

// A rod quantity in SI: key, bounds and unit from its declaration
// (physics/rod_quantities.h), as in a scene file.
double readSI(const JsonNode& parent, const rodq::Quantity& q) { return units::toSI(q.spec, readEdge(parent, q)); }

// Points in mm, at least 2; consecutive points must differ (a centre line or
// polyline with a zero-length segment has no tangent there).
std::vector<Vec3> pointsMm(const JsonNode& n, std::string_view what) {
  std::vector<Vec3> out;
  const std::vector<JsonNode> items = n.items(2, SIZE_MAX, what);
  if (items.size() > kMaxPoints)
    n.fail("holds " + std::to_string(items.size()) + " points, more than the limit of " + std::to_string(kMaxPoints));
  for (const JsonNode& p : items) {
    const auto a = p.vec3(Bounds::closed(-kMaxCoords, kMaxCoords, "mm"));
    out.push_back(units::mmToM(1.0) * Vec3(a[0], a[1], a[2]));
    if (out.size() > 1 && out.back() == out[out.size() - 2])
      p.fail("expected a point different from the previous one (consecutive points of a line must differ), got the same "
             "point twice");
  }
  return out;
}

// The file's polyline runs from the distal tip; a coil's rest shape (as a
// deployment samples it) from the proximal end.
std::vector<Vec3> reversed(std::vector<Vec3> points) {
  std::reverse(points.begin(), points.end());
  return points;
}

RestShapeDef readRest(const JsonNode& n, double lengthM, double wireRadiusM) {
  if (!n.isObject()) n.expected("an object with a \"type\": straight, helix or polyline");
  RestShapeDef r;
  const std::string type = n.child("type").oneOf({"straight", "helix", "polyline"});
  if (type == "straight") return r;
  if (type == "helix") {
    r.type = RestShapeDef::Type::Helix;
    // A loop cannot be tighter than the wire it is wound from, nor wider than the coil is long.
    r.loopDiameter = readSI(n, rodq::kLoopDiameter);
    if (r.loopDiameter < 2 * wireRadiusM || r.loopDiameter > lengthM)
      n.child(rodq::kLoopDiameter.spec.name)
          .expected("a loop diameter from the wire diameter " + fmt(units::mToMm(2 * wireRadiusM)) + " mm to the coil length " +
                    fmt(units::mToMm(lengthM)) + " mm");
    r.pitch = readSI(n, rodq::kPitch);
    if (r.pitch > lengthM)
      n.child(rodq::kPitch.spec.name).expected("a pitch of at most the coil length " + fmt(units::mToMm(lengthM)) + " mm");
    r.rightHanded = n.child("handedness").oneOf({"right", "left"}) == "right";
    return r;
  }
  r.type = RestShapeDef::Type::Polyline;
  r.frames = FrameRule::Frenet;
  const JsonNode pts = n.child("points_mm");
  const std::vector<Vec3> fromTip =
      pointsMm(pts, "an array of at least 2 points [x, y, z] in mm, from the distal tip to the proximal end");
  double arc = 0;
  for (size_t i = 1; i < fromTip.size(); ++i) arc += (fromTip[i] - fromTip[i - 1]).norm();
  if (std::abs(arc - lengthM) > 0.01 * lengthM)
    pts.fail("the polyline is " + fmt(units::mToMm(arc)) + " mm long but /coil/length_mm is " + fmt(units::mToMm(lengthM)) +
             " mm; they must agree within 1 %");
  r.points = reversed(fromTip);
  if (auto t = n.optional("twist_deg_per_mm"))
    r.twistPerLength = units::degPerMmToRadPerM(t->number(Bounds::closed(-360, 360, "deg/mm")));
  return r;
}

// The coil as a solid circular wire; its mass per length from density_g_cm3
// or mass_g (then as a density: mass / (pi r^2 length)).
void readCoil(const JsonNode& n, Measurement& m) {
  RodSpec& c = m.coil;
  if (!n.isObject()) n.expected("an object describing the coil");
  c.length = readSI(n, rodq::kLength);
  c.wireRadius = readSI(n, rodq::kWireRadius);
  const double area = M_PI * c.wireRadius * c.wireRadius;
  const auto density = n.optional(rodq::kDensity.spec.name);
  const auto mass = n.optional("mass_g");
  if (!density && !mass)
    n.child(rodq::kDensity.spec.name).expected(boundsOf(rodq::kDensity).describe() + ", or \"mass_g\" instead");
  if (density) c.density = readSI(n, rodq::kDensity);
  if (mass) {
    const double perLength = mass->number(Bounds::positive()) * 1e-3 / c.length;  // g -> kg
    const double densityPerLength = c.density * area;
    if (density && std::abs(perLength - densityPerLength) > 0.01 * densityPerLength)
      mass->fail("mass_g and density_g_cm3 disagree by more than 1 % (" + fmt(perLength * c.length * 1e3) + " g vs " +
                 fmt(densityPerLength * c.length * 1e3) + " g); give one of them");
    const double implied = units::kgm3ToGcm3(perLength / area);
    if (!(implied >= 1e-3 && implied <= 1000))
      mass->fail("mass_g implies a wire density of " + fmt(implied) +
                 " g/cm3 (mass / (pi r^2 length)), outside [0.001, 1000] g/cm3: check its unit");
    c.density = perLength / area;
  }
  c.rest = readRest(n.child("rest_shape"), c.length, c.wireRadius);
  if (n.optional(rodq::kYoungModulus.spec.name)) c.youngModulus = readSI(n, rodq::kYoungModulus);
  if (n.optional(rodq::kPoissonRatio.spec.name)) {
    c.poissonRatio = readSI(n, rodq::kPoissonRatio);
    m.givesPoissonRatio = true;
  }
}

Stage readStage(const JsonNode& n, double coilLength, const Vec3& tip) {
  if (!n.isObject()) n.expected("a stage object");
  Stage s;
  s.name = n.child("name").string();
  const JsonNode l = n.child("deployed_length_mm");
  s.deployed = units::mmToM(l.number(Bounds::positive()));
  if (s.deployed > coilLength * (1 + 1e-9))
    l.expected("a deployed length <= the coil length " + fmt(units::mToMm(coilLength)) + " mm");
  if (auto t = n.optional("twist_deg")) s.twist = units::degToRad(t->number(Bounds::closed(-kMaxTwistDeg, kMaxTwistDeg, "deg")));
  if (auto p = n.optional("point_sigma_mm")) s.pointSigma = units::mmToM(p->number(Bounds::closed(0, 10, "mm")));
  const JsonNode line = n.child("centerline_mm");
  s.centerline = pointsMm(line, "an array of at least 2 points [x, y, z] in mm, from the catheter tip outward");
  // The deployed coil cannot reach further from the tip than its length
  // (plus 5 % and 1 mm for the fit of the line, and 5 sigma of noise).
  const double reach = 1.05 * s.deployed + units::mmToM(1.0) + 5 * s.pointSigma;
  for (size_t i = 0; i < s.centerline.size(); ++i)
    if ((s.centerline[i] - tip).norm() > reach)
      line.child(std::to_string(i)).fail("this point is " + fmt(units::mToMm((s.centerline[i] - tip).norm())) +
                                         " mm from the catheter tip, but only " + fmt(units::mToMm(s.deployed)) +
                                         " mm of coil is deployed (the line reaches at most " +
                                         fmt(units::mToMm(reach)) + " mm); is it in other units or another frame?");
  if (auto h = n.optional("push_history")) {
    double lastTime = -INFINITY;
    for (const JsonNode& e : h->items(1, SIZE_MAX, "an array of [t_s, deployed_length_mm, twist_deg] samples")) {
      const auto row = e.items(3, 3, "[t_s, deployed_length_mm, twist_deg]");
      validation::PushSample p;
      p.time = row[0].number();
      if (!(p.time > lastTime)) row[0].expected("a time greater than the previous sample's (" + fmt(lastTime) + " s)");
      if (!s.pushHistory.empty() && p.time - s.pushHistory.front().time > kMaxHistorySpanS)
        row[0].expected("a time at most " + fmt(kMaxHistorySpanS) + " s after the first sample (the longest history simulated)");
      lastTime = p.time;
      p.deployed = units::mmToM(row[1].number(Bounds::closed(0, units::mToMm(coilLength), "mm")));
      p.twist = units::degToRad(row[2].number(Bounds::closed(-kMaxTwistDeg, kMaxTwistDeg, "deg")));
      s.pushHistory.push_back(p);
    }
    const JsonNode c = n.child("capture_time_s");
    if (!c.exists()) c.expected("a capture time in s (required with push_history)");
    // Validate simulates from the first sample to the capture: bounded, as every simulated time.
    s.captureTime = c.number(Bounds::closed(s.pushHistory.front().time, s.pushHistory.front().time + kMaxHistorySpanS, "s"));
  }
  return s;
}

Measurement fromDocument(const nlohmann::json& doc, const std::string& file) {
  const JsonNode root(doc, file);
  if (!root.isObject()) root.expected("a coil-measurement/1 object");
  root.child("format").oneOf({"coil-measurement/1"});
  Measurement m;
  m.file = file;
  m.name = root.child("name").string();
  if (auto d = root.optional("description")) m.description = d->string(true);
  readCoil(root.child("coil"), m);

  const JsonNode setup = root.child("setup");
  if (!setup.isObject()) setup.expected("an object with gravity_m_s2 and catheter_tip");
  {
    const auto g = setup.child("gravity_m_s2").vec3(Bounds::closed(-100, 100, "m/s2"));  // 10 g at most
    m.gravity = Vec3(g[0], g[1], g[2]);
  }
  if (auto med = setup.optional("medium")) {
    if (!med->isObject()) med->expected("an object {\"density_g_cm3\", \"viscosity_pa_s\"}");
    m.mediumDensity = units::gcm3ToKgm3(med->child("density_g_cm3").number(Bounds::closed(0, 30, "g/cm3")));
    m.mediumViscosity = med->child("viscosity_pa_s").number(Bounds::closed(0, 1000, "Pa s"));
  }
  const JsonNode tip = setup.child("catheter_tip");
  if (!tip.isObject()) tip.expected("an object {\"position_mm\", \"direction\", \"reference_normal\"}");
  {
    const auto p = tip.child("position_mm").vec3(Bounds::closed(-kMaxCoords, kMaxCoords, "mm"));
    m.tip.position = units::mmToM(1.0) * Vec3(p[0], p[1], p[2]);
  }
  m.tip.direction = unitVec(tip.child("direction"));
  const JsonNode normal = tip.child("reference_normal");
  m.tip.normal = unitVec(normal);
  if (std::abs(m.tip.normal.dot(m.tip.direction)) > 1e-3)
    normal.expected("a unit vector orthogonal to /setup/catheter_tip/direction (|dot| <= 1e-3), got dot " +
                    fmt(m.tip.normal.dot(m.tip.direction)));

  for (const JsonNode& s : root.child("stages").items(1, SIZE_MAX, "an array of at least one stage"))
    m.stages.push_back(readStage(s, m.coil.length, m.tip.position));
  return m;
}

}  // namespace

Measurement parseMeasurement(std::string_view text, const std::string& file) {
  return fromDocument(parseJson(text, file), file);
}

Measurement readMeasurement(const std::string& path) { return fromDocument(readJsonFile(path), path); }

std::string formatMeasurement(const Measurement& m) {
  using nlohmann::ordered_json;
  auto mm = [](const Vec3& v) { return ordered_json::array({units::mToMm(v.x()), units::mToMm(v.y()), units::mToMm(v.z())}); };
  auto round = [](double v, double q) { return std::round(v / q) * q; };
  ordered_json j;
  j["format"] = "coil-measurement/1";
  j["name"] = m.name;
  j["description"] = m.description;
  ordered_json coil;
  coil["length_mm"] = units::mToMm(m.coil.length);
  coil["wire_radius_mm"] = units::mToMm(m.coil.wireRadius);
  coil["mass_g"] = massPerLength(m.coil) * m.coil.length * 1e3;
  ordered_json rest;
  switch (m.coil.rest.type) {
    case RestShapeDef::Type::Straight: rest["type"] = "straight"; break;
    case RestShapeDef::Type::Helix:
      rest["type"] = "helix";
      rest["loop_diameter_mm"] = units::mToMm(m.coil.rest.loopDiameter);
      rest["pitch_mm"] = units::mToMm(m.coil.rest.pitch);
      rest["handedness"] = m.coil.rest.rightHanded ? "right" : "left";
      break;
    case RestShapeDef::Type::Birdcage: throw std::invalid_argument("coil-measurement/1 has no bird-cage rest shape");
    case RestShapeDef::Type::Polyline:
      rest["type"] = "polyline";
      rest["points_mm"] = ordered_json::array();
      for (const Vec3& p : reversed(m.coil.rest.points)) rest["points_mm"].push_back(mm(p));
      rest["twist_deg_per_mm"] = units::radToDeg(m.coil.rest.twistPerLength) * units::kMetresPerMm;
      break;
  }
  coil["rest_shape"] = rest;
  if (m.coil.youngModulus > 0) coil["young_modulus_gpa"] = units::paToGpa(m.coil.youngModulus);
  if (m.givesPoissonRatio) coil["poisson_ratio"] = m.coil.poissonRatio;
  j["coil"] = coil;
  ordered_json setup;
  setup["gravity_m_s2"] = {m.gravity.x(), m.gravity.y(), m.gravity.z()};
  setup["medium"] = {{"density_g_cm3", units::kgm3ToGcm3(m.mediumDensity)}, {"viscosity_pa_s", m.mediumViscosity}};
  setup["catheter_tip"] = {{"position_mm", mm(m.tip.position)},
                           {"direction", {m.tip.direction.x(), m.tip.direction.y(), m.tip.direction.z()}},
                           {"reference_normal", {m.tip.normal.x(), m.tip.normal.y(), m.tip.normal.z()}}};
  j["setup"] = setup;
  j["stages"] = ordered_json::array();
  for (const Stage& s : m.stages) {
    ordered_json st;
    st["name"] = s.name;
    st["deployed_length_mm"] = units::mToMm(s.deployed);
    st["twist_deg"] = units::radToDeg(s.twist);
    if (s.pointSigma > 0) st["point_sigma_mm"] = units::mToMm(s.pointSigma);
    st["centerline_mm"] = ordered_json::array();
    for (const Vec3& p : s.centerline) {
      const Vec3 q = units::mToMm(1.0) * p;
      st["centerline_mm"].push_back({round(q.x(), 1e-5), round(q.y(), 1e-5), round(q.z(), 1e-5)});
    }
    if (s.dynamic()) {
      st["push_history"] = ordered_json::array();
      for (const auto& p : s.pushHistory)
        st["push_history"].push_back({p.time, units::mToMm(p.deployed), units::radToDeg(p.twist)});
      st["capture_time_s"] = s.captureTime;
    }
    j["stages"].push_back(st);
  }
  return formatJson(j);
}

}  // namespace coilsim::io
