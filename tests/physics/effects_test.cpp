// Tests of the effects, each alone (src/physics/effects/*.cpp), and of their
// registry (src/physics/effect.cpp).
// References:
//  - gravity: free fall v = g t (a constant force on an undeformed free rod;
//    implicit Euler integrates it exactly); cantilever sag w L^4 / 8EI +
//    w L^2 / (2 kappa G A) plus the known 1 / (3 n^2) of force-only lumping
//    (see convergence_test.cpp);
//  - buoyancy (Archimedes): upthrust rho_f A g per length, so the net weight
//    is scaled by (rho - rho_f) / rho and buoyancy alone lifts the rod at
//    g rho_f / rho;
//  - drag: resistive-force theory, Gray & Hancock (1955), J. Exp. Biol.
//    32:802, drag per length c_n v (broadside) and c_t v (end-on) with
//    c_n = 4 pi mu / (ln(2 lambda / r) + 1/2), c_t = 2 pi mu / (ln(2 lambda / r)
//    - 1/2) (the coefficients named in src/physics/effects/drag.cpp, written
//    out again here); terminal velocity of a falling straight rod m g / (c L).
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "support/known_bugs.h"
#include "support/rod_models.h"
#include "support/tolerance.h"

namespace coilsim::test {
namespace {

constexpr double kG = 9.81;
constexpr double kLength = 0.05, kRadius = 1e-4;
constexpr int kBeams = 10;

RodDef freeRod() { return straightRod(kLength, kBeams, steel(), circularSection(kRadius, kSteelPoisson)); }

// Round-off of a rigid motion of a free rod: the stiffness times a uniform
// velocity is zero only to eps |K| |v|, which the step turns into a velocity
// error of eps h^2 w_max^2 |v|, w_max^2 = 4 E / (rho l^2) the highest axial
// mode of beams of length l (h^2 w_max^2 = 4e6 at h = 1 ms, l = 5 mm): a
// worst-case bound that adds up over the steps.
Tolerance rigidRoundoff(int steps) {
  const double l = kLength / kBeams, h = ModelDef().timeStep;
  const double w2 = 4 * steel().youngModulus / (steel().density * l * l);
  return roundoff(1.0, steps * h * h * w2, "eps h^2 w_max^2 per step, summed over the steps");
}

double velocitySpread(const RodState& r, const Vec3& expected) {
  double worst = 0;
  for (const Vec3& v : r.v) worst = std::max(worst, (v - expected).norm());
  return worst;
}

TEST(EffectsTest, GravityAloneMakesAFreeRodFallAtG) {
  const Model m = compileModel(modelOf({freeRod()}, {"gravity"}, Vec3(0, 0, -kG)));
  State s = makeState(m);
  ASSERT_TRUE(run(m, s, 100));
  EXPECT_TRUE(small("free fall: node velocities minus g t, / g t", velocitySpread(s.rods[0], Vec3(0, 0, -kG * s.time)) /
                                                                       (kG * s.time),
                    rigidRoundoff(100)));
}

TEST(EffectsTest, SwitchedOffEffectDoesNothing) {
  ModelDef d = modelOf({freeRod()}, {"gravity", "buoyancy", "drag"}, Vec3(0, 0, -kG));
  for (EffectUse& u : d.effects) u.enabled = false;
  const Model m = compileModel(d);
  State s = makeState(m);
  ASSERT_TRUE(run(m, s, 20));
  EXPECT_TRUE(small("velocity with every effect off", velocitySpread(s.rods[0], Vec3::Zero()), {0.0, "no force at all"}));
}

// Static tip sag of a cantilever under the model's effects, with gravity
// scaled down 1000 times so the response is linear (w L^3 / EI ~ 1e-6).
double tipSag(std::initializer_list<const char*> effects, double mediumDensity = 1000) {
  ModelDef d = modelOf({clamped(freeRod())}, effects, Vec3(0, 0, -kG * 1e-3));
  for (EffectUse& u : d.effects)
    if (u.name() == "buoyancy") u.set("medium_density_g_cm3", mediumDensity);
  const Model m = compileModel(d);
  State s = makeState(m);
  const StaticReport rep = solveStatic(m, s, tightStatic(1));
  EXPECT_TRUE(rep.converged()) << rep.message();
  return -s.rods[0].x[kBeams].z();
}

const Tolerance kLinear{1e-6, "linear regime (w L^3 / EI ~ 1e-6), Newton stop 1e-13 L"};

TEST(EffectsTest, GravityAloneGivesTheSelfWeightSag) {
  const Section s = circularSection(kRadius, kSteelPoisson);
  const double w = steel().density * s.area * kG * 1e-3, ei = steel().youngModulus * s.iy;
  const double bending = w * std::pow(kLength, 4) / (8 * ei);
  const double shear = w * kLength * kLength / (2 * s.shearFactor * steel().shearModulus * s.area);
  const double lumping = bending / (3.0 * kBeams * kBeams);
  EXPECT_TRUE(nearRel("gravity sag vs wL^4/8EI + shear + lumping", tipSag({"gravity"}), bending + shear + lumping,
                      kLinear));
}

TEST(EffectsTest, BuoyancyScalesTheNetWeightByDensityContrast) {
  const double rho = steel().density, rhoF = 1000.0;
  const double weight = tipSag({"gravity"});
  EXPECT_TRUE(nearRel("gravity + buoyancy sag / gravity sag vs (rho - rho_f) / rho",
                      tipSag({"gravity", "buoyancy"}, rhoF) / weight, (rho - rhoF) / rho, kLinear));
  // Buoyancy alone pushes up with rho_f / rho of the weight.
  EXPECT_TRUE(nearRel("buoyancy-only sag / gravity sag vs -rho_f / rho", tipSag({"buoyancy"}, rhoF) / weight,
                      -rhoF / rho, kLinear));
}

TEST(EffectsTest, BuoyancyAloneLiftsAFreeRodAtGRhoFOverRho) {
  ModelDef d = modelOf({freeRod()}, {"buoyancy"}, Vec3(0, 0, -kG));
  const double rhoF = 1060.0;  // blood
  d.effects[0].set("medium_density_g_cm3", rhoF);
  const Model m = compileModel(d);
  State s = makeState(m);
  ASSERT_TRUE(run(m, s, 50));
  const double a = kG * rhoF / steel().density;
  EXPECT_TRUE(small("buoyant rise: velocities minus g rho_f/rho t, / (a t)",
                    velocitySpread(s.rods[0], Vec3(0, 0, a * s.time)) / (a * s.time),
                    rigidRoundoff(50)));
}

// Gray-Hancock coefficients, written out independently of drag.cpp.
struct RftCoefficients {
  double normal, tangential;
};
RftCoefficients grayHancock(double mu, double lambda, double radius) {
  const double lg = std::log(2 * lambda / radius);
  return {4 * M_PI * mu / (lg + 0.5), 2 * M_PI * mu / (lg - 0.5)};
}

// Terminal velocity of a free straight rod falling with axis `axis` under
// gravity and drag (viscosity 0.1 Pa s, lambda 7 mm).
double terminalSpeed(const Vec3& axis, double& timeConstant) {
  RodDef r = freeRod();
  r.placement.direction = axis;
  r.placement.normal = axis.cross(Vec3::UnitX()).norm() > 0.5 ? axis.cross(Vec3::UnitX()).normalized() : Vec3::UnitY();
  ModelDef d = modelOf({r}, {"gravity", "drag"}, Vec3(0, 0, -kG));
  const double mu = 0.1, lambda = 0.007;
  d.effects[1].set("viscosity_pa_s", mu);
  d.effects[1].set("rft_length_mm", lambda);
  const RftCoefficients c = grayHancock(mu, lambda, kRadius);
  const double massPerLength = steel().density * r.section.area;
  const bool broadside = std::abs(axis.z()) < 0.5;
  timeConstant = massPerLength / (broadside ? c.normal : c.tangential);
  d.timeStep = timeConstant / 20;
  const Model m = compileModel(d);
  State s = makeState(m);
  // 40 time constants: (1 + h / tau)^(-800) = 1e-17 of the start remains.
  EXPECT_TRUE(run(m, s, 800));
  double worst = 0;
  for (const Vec3& v : s.rods[0].v) worst = std::max(worst, std::abs(v.z() - s.rods[0].v[0].z()));
  EXPECT_TRUE(small("spread of node velocities / mean", worst / std::abs(s.rods[0].v[0].z()),
                    {1e-9, "uniform weight and drag per length: a rigid fall"}));
  return -s.rods[0].v[kBeams / 2].z();
}

TEST(EffectsTest, DragGivesTheGrayHancockTerminalVelocityBroadsideAndEndOn) {
  SKIP_IF_OPEN(kEffectDampingCountedTwice);
  const RftCoefficients c = grayHancock(0.1, 0.007, kRadius);
  const double weightPerLength = steel().density * M_PI * kRadius * kRadius * kG;
  double tau = 0;
  const Tolerance settled{1e-9, "40 time constants of implicit Euler: the transient is 1e-17"};
  EXPECT_TRUE(nearRel("broadside terminal speed vs m g / (c_n L)", terminalSpeed(Vec3::UnitX(), tau),
                      weightPerLength / c.normal, settled));
  EXPECT_TRUE(nearRel("end-on terminal speed vs m g / (c_t L)", terminalSpeed(Vec3(0, 0, -1), tau),
                      weightPerLength / c.tangential, settled));
}

// ---- Registry --------------------------------------------------------------

class Dummy final : public Effect {
 public:
  explicit Dummy(std::string_view name) : name_(name) {}
  std::string_view name() const override { return name_; }
  std::string_view description() const override { return "test effect"; }
  void apply(const EffectContext&, std::span<const double>, RodForces&) const override {}

 private:
  std::string_view name_;
};

TEST(EffectRegistryTest, BuiltinsAreRegisteredByName) {
  for (const char* name : {"gravity", "buoyancy", "drag"})
    EXPECT_NE(EffectRegistry::global().find(name), nullptr) << name;
}

TEST(EffectRegistryTest, RefusesAnUnknownNameAndListsTheKnownOnes) {
  try {
    EffectRegistry::global().use("magnetism");
    FAIL() << "an unknown effect was accepted";
  } catch (const std::invalid_argument& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("magnetism"), std::string::npos) << msg;
    EXPECT_NE(msg.find("gravity"), std::string::npos) << msg;
  }
}

TEST(EffectRegistryTest, RefusesADuplicateName) {
  EffectRegistry registry;
  registerBuiltinEffects(registry);
  EXPECT_THROW(registry.add(std::make_unique<Dummy>("drag")), std::invalid_argument);
  const Effect* added = registry.add(std::make_unique<Dummy>("magnetism"));
  EXPECT_EQ(registry.find("magnetism"), added);
  EXPECT_THROW(registry.add(std::make_unique<Dummy>("magnetism")), std::invalid_argument);
}

TEST(EffectRegistryTest, CompileRefusesParametersOutsideTheirBounds) {
  ModelDef d = modelOf({freeRod()}, {"drag"});
  d.effects[0].set("viscosity_pa_s", -1.0);
  EXPECT_THROW(compileModel(d), std::invalid_argument);
  d.effects[0].set("viscosity_pa_s", std::nan(""));
  EXPECT_THROW(compileModel(d), std::invalid_argument);
}

}  // namespace
}  // namespace coilsim::test
