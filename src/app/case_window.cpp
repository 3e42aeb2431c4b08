#include "app/case_window.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <filesystem>

#include "geometry/ray_pick.h"
#include "geometry/sac_morphology.h"
#include "io/units.h"

namespace coilsim::app {
namespace {

Vec3 toM(const Vec3& mm) { return mm * units::kMetresPerMm; }
Vec3 toMm(const Vec3& m) { return m / units::kMetresPerMm; }

std::string format(const char* f, double a, double b = 0, double c = 0) {
  char buf[96];
  std::snprintf(buf, sizeof buf, f, a, b, c);
  return buf;
}

// The surface split into the vessel and the sac piece (one mesh each, so the sac shows in its own colour).
void addSurface(const planning::CaseEditor& e, DrawData& d) {
  const TriangleMesh& s = e.surface();
  const std::vector<char> piece = geometry::sacPiece(s, e.neck(), e.sacCentre());
  DrawMesh vessel, sac;
  vessel.name = "vessel";
  sac.name = "sac";
  vessel.colour = Colour(0.62f, 0.66f, 0.72f, 0.28f);
  sac.colour = Colour(1.0f, 0.55f, 0.15f, 0.5f);
  for (const Vec3& v : s.vertices) vessel.vertices.push_back(toM(v));
  sac.vertices = vessel.vertices;
  for (size_t t = 0; t < s.triangles.size(); ++t) (piece[t] ? sac : vessel).triangles.push_back(s.triangles[t]);
  d.meshes.push_back(std::move(vessel));
  d.meshes.push_back(std::move(sac));
}

// The neck plane as a disc a little wider than the ostium (the renderer draws meshes from both sides), and its normal.
void addNeck(const planning::CaseEditor& e, DrawData& d) {
  const geometry::SacMorphology& m = e.morphology();
  const Vec3 n = e.neck().normal, c = m.neckCentre;
  const double r = 0.65 * std::max(m.neckWidth, 1.0);
  const Vec3 u = n.unitOrthogonal(), v = n.cross(u);
  DrawMesh disc;
  disc.name = "neck plane";
  disc.colour = Colour(0.2f, 0.85f, 0.95f, 0.45f);
  disc.vertices.push_back(toM(c));
  const int sides = 48;
  for (int k = 0; k < sides; ++k) {
    const double a = 2 * M_PI * k / sides;
    disc.vertices.push_back(toM(c + r * (std::cos(a) * u + std::sin(a) * v)));
  }
  for (int k = 0; k < sides; ++k) {
    const int a = 1 + k, b = 1 + (k + 1) % sides;
    disc.triangles.emplace_back(0, a, b);
  }
  d.meshes.push_back(std::move(disc));
  DrawPoint normal;
  normal.position = toM(c);
  normal.vector = toM(std::max(2.0, 0.5 * m.domeHeight) * n);
  normal.colour = Colour(0.2f, 0.85f, 0.95f, 1.0f);
  d.points.push_back(normal);
}

// The catheter's last 3 mm ending at the tip, and the direction it points.
void addTip(const planning::CaseEditor& e, DrawData& d) {
  const planning::Catheter& c = e.catheter();
  DrawTube tube;
  tube.name = "catheter";
  tube.role = RodRole::Catheter;
  tube.radius = units::mmToM(0.3);
  tube.centre = {toM(c.tip - 3.0 * c.direction), toM(c.tip)};
  tube.colours.assign(2, Colour(0.75f, 0.75f, 0.8f, 1.0f));
  d.tubes.push_back(std::move(tube));
  DrawPoint tip;
  tip.position = toM(c.tip);
  tip.vector = toM(2.0 * c.direction);
  tip.colour = Colour(1.0f, 0.9f, 0.1f, 1.0f);
  d.points.push_back(tip);
}

}  // namespace

ui::CaseEditorView caseEditorView(const planning::CaseEditor& e) {
  ui::CaseEditorView v;
  addSurface(e, v.scene);
  addNeck(e, v.scene);
  addTip(e, v.scene);
  v.neckNormal = e.neck().normal;
  v.tip = toM(e.catheter().tip);
  v.unsaved = e.edited();
  const geometry::SacMorphology& m = e.morphology();
  const Vec3 p = e.neck().point, n = e.neck().normal, t = e.catheter().tip, dir = e.catheter().direction;
  v.rows = {
      {"sac volume", format("%.1f mm^3", m.volume)},
      {"neck width", format("%.2f mm", m.neckWidth)},
      {"neck area", format("%.1f mm^2", m.neckArea)},
      {"dome height", format("%.2f mm", m.domeHeight)},
      {"max diameter", format("%.2f mm", m.maxDiameter)},
      {"mean diameter", format("%.2f mm", m.meanDiameter)},
      {"width x depth", format("%.2f x %.2f mm", m.width, m.depth)},
      {"aspect ratio", format("%.2f", m.aspectRatio)},
      {"dome-to-neck", format("%.2f", m.domeToNeck)},
      {"size ratio", m.sizeRatio > 0 ? format("%.2f", m.sizeRatio) : "unknown (no parent vessel diameter)"},
      {"neck point", format("%.2f, %.2f, %.2f mm", p.x(), p.y(), p.z())},
      {"neck normal", format("%.3f, %.3f, %.3f", n.x(), n.y(), n.z())},
      {"catheter tip", format("%.2f, %.2f, %.2f mm", t.x(), t.y(), t.z())},
      {"tip direction", format("%.3f, %.3f, %.3f", dir.x(), dir.y(), dir.z())},
  };
  return v;
}

ui::CaseEditorHooks caseEditorHooks(planning::CaseEditor& e, const std::string& caseFile, const std::string& savePath) {
  ui::CaseEditorHooks h;
  h.title = caseFile;
  h.savePath = savePath;
  std::error_code ec;
  h.saveOverwrites = savePath == caseFile || std::filesystem::equivalent(savePath, caseFile, ec);
  h.view = [&e] { return caseEditorView(e); };
  const auto why = [&e](bool ok) { return ok ? std::string() : e.refusal(); };
  h.moveNeck = [&e, why](double mm) { return why(e.moveNeck(mm)); };
  h.tiltNeck = [&e, why](const Vec3& axis, double radians) { return why(e.tiltNeck(axis, radians)); };
  // The window's rays are in metres, the case in millimetres.
  h.placeTip = [&e, why](const Vec3& origin, const Vec3& direction) -> std::string {
    const auto p = geometry::firstLumenMiddle(e.surface(), toMm(origin), direction);
    if (!p) return "there is no vessel under the cursor";
    return why(e.placeTip(*p));
  };
  h.placeNeck = [&e, why](const Vec3& origin, const Vec3& direction) -> std::string {
    const auto p = geometry::firstHit(e.surface(), toMm(origin), direction);
    if (!p) return "there is no surface under the cursor";
    return why(e.placeNeckThrough(*p));
  };
  h.aimTip = [&e, why] { return why(e.pointTip(e.morphology().neckCentre - e.catheter().tip)); };
  h.save = [&e, savePath]() -> std::string {
    try {
      e.save(savePath);
      e.markSaved();
      return "";
    } catch (const std::exception& ex) {
      return ex.what();
    }
  };
  return h;
}

}  // namespace coilsim::app
