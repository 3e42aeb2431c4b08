#pragma once
// Coil catalogue files ("coilsim-coil/1", assets/coils/*.json, docs/coils.md):
// one detachable coil as a clinician orders it (family, shape, loop
// diameter, length) and as it is built (wire wound into a close-coiled
// primary spring). The wound spring is far softer than a solid wire of the
// same outer diameter; its effective bending and torsional stiffness follow
// from the winding (helicalSpringBending / helicalSpringTorsion below) and the
// file's stored values must agree with them. Errors are InputErrors naming
// the file, the JSON path and what was expected.
#include <string>
#include <string_view>
#include <vector>

#include "io/json_reader.h"
#include "io/scene.h"

namespace coilsim::io {

inline constexpr const char* kCoilFormat = "coilsim-coil/1";

enum class CoilFamily { Framing, Filling, Finishing };
enum class CoilShape { Complex3d, Birdcage, Helical, Spiral2d };

struct CoilSpec {
  std::string file;  // where it was read from, for messages
  std::string name, description;
  CoilFamily family = CoilFamily::Framing;
  CoilShape shape = CoilShape::Helical;
  double loopDiameterMm = 0;     // secondary (shape) diameter
  double lengthMm = 0;           // coil length
  double primaryDiameterMm = 0;  // outer diameter of the wound primary coil
  double wireDiameterMm = 0;     // filar (wire) diameter d
  double wireYoungGpa = 0, wirePoisson = 0, wireDensityGcm3 = 0;
  bool stretchResistant = false;
  double bendingStiffnessNmm2 = 0;  // as stored; equals helicalSpringBending within 1 %
  double torsionStiffnessNmm2 = 0;  // as stored; equals helicalSpringTorsion within 1 %
  std::vector<std::string> sources;
};

// Effective flexural rigidity (N mm^2) of a close-coiled helical spring of
// wire diameter d, mean coil diameter D = primary - d, pitch p = d, wire
// modulus E (GPa) and Poisson ratio nu: B = 2 p E I / (pi D (2 + nu)),
// I = pi d^4 / 64, i.e. B = E d^5 / (32 D (2 + nu)) (Timoshenko & Gere,
// Theory of Elastic Stability, 2nd ed. 1961, sec. 2.19, eq. 2-63; Wahl,
// Mechanical Springs, 1963). Derivation in docs/coils.md.
double helicalSpringBending(double wireDiameterMm, double primaryDiameterMm, double youngGpa, double poisson);
// Effective torsional rigidity (N mm^2) about the spring axis: the twisting
// moment bends the wire, C = p E I / (pi D) = E d^5 / (64 D) (the torsion
// spring rate E d^4 / (64 D n) of Wahl times the length n p).
double helicalSpringTorsion(double wireDiameterMm, double primaryDiameterMm, double youngGpa);
// Metal cross-section per unit coil length (mm^2): wire area pi d^2 / 4
// times wire length per coil length pi D / p, i.e. pi^2 d D / 4.
double woundMetalArea(double wireDiameterMm, double primaryDiameterMm);

// Reads and checks one coil document. Throws InputError (file, JSON path, expectation).
CoilSpec parseCoil(const nlohmann::json& document, const std::string& file);
// readJsonFile + parseCoil.
CoilSpec loadCoil(const std::string& path);
CoilSpec coilFromText(std::string_view text, const std::string& label);

// Every *.json in `directory`, sorted by name; throws InputError naming the
// directory if it cannot be listed or a file is bad, or if two coils share a name.
std::vector<CoilSpec> loadCatalogue(const std::string& directory);
// The coil called `name` in `catalogue`; throws InputError listing the names if absent.
const CoilSpec& findCoil(const std::vector<CoilSpec>& catalogue, const std::string& name);

std::string_view familyName(CoilFamily f);
std::string_view shapeName(CoilShape s);

// Puts the coil into a scene's deployment: length, beams (about `spacingMm`
// apart, at least 8), rest shape, wire material and the wound section
// (area = woundMetalArea so the mass per length is right, inertia and
// torsion constants giving the effective rigidities with the wire's E and
// G, outer radius = primary radius for contact). Keeps the catheter.
void applyCoil(const CoilSpec& coil, double spacingMm, DeploymentSpec& deployment);

}  // namespace coilsim::io
