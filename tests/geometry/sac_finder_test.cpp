// The sac finder on phantoms of known geometry: the phantom generator places
// the sac and the neck plane by construction (its sidecar), independently of
// how the finder looks for them.
#include "geometry/sac_finder.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "geometry/marching_tets.h"
#include "geometry/phantom.h"
#include "geometry/sac_morphology.h"

namespace coilsim::geometry {
namespace {

struct Catalogued {
  const char* name;
  VesselType vessel;
  double sac, neck, resolution;
  int lobes;
};

// The phantoms of assets/meshes (make-catalogue.sh), rebuilt in memory.
const Catalogued kCatalogue[] = {
    {"sidewall_7mm", VesselType::Sidewall, 7, 3.5, 0.6, 1},
    {"sidewall_7mm_wide_neck", VesselType::Sidewall, 7, 5.5, 0.6, 1},
    {"sidewall_5mm", VesselType::Sidewall, 5, 2.5, 0.55, 1},
    {"sidewall_10mm", VesselType::Sidewall, 10, 4, 0.65, 1},
    {"curved_7mm", VesselType::Curved, 7, 3.5, 0.65, 1},
    {"bifurcation_7mm", VesselType::Bifurcation, 7, 4, 0.6, 1},
    {"multilobe_7mm", VesselType::Sidewall, 7, 3.5, 0.55, 3},
};

class CataloguePhantom : public testing::TestWithParam<Catalogued> {};

// Tolerances: the neck plane within 3 degrees and 0.5 mm (about one sampling
// step of the phantoms' grid) of the sidecar's; the sac volume measured with
// the found plane within 10 % of the volume with the sidecar's plane (a
// 0.5 mm shift of a 3.5 mm neck moves ~5 mm^3 of ~170).
TEST_P(CataloguePhantom, FindsTheSidecarsSacAndNeck) {
  const Catalogued& c = GetParam();
  PhantomSpec spec;
  spec.vessel = c.vessel, spec.sacDiameter = c.sac, spec.neckWidth = c.neck, spec.resolution = c.resolution;
  spec.lobes = c.lobes;
  const Phantom p = makePhantom(spec);
  const MeshQuery query(p.mesh);
  const SacFinding s = findSac(query);
  ASSERT_TRUE(s.found) << s.problem;
  const double angle = std::acos(std::clamp(s.neck.normal.dot(p.info.neck.normal), -1.0, 1.0)) * 180 / M_PI;
  const double shift = p.info.neck.side(s.neck.point);
  const SacMorphology found = measureSac(p.mesh, s.neck, s.centre, 2 * s.vesselRadius);
  const SacMorphology truth = measureSac(p.mesh, p.info.neck, p.info.sacCentre, 2 * p.info.vesselRadius);
  std::printf("[ measured ] %s: neck tilt %.2f deg, shift %+.3f mm; volume %.1f vs %.1f mm^3; sac centre off %.2f mm; "
              "vessel radius %.2f (true %.2f)\n",
              c.name, angle, shift, found.volume, truth.volume, (s.centre - p.info.sacCentre).norm(), s.vesselRadius,
              p.info.vesselRadius);
  EXPECT_LT(angle, 3.0);
  EXPECT_LT(std::abs(shift), 0.5);
  EXPECT_NEAR(found.volume, truth.volume, 0.10 * truth.volume);
  EXPECT_NEAR(s.vesselRadius, p.info.vesselRadius, 0.25 * p.info.vesselRadius);
  EXPECT_GT(p.info.neck.side(s.centre), 0);  // the sac centre is on the dome side
}

INSTANTIATE_TEST_SUITE_P(Catalogue, CataloguePhantom, testing::ValuesIn(kCatalogue),
                         [](const testing::TestParamInfo<Catalogued>& i) { return std::string(i.param.name); });

// A straight vessel with two sacs side by side: the finder names both and
// finds nothing; given a point in one, it finds that one.
TEST(SacFinder, TwoSacsAskForAPoint) {
  const Vec3 left(-6, 0, 4.5), right(6, 0, 4.5);
  const Field field = [&](const Vec3& p) {
    const double vessel = std::hypot(p.y(), p.z()) - 2;
    const double tube = std::max(vessel, std::abs(p.x()) - 14);
    return std::min({tube, (p - left).norm() - 3.2, (p - right).norm() - 3.2});
  };
  const TriangleMesh mesh = polygonise(field, Vec3(-15, -4, -3), Vec3(15, 4, 9), 0.5);
  const MeshQuery query(mesh);
  const SacFinding s = findSac(query);
  EXPECT_FALSE(s.found);
  ASSERT_EQ(s.candidates.size(), 2u) << s.problem;
  EXPECT_NE(s.problem.find("2 candidate sacs"), std::string::npos) << s.problem;

  SacFinderOptions o;
  o.sacPoint = Vec3(5, 0.5, 5);
  const SacFinding chosen = findSac(query, o);
  ASSERT_TRUE(chosen.found) << chosen.problem;
  EXPECT_LT((chosen.centre - right).norm(), 0.3);
  EXPECT_GT(chosen.neck.normal.z(), 0.99);  // the neck faces up into the sac
}

// A closed ball has no vessel and no neck: nothing is found, and it says why.
TEST(SacFinder, ABallWithoutVesselHasNoSac) {
  const Field ball = [](const Vec3& p) { return p.norm() - 4; };
  const TriangleMesh mesh = polygonise(ball, Vec3::Constant(-5), Vec3::Constant(5), 0.8);
  const MeshQuery query(mesh);
  const SacFinding s = findSac(query);
  EXPECT_FALSE(s.found);
  EXPECT_FALSE(s.problem.empty());
  SacFinderOptions o;
  o.sacPoint = Vec3(1, 0, 0);
  const SacFinding pointed = findSac(query, o);
  EXPECT_FALSE(pointed.found);
  EXPECT_NE(pointed.problem.find("no neck"), std::string::npos) << pointed.problem;
}

// A sac point outside the surface is refused, naming the point.
TEST(SacFinder, ASacPointOutsideIsRefused) {
  const Field ball = [](const Vec3& p) { return p.norm() - 4; };
  const MeshQuery query(polygonise(ball, Vec3::Constant(-5), Vec3::Constant(5), 0.8));
  SacFinderOptions o;
  o.sacPoint = Vec3(9, 0, 0);
  const SacFinding s = findSac(query, o);
  EXPECT_FALSE(s.found);
  EXPECT_NE(s.problem.find("not inside"), std::string::npos) << s.problem;
}

// Inscribed balls of a straight tube lie on its axis with its radius: within
// the method's 5 % slack (medial_balls.cpp) and the faceting, 0.15 mm of 2.
TEST(MedialBalls, TubeCentreLineAndRadius) {
  const Field tube = [](const Vec3& p) { return std::max(std::hypot(p.y(), p.z()) - 2, std::abs(p.x()) - 10); };
  const MeshQuery query(polygonise(tube, Vec3(-11, -3, -3), Vec3(11, 3, 3), 0.25));
  int onAxis = 0, mid = 0;
  for (const Ball& b : medialBalls(query)) {
    if (std::abs(b.centre.x()) > 7) continue;  // away from the flat ends
    ++mid;
    if (std::hypot(b.centre.y(), b.centre.z()) < 0.15 && std::abs(b.radius - 2) < 0.15) ++onAxis;
  }
  ASSERT_GT(mid, 100);
  EXPECT_GT(onAxis, 0.9 * mid);
}

}  // namespace
}  // namespace coilsim::geometry
