#pragma once
// Parametric saccular aneurysm phantoms: a sac (sphere, ellipsoid or several
// lobes) on a parent vessel (straight sidewall, curved, or a bifurcation),
// one closed, 2-manifold, outward surface. Built as an implicit solid (smooth
// union of vessel tubes and sac) polygonised by marching tetrahedra.
// Lengths in millimetres: phantoms are written to files as they are made.
#include <string>
#include <vector>

#include "geometry/volume.h"
#include "physics/triangle_mesh.h"

namespace coilsim::geometry {

enum class VesselType { Sidewall, Curved, Bifurcation };

struct PhantomSpec {
  VesselType vessel = VesselType::Sidewall;
  double sacDiameter = 7;      // mm, across the dome axis
  double sacHeight = 0;        // mm, along the dome axis; 0: a sphere (= sacDiameter)
  double neckWidth = 0;        // mm; 0: sacDiameter / domeToNeck
  double domeToNeck = 2;       // sac diameter / neck width, when neckWidth is 0
  int lobes = 1;               // 1: one sac; more: daughter lobes on the dome
  double vesselDiameter = 4;   // mm, parent vessel (daughters of a bifurcation: 0.8 of it)
  double resolution = 0.3;     // mm, sampling grid spacing
  double blend = 0.5;          // mm, fillet radius of the smooth unions
};

struct Lobe {
  Vec3 centre = Vec3::Zero();
  Vec3 radii = Vec3::Zero();   // semi-axes along (axisU, axisV, dome axis)
};

// Where the sac is: what planning needs to measure it (sidecar JSON).
struct PhantomInfo {
  std::string type;                 // "sidewall", "curved", "bifurcation"
  PhantomSpec spec;
  Vec3 sacCentre = Vec3::Zero();    // centre of the main lobe
  Vec3 sacRadii = Vec3::Zero();     // its semi-axes (a, a, c)
  Vec3 axisU = Vec3::UnitX(), axisV = Vec3::UnitY();  // lateral axes of the sac
  std::vector<Lobe> lobes;          // main lobe first
  Plane neck;                       // neck plane, normal toward the dome
  double neckWidth = 0;             // mm, diameter where the main lobe crosses the neck plane
  double vesselRadius = 0;          // mm, parent vessel
  // The ideal main lobe's volume above the neck plane (ellipsoid cap
  // formula, no fillets): a reference for a single-lobe phantom.
  double idealSacVolume = 0;        // mm^3
};

struct Phantom {
  TriangleMesh mesh;  // mm
  PhantomInfo info;
};

// Builds the phantom. Throws std::invalid_argument naming the parameter and
// its allowed range when one is out of range (e.g. a neck wider than the sac).
Phantom makePhantom(const PhantomSpec& spec);

// "sidewall" / "curved" / "bifurcation"; parse returns false on other names.
const char* vesselTypeName(VesselType type);
bool parseVesselType(const std::string& name, VesselType& out);

}  // namespace coilsim::geometry
