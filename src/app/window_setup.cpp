// Live read-outs and the coil / catheter choice of the window.
#include "app/window_setup.h"

#include <algorithm>
#include <cmath>
#include <memory>

#include "app/format.h"
#include "io/units.h"
#include "physics/integrator.h"
#include "planning/live_readouts.h"

namespace coilsim::app {

ui::ReadoutHook liveReadouts(const planning::Sac& sac, const Deployment& dep, double wallForceLimit,
                             const std::string& title) {
  auto live = std::make_shared<planning::LiveReadouts>(sac, dep, wallForceLimit);
  ui::ReadoutHook hook;
  hook.title = title;
  hook.compute = [live](const Model& m, const State& s) {
    std::vector<ui::Readout> out;
    for (const planning::LiveLine& l : live->lines(m, s)) out.push_back({l.label, l.value, l.warning});
    return out;
  };
  return hook;
}

std::string coilLabel(const io::CoilSpec& c) {
  return c.name + ": " + std::string(io::shapeName(c.shape)) + ", " + fmt("%g", c.loopDiameterMm) + " mm loops, " +
         fmt("%g", c.lengthMm) + " mm, B " + fmt("%.2g", c.bendingStiffnessNmm2) + " N mm2";
}

std::vector<CatheterChoice> catheterChoices(const io::CatheterSpec& scene) {
  using T = CatheterShape::Type;
  std::vector<CatheterChoice> out;
  CatheterChoice own;
  own.keepScene = true;
  own.label = "the scene's: " + std::string(scene.flexible ? "flexible" : "rigid straight");
  out.push_back(own);
  // Tight bends: the tip sits at an aneurysm neck in a vessel a few mm wide.
  const CatheterChoice shapes[] = {
      {"rigid straight", false, false, T::Straight, 0, 0},
      {"flexible straight", false, true, T::Straight, 0, 0},
      {"flexible 45\xc2\xb0 (r 2 mm)", false, true, T::Angled, 45, 2},
      {"flexible 90\xc2\xb0 (r 1.5 mm)", false, true, T::Angled, 90, 1.5},
      {"flexible J (180\xc2\xb0, r 1 mm)", false, true, T::J, 180, 1},
      {"flexible S (2 x 45\xc2\xb0, r 1.5 mm)", false, true, T::S, 45, 1.5},
  };
  out.insert(out.end(), std::begin(shapes), std::end(shapes));
  return out;
}

namespace {

// Net turn (deg) from the held part to the tip: the bend of an angled tip or a J, none for an S.
double netTurnDeg(bool flexible, CatheterShape::Type type, double angleDeg) {
  if (!flexible || type == CatheterShape::Type::Straight || type == CatheterShape::Type::S) return 0.0;
  return angleDeg;
}

}  // namespace

void applyCatheter(const CatheterChoice& choice, io::DeploymentSpec& dep) {
  if (choice.keepScene) return;
  io::CatheterSpec& c = dep.catheter;
  // The catheter keeps its approach (the held part's axis, in the plane of
  // the tip's direction and normal) and its tip position; the shape decides
  // where the tip points: turned from the approach towards the scene's
  // reference normal by the shape's net bend. So the body stays where the
  // scene put it (in the parent vessel) and only the tip changes.
  const Vec3 d = c.direction.normalized();
  const Vec3 n = (c.referenceNormal - c.referenceNormal.dot(d) * d).normalized();
  const double was = units::degToRad(netTurnDeg(c.flexible, c.rest.type, c.rest.angleDeg));
  const Vec3 approach = std::cos(was) * d - std::sin(was) * n, side = std::sin(was) * d + std::cos(was) * n;
  const double turn = units::degToRad(netTurnDeg(choice.flexible, choice.type, choice.angleDeg));
  c.direction = std::cos(turn) * approach + std::sin(turn) * side;
  c.referenceNormal = -std::sin(turn) * approach + std::cos(turn) * side;
  if (!choice.flexible) {
    c.flexible = false;
    return;
  }
  if (!c.flexible) {
    // A soft microcatheter tube (polymer E 0.3 GPa, as scenes/preshaped-catheter.json):
    // 1 mm held behind the bends and 1 mm straight before them (a short body keeps
    // inside the parent vessel of a scene made for a straight stub), beams about 0.5 mm.
    c.flexible = true;
    c.innerDiameterMm = 0.7 * c.outerDiameterMm;
    c.material = {0.3, 0.4, 1.1};
    c.heldLengthMm = 1;
    c.freeLengthMm = 0;
    c.beams = 0;
    c.weighting = CompositeWeighting::BendingStiffness;
  }
  c.rest.type = choice.type;
  c.rest.angleDeg = choice.angleDeg;
  c.rest.radiusMm = choice.radiusMm;
  const double bends = choice.type == CatheterShape::Type::Straight ? 0.0
                       : units::degToRad(choice.angleDeg) * choice.radiusMm * (choice.type == CatheterShape::Type::S ? 2 : 1);
  c.freeLengthMm = std::max(c.freeLengthMm, bends + 1.0);
  c.beams = std::max(c.beams, int(std::ceil((c.heldLengthMm + c.freeLengthMm) / 0.5)));
}

ui::SetupChoices sceneSetupChoices(const io::SceneSpec& scene, const std::optional<planning::Sac>& sac) {
  ui::SetupChoices choices;
  const auto catalogue = std::make_shared<std::vector<io::CoilSpec>>(io::loadCatalogue(planning::defaultCatalogue()));
  for (const io::CoilSpec& c : *catalogue) choices.coils.push_back(coilLabel(c));
  const std::vector<CatheterChoice> catheters = catheterChoices(scene.deployment->catheter);
  for (const CatheterChoice& c : catheters) choices.catheters.push_back(c.label);
  choices.catheter = 0;
  choices.coilNote = "from assets/coils (docs/coils.md); loading one resets the run";
  const double spacingMm = scene.deployment->lengthMm / scene.deployment->beams;
  choices.build = [scene, catalogue, catheters, sac, spacingMm](int coil, int catheter) {
    io::SceneSpec spec = scene;
    io::DeploymentSpec& dep = *spec.deployment;
    std::string coilName = "the scene's coil";
    if (coil >= 0) {
      const io::CoilSpec& c = catalogue->at(size_t(coil));
      io::applyCoil(c, spacingMm, dep);
      dep.initialDeployedMm = std::min(dep.initialDeployedMm, 0.5 * c.lengthMm);
      coilName = c.name;
    }
    if (catheter >= 0) applyCatheter(catheters.at(size_t(catheter)), dep);
    io::checkScene(spec);  // throws InputError saying what does not fit
    ui::SceneSetup s;
    s.model = compileModel(io::compileScene(spec));
    s.state = makeState(s.model);
    if (sac) s.readouts = liveReadouts(*sac, *s.model.device, planning::Goal{}.maxWallForce, "Aneurysm read-outs");
    s.loaded = "loaded " + coilName + " (" + fmt("%g", dep.lengthMm) + " mm, " + std::to_string(dep.beams) +
               " beams) in the " + (catheter >= 0 ? catheters[size_t(catheter)].label : "scene's") + " catheter";
    return s;
  };
  return choices;
}

}  // namespace coilsim::app
