#include "app/sac_drawing.h"

#include "ui/contact_overlay.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace coilsim::app {
namespace {

const Colour kNeckColour(0.25f, 0.85f, 1.0f, 0.3f);  // light: protruding coil seen through it keeps its colour
const Colour kWallColour = DrawMesh{}.colour;  // the renderer's default for obstacle meshes

}  // namespace

DrawMesh neckDisc(const planning::Sac& sac) {
  DrawMesh disc;
  disc.name = "neck plane";
  disc.colour = kNeckColour;
  if (!sac.mesh) return disc;
  const planning::Plane& plane = sac.neck;
  const Vec3 n = plane.normal.normalized();
  // Every edge's crossing of the plane (each edge twice at most: harmless).
  std::vector<Vec3> cut;
  const auto& v = sac.mesh->vertices;
  for (const Eigen::Vector3i& t : sac.mesh->triangles)
    for (int k = 0; k < 3; ++k) {
      const Vec3 &a = v[size_t(t[k])], &b = v[size_t(t[(k + 1) % 3])];
      const double da = plane.signedDistance(a), db = plane.signedDistance(b);
      if ((da < 0) == (db < 0) || da == db) continue;
      cut.push_back(a + (da / (da - db)) * (b - a));
    }
  if (cut.size() < 3) return disc;
  const Vec3 c = plane.point - plane.signedDistance(plane.point) * n;
  double nearest = std::numeric_limits<double>::infinity();
  for (const Vec3& p : cut) nearest = std::min(nearest, (p - c).norm());
  const Vec3 u = n.unitOrthogonal(), w = n.cross(u);
  std::vector<std::pair<double, Vec3>> ring;
  Vec3 centre = Vec3::Zero();
  for (const Vec3& p : cut)
    if ((p - c).norm() <= 2.5 * nearest + 1e-12) ring.emplace_back(0.0, p), centre += p;
  if (ring.size() < 3) return disc;
  centre /= double(ring.size());
  for (auto& [angle, p] : ring) angle = std::atan2((p - centre).dot(w), (p - centre).dot(u));
  std::sort(ring.begin(), ring.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  disc.vertices.push_back(centre);
  for (const auto& [angle, p] : ring) disc.vertices.push_back(p);
  const int m = int(ring.size());
  for (int i = 0; i < m; ++i) disc.triangles.emplace_back(0, 1 + i, 1 + (i + 1) % m);
  return disc;
}

bool hasParentVessel(const planning::Sac& sac) {
  if (!sac.mesh) return false;
  const double inside = planning::volumeOnSide(*sac.mesh, sac.neck);
  const double beyond = planning::volumeOnSide(*sac.mesh, planning::Plane{sac.neck.point, -sac.neck.normal});
  return beyond > 0.5 * inside;
}

std::vector<ui::LegendEntry> sacLegend(const planning::Sac& sac) {
  std::vector<ui::LegendEntry> l;
  using M = ui::LegendMatter;
  l.push_back({defaultColour(RodRole::Coil), "coil", M::Coil});
  l.push_back({defaultColour(RodRole::Catheter), "microcatheter", M::Catheter});
  const bool vessel = hasParentVessel(sac);
  // In X-ray the wall is the contrast it holds; the neck plane a line across it.
  l.push_back({kWallColour, vessel ? "sac and parent vessel wall" : "sac wall", M::Vessel});
  l.push_back({kNeckColour, "neck plane (the ostium)", M::VesselOutline});
  // The contact markers (ui/contact_overlay.h): their arrows' lengths are
  // relative, the longest the largest force drawn.
  l.push_back({ui::kWallContactColour, "wall contact, arrow: its force"});
  l.push_back({ui::kCoilContactColour, "coil-coil contact, arrow: its force"});
  if (!vessel) l.push_back({Colour(0, 0, 0, 0), "no parent vessel in this case: its side is beyond the neck plane"});
  return l;
}

}  // namespace coilsim::app
