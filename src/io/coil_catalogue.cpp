// Coil catalogue files -> CoilSpec; the wound-spring rigidities; a coil put
// into a scene's deployment block.
#include "io/coil_catalogue.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <set>

#include "io/units.h"

namespace coilsim::io {
namespace {

constexpr std::string_view kFamilies[] = {"framing", "filling", "finishing"};
constexpr std::string_view kShapes[] = {"complex_3d", "birdcage", "helical", "spiral_2d"};

std::string fmt(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

// A stored rigidity must be the one the winding gives: a hand-edited value
// that disagrees would silently change the coil's mechanics.
void checkDerived(const JsonNode& n, double stored, double derived, std::string_view formula) {
  if (std::abs(stored - derived) > 0.01 * derived)
    n.fail("is " + fmt(stored) + " N mm^2, but the winding gives " + fmt(derived) + " N mm^2 (" + std::string(formula) +
           ", docs/coils.md); fix the winding or the value");
}

// A planar Archimedean spiral from radius R inwards to R / 4, as points in mm.
std::vector<Vec3> spiralPoints(double loopDiameterMm, double lengthMm) {
  const double R = 0.5 * loopDiameterMm, rMin = 0.25 * R;
  const int samples = 4000;
  // Length of the spiral r(theta) = R - a theta is close to the mean circumference times turns.
  const double turns = lengthMm / (M_PI * (R + rMin));
  const double a = (R - rMin) / (2 * M_PI * turns);
  std::vector<Vec3> pts;
  pts.reserve(samples + 1);
  double theta = 0;
  const double ds = lengthMm / samples;
  pts.push_back(Vec3::Zero());
  for (int i = 1; i <= samples; ++i) {
    const double r = R - a * theta;
    theta += ds / std::sqrt(r * r + a * a);
    const double rn = R - a * theta;
    pts.push_back(Vec3(rn * std::cos(theta) - R, rn * std::sin(theta), 0));
  }
  return pts;
}

}  // namespace

double helicalSpringBending(double d, double primary, double youngGpa, double poisson) {
  const double D = primary - d, E = youngGpa * 1e3;  // N/mm^2
  return E * std::pow(d, 5) / (32.0 * D * (2.0 + poisson));
}

double helicalSpringTorsion(double d, double primary, double youngGpa) {
  const double D = primary - d, E = youngGpa * 1e3;
  return E * std::pow(d, 5) / (64.0 * D);
}

double woundMetalArea(double d, double primary) { return M_PI * M_PI * d * (primary - d) / 4.0; }

std::string_view familyName(CoilFamily f) { return kFamilies[int(f)]; }
std::string_view shapeName(CoilShape s) { return kShapes[int(s)]; }

CoilSpec parseCoil(const nlohmann::json& document, const std::string& file) {
  const JsonNode root(document, file);
  if (!root.isObject()) root.expected("a coil object {\"format\": \"coilsim-coil/1\", ...}");
  root.allowKeys({"format", "name", "description", "family", "shape", "loop_diameter_mm", "length_mm",
                  "primary_diameter_mm", "wire", "stretch_resistant", "bending_stiffness_n_mm2",
                  "torsion_stiffness_n_mm2", "sources"});
  root.child("format").oneOf({kCoilFormat});
  CoilSpec c;
  c.file = file;
  c.name = root.child("name").string();
  if (auto d = root.optional("description")) c.description = d->string(true);
  const std::string family = root.child("family").oneOf({"framing", "filling", "finishing"});
  c.family = CoilFamily(std::find(std::begin(kFamilies), std::end(kFamilies), family) - std::begin(kFamilies));
  const std::string shape = root.child("shape").oneOf({"complex_3d", "birdcage", "helical", "spiral_2d"});
  c.shape = CoilShape(std::find(std::begin(kShapes), std::end(kShapes), shape) - std::begin(kShapes));
  // Clinical ranges: loops 1-25 mm, lengths 5 mm - 60 cm, primary 0.2-0.6 mm (0.008"-0.024").
  c.loopDiameterMm = root.child("loop_diameter_mm").number(Bounds::closed(1, 25, "mm"));
  c.lengthMm = root.child("length_mm").number(Bounds::closed(5, 600, "mm"));
  const JsonNode primary = root.child("primary_diameter_mm");
  c.primaryDiameterMm = primary.number(Bounds::closed(0.15, 0.6, "mm"));
  const JsonNode wire = root.child("wire");
  if (!wire.isObject()) wire.expected("an object {\"diameter_mm\", \"young_modulus_gpa\", \"poisson_ratio\", \"density_g_cm3\", \"material\"}");
  wire.allowKeys({"material", "diameter_mm", "young_modulus_gpa", "poisson_ratio", "density_g_cm3"});
  if (auto m = wire.optional("material")) m->string();
  const JsonNode wd = wire.child("diameter_mm");
  c.wireDiameterMm = wd.number(Bounds::closed(0.01, 0.2, "mm"));
  // A spring needs room inside: the mean diameter D = primary - d must exceed d.
  if (!(c.primaryDiameterMm > 2 * c.wireDiameterMm))
    wd.fail("wire diameter " + fmt(c.wireDiameterMm) + " mm leaves no lumen in a primary coil of " +
            fmt(c.primaryDiameterMm) + " mm (needs primary_diameter_mm > 2 diameter_mm)");
  // Wires from polymers (about 1 GPa, 1 g/cm3) to tungsten (411 GPa, 19.3 g/cm3) and platinum (21.45 g/cm3).
  c.wireYoungGpa = wire.child("young_modulus_gpa").number(Bounds::closed(0.1, 1000, "GPa"));
  c.wirePoisson = wire.child("poisson_ratio").number(Bounds{0, 0.5, false, false, {}});
  c.wireDensityGcm3 = wire.child("density_g_cm3").number(Bounds::closed(0.5, 25, "g/cm3"));
  if (c.loopDiameterMm < 4 * c.primaryDiameterMm)
    root.child("loop_diameter_mm").fail("a loop of " + fmt(c.loopDiameterMm) + " mm is too tight for a primary coil of " +
                                        fmt(c.primaryDiameterMm) + " mm (needs at least 4 primary diameters)");
  c.stretchResistant = root.child("stretch_resistant").boolean();
  const JsonNode b = root.child("bending_stiffness_n_mm2");
  c.bendingStiffnessNmm2 = b.number(Bounds::positive());
  checkDerived(b, c.bendingStiffnessNmm2,
               helicalSpringBending(c.wireDiameterMm, c.primaryDiameterMm, c.wireYoungGpa, c.wirePoisson),
               "E d^5 / (32 D (2 + nu))");
  const JsonNode t = root.child("torsion_stiffness_n_mm2");
  c.torsionStiffnessNmm2 = t.number(Bounds::positive());
  checkDerived(t, c.torsionStiffnessNmm2, helicalSpringTorsion(c.wireDiameterMm, c.primaryDiameterMm, c.wireYoungGpa),
               "E d^5 / (64 D)");
  if (auto s = root.optional("sources"))
    for (const JsonNode& item : s->items(0, 50, "an array of source strings")) c.sources.push_back(item.string());
  return c;
}

CoilSpec loadCoil(const std::string& path) { return parseCoil(readJsonFile(path), path); }

CoilSpec coilFromText(std::string_view text, const std::string& label) { return parseCoil(parseJson(text, label), label); }

std::vector<CoilSpec> loadCatalogue(const std::string& directory) {
  namespace fs = std::filesystem;
  std::error_code ec;
  std::vector<std::string> paths;
  for (fs::directory_iterator it(directory, ec), end; !ec && it != end; it.increment(ec))
    if (it->path().extension() == ".json") paths.push_back(it->path().string());
  if (ec) throw InputError(directory + ": cannot list the coil catalogue: " + ec.message());
  if (paths.empty()) throw InputError(directory + ": no coil files (*.json) in the catalogue directory");
  std::sort(paths.begin(), paths.end());
  std::vector<CoilSpec> coils;
  std::set<std::string> names;
  for (const std::string& p : paths) {
    coils.push_back(loadCoil(p));
    if (!names.insert(coils.back().name).second)
      throw InputError(p + ": /name: \"" + coils.back().name + "\" is already the name of another coil in " + directory);
  }
  return coils;
}

const CoilSpec& findCoil(const std::vector<CoilSpec>& catalogue, const std::string& name) {
  for (const CoilSpec& c : catalogue)
    if (c.name == name) return c;
  std::string list;
  for (const CoilSpec& c : catalogue) list += (list.empty() ? "" : ", ") + c.name;
  throw InputError("no coil called \"" + name + "\" in the catalogue; it has: " + list);
}

void applyCoil(const CoilSpec& coil, double spacingMm, DeploymentSpec& dep) {
  dep.coilName = coil.name;
  dep.lengthMm = coil.lengthMm;
  dep.beams = std::max(8, int(std::ceil(coil.lengthMm / spacingMm)));
  RestShapeSpec rest;
  switch (coil.shape) {
    case CoilShape::Helical:
      // Secondary loops wound side by side: the pitch is one primary diameter.
      rest.type = RestShapeSpec::Type::Helix;
      rest.loopDiameterMm = coil.loopDiameterMm;
      rest.pitchMm = coil.primaryDiameterMm;
      break;
    case CoilShape::Complex3d:
    case CoilShape::Birdcage:
      // Loops on a sphere of the loop diameter; a complex coil turns its
      // loop planes further than a bird-cage one, spreading over the sphere faster.
      rest.type = RestShapeSpec::Type::Birdcage;
      rest.sphereDiameterMm = coil.loopDiameterMm;
      rest.planeTurnPerLoopDeg = coil.shape == CoilShape::Complex3d ? 60.0 : 36.0;
      break;
    case CoilShape::Spiral2d:
      rest.type = RestShapeSpec::Type::Polyline;
      rest.pointsMm = spiralPoints(coil.loopDiameterMm, coil.lengthMm);
      rest.frames = FrameRule::Frenet;
      break;
  }
  dep.rest = rest;
  dep.material.youngModulusGpa = coil.wireYoungGpa;
  dep.material.poissonRatio = coil.wirePoisson;
  dep.material.densityGcm3 = coil.wireDensityGcm3;
  const double E = coil.wireYoungGpa * 1e3, G = E / (2 * (1 + coil.wirePoisson));  // N/mm^2
  dep.section.circular = false;
  dep.section.areaMm2 = woundMetalArea(coil.wireDiameterMm, coil.primaryDiameterMm);
  dep.section.inertiaMm4 = coil.bendingStiffnessNmm2 / E;
  dep.section.torsionMm4 = coil.torsionStiffnessNmm2 / G;
  dep.section.shearFactor = 0;  // slender spring: Euler-Bernoulli
  dep.section.outerRadiusMm = 0.5 * coil.primaryDiameterMm;
}

}  // namespace coilsim::io
