// Phantoms are closed, outward, one piece; their sac sits where the sidecar
// says, with the volume of the ideal shape above the neck plane.
#include "geometry/phantom.h"

#include <gtest/gtest.h>

#include <stdexcept>

#include "geometry/mesh_query.h"
#include "geometry/mesh_report.h"
#include "support/tolerance.h"

namespace coilsim::geometry {
namespace {

PhantomSpec spec(VesselType type, double sac, double ratio, int lobes = 1) {
  PhantomSpec s;
  s.vessel = type;
  s.sacDiameter = sac;
  s.domeToNeck = ratio;
  s.lobes = lobes;
  return s;
}

void expectSound(const Phantom& p) {
  const MeshReport r = analyseMesh(p.mesh);
  EXPECT_TRUE(r.usable()) << p.info.type << ": " << (describeProblems(r).empty() ? "" : describeProblems(r).front());
  EXPECT_EQ(r.components, 1u) << p.info.type;
  EXPECT_EQ(long(r.vertices) - long(r.edges) + long(r.triangles), 2) << p.info.type << ": sphere-like";
  std::printf("[ measured ] %s %.0f mm, neck %.2f mm: %zu triangles, volume %.1f mm^3\n", p.info.type.c_str(),
              p.info.spec.sacDiameter, p.info.neckWidth, r.triangles, r.volume);
}

TEST(Phantom, EveryVesselTypeIsOneClosedOutwardSurface) {
  for (VesselType t : {VesselType::Sidewall, VesselType::Curved, VesselType::Bifurcation}) {
    const Phantom p = makePhantom(spec(t, 7, 2));
    expectSound(p);
    const MeshQuery q(p.mesh);
    // The sac centre is inside; the dome top just inside, just beyond it outside.
    EXPECT_TRUE(q.inside(p.info.sacCentre));
    const Vec3 top = p.info.sacCentre + p.info.sacRadii.z() * p.info.neck.normal;
    EXPECT_TRUE(q.inside(top - 0.2 * p.info.neck.normal));
    EXPECT_FALSE(q.inside(top + 0.2 * p.info.neck.normal));
    // The neck is open: in the neck plane, inside within the neck's radius,
    // outside beyond it (sideways, where the vessel falls away).
    const double rn = 0.5 * p.info.neckWidth;
    EXPECT_TRUE(q.inside(p.info.neck.point));
    EXPECT_TRUE(q.inside(p.info.neck.point + (rn - 0.3) * p.info.axisV));
    EXPECT_FALSE(q.inside(p.info.neck.point + (rn + p.info.spec.blend + 0.3) * p.info.axisV));
  }
}

TEST(Phantom, SacVolumeAboveTheNeckPlaneIsTheIdealCap) {
  // Fillets of radius `blend` at the neck add a sliver; the polyhedron loses O(h^2).
  for (VesselType t : {VesselType::Sidewall, VesselType::Curved, VesselType::Bifurcation})
    for (double ratio : {1.2, 2.0}) {
      const Phantom p = makePhantom(spec(t, 7, ratio));
      const double a = 3.5, d = (p.info.sacCentre - p.info.neck.point).norm();
      // Reference from the cap formula alone: ball minus the cap below the plane.
      const double h = a - d;
      const double ideal = 4.0 / 3.0 * M_PI * a * a * a - M_PI * h * h * (3 * a - h) / 3.0;
      EXPECT_TRUE(test::nearRel(std::string(p.info.type) + " sac above neck, D/N " + std::to_string(ratio),
                                volumeAbovePlane(p.mesh, p.info.neck), ideal, {0.02, "fillets and h = 0.3 mm"}));
      EXPECT_TRUE(test::nearRel("recorded ideal volume", p.info.idealSacVolume, ideal, {1e-12, "same formula"}));
    }
}

TEST(Phantom, NeckWidthSetsTheCrossSectionAtTheNeckPlane) {
  PhantomSpec s = spec(VesselType::Sidewall, 10, 2.5);
  s.resolution = 0.2;
  const Phantom p = makePhantom(s);
  // Lift the plane past the fillet; the sphere's section there is known exactly.
  const double lift = 0.6, a = 5, d = (p.info.sacCentre - p.info.neck.point).norm() - lift;
  const Plane above{p.info.neck.point + lift * p.info.neck.normal, p.info.neck.normal};
  EXPECT_TRUE(test::nearRel("section 0.6 mm above the neck", sectionArea(p.mesh, above), M_PI * (a * a - d * d),
                            {0.02, "h = 0.2 mm"}));
  EXPECT_NEAR(p.info.neckWidth, 4.0, 1e-12);
}

TEST(Phantom, EllipsoidAndMultilobeSacs) {
  PhantomSpec s = spec(VesselType::Sidewall, 6, 2);
  s.sacHeight = 9;
  const Phantom tall = makePhantom(s);
  expectSound(tall);
  EXPECT_EQ(tall.info.sacRadii, Vec3(3, 3, 4.5));
  const MeshQuery q(tall.mesh);
  const Vec3 top = tall.info.sacCentre + 4.5 * tall.info.neck.normal;
  EXPECT_TRUE(q.inside(top - 0.2 * tall.info.neck.normal));
  EXPECT_FALSE(q.inside(top + 0.2 * tall.info.neck.normal));

  const Phantom lobed = makePhantom(spec(VesselType::Sidewall, 7, 2, 3));
  expectSound(lobed);
  ASSERT_EQ(lobed.info.lobes.size(), 3u);
  const MeshQuery ql(lobed.mesh);
  for (const Lobe& l : lobed.info.lobes) EXPECT_TRUE(ql.inside(l.centre));
  // Daughter lobes add volume to the single sac of the same size.
  EXPECT_GT(volumeAbovePlane(lobed.mesh, lobed.info.neck), 1.05 * lobed.info.idealSacVolume);
}

TEST(Phantom, RefusesImpossibleParameters) {
  PhantomSpec s = spec(VesselType::Sidewall, 7, 2);
  s.neckWidth = 8;  // wider than the sac
  EXPECT_THROW(makePhantom(s), std::invalid_argument);
  EXPECT_THROW(makePhantom(spec(VesselType::Sidewall, 0.5, 2)), std::invalid_argument);
  EXPECT_THROW(makePhantom(spec(VesselType::Sidewall, 7, 0.5)), std::invalid_argument);
  EXPECT_THROW(makePhantom(spec(VesselType::Sidewall, 7, 2, 9)), std::invalid_argument);
  s = spec(VesselType::Sidewall, 7, 2);
  s.resolution = std::nan("");
  EXPECT_THROW(makePhantom(s), std::invalid_argument);
  VesselType t;
  EXPECT_TRUE(parseVesselType("curved", t));
  EXPECT_EQ(t, VesselType::Curved);
  EXPECT_FALSE(parseVesselType("fusiform", t));
}

}  // namespace
}  // namespace coilsim::geometry
