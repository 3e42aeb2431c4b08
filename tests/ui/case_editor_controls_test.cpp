// The case editor's controls driven by events as the window hands them
// over, against hooks that record what they were asked: a shift drag moves
// the neck plane by whole pixels times the documented step however the
// motion is split, a refusal keeps the plane and is said in words, a click
// casts the ray that render's own view and projection matrices put through
// the point under the cursor, Save and Close ask before overwriting or
// losing edits.
#include "ui/case_editor_controls.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace coilsim::ui {
namespace {

struct Record {
  std::vector<double> moves;  // mm asked
  double accepted = 0;        // mm accepted in total
  double limit = 1e9;         // moves beyond this total are refused
  std::vector<std::pair<Vec3, double>> tilts;
  std::vector<std::pair<Vec3, Vec3>> tips, necks;
  int saves = 0;
  bool unsaved = false;
  Vec3 tip = Vec3(0.004, 0.004, -0.004);  // m
};

CaseEditorHooks hooks(Record& r, bool overwrites = false) {
  CaseEditorHooks h;
  h.title = "case.json";
  h.savePath = "case.json";
  h.saveOverwrites = overwrites;
  h.view = [&r] {
    CaseEditorView v;
    DrawPoint p;
    p.position = Vec3(0.01, 0, 0);  // something to fit the camera to: a 2 cm box
    v.scene.points = {p, DrawPoint{}};
    v.scene.points[1].position = Vec3(-0.01, 0.005, 0.005);
    v.unsaved = r.unsaved;
    v.tip = r.tip;
    return v;
  };
  h.moveNeck = [&r](double mm) -> std::string {
    r.moves.push_back(mm);
    if (r.accepted + mm > r.limit + 1e-12) return "past the sac centre";
    r.accepted += mm;
    r.unsaved = true;
    return "";
  };
  h.tiltNeck = [&r](const Vec3& axis, double rad) {
    r.tilts.push_back({axis, rad});
    return std::string();
  };
  h.placeTip = [&r](const Vec3& o, const Vec3& d) {
    r.tips.push_back({o, d});
    return std::string();
  };
  h.placeNeck = [&r](const Vec3& o, const Vec3& d) {
    r.necks.push_back({o, d});
    return std::string();
  };
  h.save = [&r] {
    ++r.saves;
    r.unsaved = false;
    return std::string();
  };
  return h;
}

constexpr EditorMods kShift{true, false}, kCtrl{false, true}, kNone{};

// Window pixel of p through render's matrices (not the controls' own formula).
void projected(const CaseEditorControls& c, const Vec3& p, int x0, int w, int h, double& px, double& py) {
  const Eigen::Vector4f world(float(p.x()), float(p.y()), float(p.z()), 1);
  const Eigen::Vector4f clip = c.camera().projection(double(w) / h) * c.camera().view() * world;
  px = x0 + 0.5 * (clip.x() / clip.w() + 1) * w, py = 0.5 * (1 - clip.y() / clip.w()) * h;
}

TEST(CaseEditorControls, AShiftDragMovesTheNeckByWholePixelsTimesTheStep) {
  Record r;
  CaseEditorControls c(hooks(r));
  c.setArea(300, 0, 900, 800);
  c.press(0, 600, 500, kShift);
  c.move(600, 487);    // 13 px up
  c.move(600, 460.4);  // 39.6 px: 40 whole pixels
  c.release(0, 600, 460);
  ASSERT_EQ(r.moves.size(), 2u);
  EXPECT_DOUBLE_EQ(r.moves[0], 13 * kNeckDragMmPerPixel);
  EXPECT_NEAR(r.accepted, 40 * kNeckDragMmPerPixel, 1e-12);
  EXPECT_TRUE(r.tips.empty());  // a drag is no click
  EXPECT_FALSE(c.refused());
}

TEST(CaseEditorControls, ARefusedDragStepKeepsThePlaneAndSaysWhy) {
  Record r;
  r.limit = 1.0;
  CaseEditorControls c(hooks(r));
  c.setArea(300, 0, 900, 800);
  c.press(0, 600, 500, kShift);
  c.move(600, 490);  // 0.5 mm: accepted
  c.move(600, 460);  // 2.0 mm: refused, the plane stays at 0.5
  EXPECT_NEAR(r.accepted, 0.5, 1e-12);
  EXPECT_TRUE(c.refused());
  EXPECT_NE(c.message().find("past the sac centre"), std::string::npos) << c.message();
  c.move(600, 480);  // back to 1.0 mm: the remaining 0.5 is asked and accepted
  c.release(0, 600, 480);
  EXPECT_NEAR(r.moves.back(), 0.5, 1e-12);
  EXPECT_NEAR(r.accepted, 1.0, 1e-12);
  EXPECT_FALSE(c.refused());
}

TEST(CaseEditorControls, KeysMoveAndTiltTheNeckByTheirSteps) {
  Record r;
  CaseEditorControls c(hooks(r));
  c.setArea(300, 0, 900, 800);
  c.key(EditorKey::Up, kNone);
  c.key(EditorKey::PageDown, kNone);
  ASSERT_EQ(r.moves.size(), 2u);
  EXPECT_DOUBLE_EQ(r.moves[0], kNeckKeyStepMm);
  EXPECT_DOUBLE_EQ(r.moves[1], -kNeckPageStepMm);
  c.key(EditorKey::TiltDown, kNone);
  ASSERT_EQ(r.tilts.size(), 1u);
  EXPECT_NEAR((r.tilts[0].first - c.camera().right()).norm(), 0, 1e-12);
  EXPECT_NEAR(r.tilts[0].second, kTiltKeyStepDeg * M_PI / 180, 1e-15);
}

TEST(CaseEditorControls, AClickCastsTheRayThroughThePointProjectedUnderTheCursor) {
  Record r;
  CaseEditorControls c(hooks(r));
  const int x0 = 300, w = 900, h = 800;
  c.setArea(x0, 0, w, h);
  // A point in view, projected by render's matrices (not the controls' ray formula) to window pixels.
  const Vec3 p(0.003, -0.002, 0.001);
  double px = 0, py = 0;
  projected(c, p, x0, w, h, px, py);
  c.press(0, px, py, kNone);
  c.release(0, px, py);
  ASSERT_EQ(r.tips.size(), 1u);
  const auto& [o, d] = r.tips[0];
  EXPECT_NEAR(d.norm(), 1, 1e-12);
  // Distance of p from the ray; the matrices are single precision.
  EXPECT_LT((p - o - (p - o).dot(d) * d).norm(), 1e-6 * (p - o).norm());
  // Ctrl + click: the neck plane; a press on the panel beside the view: nothing.
  c.press(0, px, py, kCtrl);
  c.release(0, px, py);
  EXPECT_EQ(r.necks.size(), 1u);
  c.press(0, 100, 100, kNone);
  c.release(0, 100, 100);
  EXPECT_EQ(r.tips.size(), 1u);
}

TEST(CaseEditorControls, ADragFromTheTipMovesTheTipUnderTheCursor) {
  Record r;
  CaseEditorControls c(hooks(r));
  c.setArea(300, 0, 900, 800);
  double tx = 0, ty = 0;
  projected(c, r.tip, 300, 900, 800, tx, ty);
  double cx = 0, cy = 0;
  c.pixelOf(r.tip, cx, cy);
  EXPECT_NEAR(cx, tx, 1e-3);
  EXPECT_NEAR(cy, ty, 1e-3);
  const double yaw = c.camera().yaw;
  c.press(0, tx + 4, ty - 3, kNone);  // within the grab radius
  c.move(tx + 20, ty + 10);
  c.move(tx + 40, ty + 25);
  c.release(0, tx + 40, ty + 25);
  EXPECT_EQ(c.camera().yaw, yaw);  // no orbit
  ASSERT_EQ(r.tips.size(), 2u);    // one per move, none on the release where the cursor stopped
  // The last ray runs through the pixel the cursor left the tip at: its origin's projection is that pixel.
  const auto& [o, d] = r.tips.back();
  double lx = 0, ly = 0;
  projected(c, o + 0.02 * d, 300, 900, 800, lx, ly);
  EXPECT_NEAR(lx, tx + 40, 0.05);
  EXPECT_NEAR(ly, ty + 25, 0.05);
}

TEST(CaseEditorControls, ADragWithoutShiftOrbitsAndPlacesNothing) {
  Record r;
  CaseEditorControls c(hooks(r));
  c.setArea(300, 0, 900, 800);
  const double yaw = c.camera().yaw;
  c.press(0, 600, 400, kNone);
  c.move(630, 400);
  c.release(0, 630, 400);
  EXPECT_TRUE(r.tips.empty());
  EXPECT_NE(c.camera().yaw, yaw);
}

TEST(CaseEditorControls, SavingOverTheCaseAsksFirst) {
  Record r;
  CaseEditorControls c(hooks(r, true));
  c.setArea(300, 0, 900, 800);
  c.key(EditorKey::Save, kNone);  // S alone is no shortcut
  EXPECT_EQ(c.asking(), EditorAsk::None);
  c.key(EditorKey::Save, kCtrl);
  EXPECT_EQ(c.asking(), EditorAsk::Overwrite);
  EXPECT_EQ(r.saves, 0);
  c.key(EditorKey::Escape, kNone);  // cancels the question, does not close
  EXPECT_EQ(c.asking(), EditorAsk::None);
  EXPECT_FALSE(c.closing());
  c.key(EditorKey::Save, kCtrl);
  c.key(EditorKey::Enter, kNone);
  EXPECT_EQ(r.saves, 1);
  EXPECT_EQ(c.asking(), EditorAsk::None);
}

TEST(CaseEditorControls, ClosingWithUnsavedEditsAsks) {
  Record r;
  CaseEditorControls c(hooks(r));
  c.setArea(300, 0, 900, 800);
  c.key(EditorKey::Up, kNone);  // an edit
  c.key(EditorKey::Escape, kNone);
  EXPECT_EQ(c.asking(), EditorAsk::Unsaved);
  EXPECT_FALSE(c.closing());
  c.key(EditorKey::Up, kNone);  // keys answer the question only
  EXPECT_EQ(r.moves.size(), 1u);
  c.key(EditorKey::No, kNone);
  EXPECT_TRUE(c.closing());
  EXPECT_EQ(r.saves, 0);

  Record saved;
  CaseEditorControls s(hooks(saved));
  s.setArea(300, 0, 900, 800);
  s.key(EditorKey::Down, kNone);
  s.closeRequested();  // the window's close button
  s.key(EditorKey::Enter, kNone);  // save and close
  EXPECT_EQ(saved.saves, 1);
  EXPECT_TRUE(s.closing());

  Record clean;
  CaseEditorControls n(hooks(clean));
  n.key(EditorKey::Escape, kNone);  // nothing to lose: closes at once
  EXPECT_TRUE(n.closing());
}

}  // namespace
}  // namespace coilsim::ui
