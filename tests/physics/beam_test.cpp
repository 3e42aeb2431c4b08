// Tests of the co-rotational beam element (src/physics/beam.cpp).
// References:
//  - small-deflection cantilever: Timoshenko & Gere, Mechanics of Materials,
//    appendix G (tip deflection P L^3 / 3EI, tip rotation P L^2 / 2EI; tip
//    moment: M L^2 / 2EI and M L / EI); shear deflection of a Timoshenko
//    cantilever P L / (kappa G A) (Timoshenko, Strength of Materials I, sec. 39;
//    Przemieniecki, Theory of Matrix Structural Analysis, sec. 5.6, whose
//    element is exact for end loads, so any mesh reproduces these values);
//  - objectivity: a rigid motion (R, t) of a configuration maps internal forces
//    f -> R f and leaves the strain energy unchanged (frame indifference, e.g.
//    Crisfield, Non-linear Finite Element Analysis of Solids and Structures 2,
//    sec. 17.1); a rigidly moved rest shape is stress-free;
//  - internal forces of an energy invariant under translations and rotations
//    have zero resultant force and zero resultant moment (Noether: linear and
//    angular momentum of a free rod are conserved), for any configuration.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "support/known_bugs.h"
#include "support/rod_models.h"
#include "support/tolerance.h"

namespace coilsim::test {
namespace {

// A wire of radius 1 mm and length 100 mm: slenderness L / r = 100.
constexpr double kLength = 0.1, kRadius = 1e-3;

// Load parameter P L^2 / EI of the small-deflection cases: the geometric
// nonlinearity changes the tip deflection by a relative O(alpha^2) = 1e-8.
constexpr double kSmallAlpha = 1e-4;

// Relative bound of the small-deflection checks. The element is exact for
// end loads, so what remains is the O(alpha^2) = 1e-8 nonlinearity and the
// Newton stop (1e-13 L against a deflection of 3e-5 L: 3e-9). 1e-6 keeps a
// margin of 100 yet resolves the shear term of the slender wire (2e-4).
const Tolerance kSmallDeflection{1e-6, "element exact for end loads; O(alpha^2) nonlinearity 1e-8"};

struct Cantilever {
  Model model;
  State state;
  int tip;
};

Cantilever solveCantilever(double length, int beams, const Section& section, const Vec3& force, const Vec3& moment) {
  RodDef r = clamped(straightRod(length, beams, steel(), section));
  r.loads.push_back({beams, force, moment});
  Cantilever c{compileModel(modelOf({r})), {}, beams};
  c.state = makeState(c.model);
  const StaticReport rep = solveStatic(c.model, c.state, tightStatic(1));
  EXPECT_TRUE(rep.converged()) << rep.message();
  return c;
}

double bendingStiffness(const Section& s) { return steel().youngModulus * s.iy; }

TEST(BeamTest, TipForceDeflectionIsTimoshenkoCantileverForAnyMesh) {
  // L / r = 100 (shear term 2e-4 of the bending term) and L / r = 5 (shear
  // term 9 %): both must match PL^3/3EI + PL/(kappa G A) to 1e-6.
  for (const double length : {kLength, 5 * kRadius}) {
    const Section s = circularSection(kRadius, kSteelPoisson);
    const double ei = bendingStiffness(s);
    const double p = kSmallAlpha * ei / (length * length);
    const double bending = p * std::pow(length, 3) / (3 * ei);
    const double shear = p * length / (s.shearFactor * steel().shearModulus * s.area);
    for (const int beams : {1, 4, 20}) {
      Cantilever c = solveCantilever(length, beams, s, Vec3(0, 0, -p), Vec3::Zero());
      const RodState& r = c.state.rods[0];
      const std::string tag = "L/r=" + std::to_string(int(length / kRadius + 0.5)) + " n=" + std::to_string(beams);
      EXPECT_TRUE(nearRel("tip deflection " + tag, -r.x[c.tip].z(), bending + shear, kSmallDeflection));
      // The section rotation of a Timoshenko cantilever is P L^2 / 2EI, shear or not.
      const double rotation = std::atan2(-tangentOf(r.q[c.tip]).z(), tangentOf(r.q[c.tip]).x());
      EXPECT_TRUE(nearRel("tip rotation " + tag, r.q[c.tip].angularDistance(Quat::Identity()),
                          p * length * length / (2 * ei), kSmallDeflection));
      EXPECT_GT(rotation, 0.0) << "a downward load turns the tip downwards";
      EXPECT_TRUE(small("out-of-plane tip motion / L " + tag, r.x[c.tip].y() / length,
                        roundoff(1.0, 1e3, "planar load: only round-off of coordinates of size L")));
    }
  }
}

TEST(BeamTest, ZeroShearFactorIsEulerBernoulli) {
  // shearFactor 0 switches the shear flexibility off: P L^3 / 3EI exactly,
  // even for the stubby L / r = 5 rod where shear would add 9 %.
  Section s = circularSection(kRadius, kSteelPoisson);
  s.shearFactor = 0;
  const double length = 5 * kRadius, ei = bendingStiffness(s);
  const double p = kSmallAlpha * ei / (length * length);
  Cantilever c = solveCantilever(length, 3, s, Vec3(0, 0, -p), Vec3::Zero());
  EXPECT_TRUE(nearRel("Euler-Bernoulli tip deflection", -c.state.rods[0].x[c.tip].z(),
                      p * std::pow(length, 3) / (3 * ei), kSmallDeflection));
}

TEST(BeamTest, TipMomentGivesMLSquaredOverTwoEIAndRotationMLOverEI) {
  const Section s = circularSection(kRadius, kSteelPoisson);
  const double ei = bendingStiffness(s);
  const double m = kSmallAlpha * ei / kLength;  // tip rotation 1e-4 rad
  // A moment about +y turns the tangent x towards -z.
  Cantilever c = solveCantilever(kLength, 10, s, Vec3::Zero(), Vec3(0, m, 0));
  const RodState& r = c.state.rods[0];
  EXPECT_TRUE(nearRel("tip deflection under moment", -r.x[c.tip].z(), m * kLength * kLength / (2 * ei),
                      kSmallDeflection));
  // Under a pure end moment the rotation is M L / EI at any amplitude.
  EXPECT_TRUE(nearRel("tip rotation under moment", r.q[c.tip].angularDistance(Quat::Identity()), m * kLength / ei,
                      kSmallDeflection));
}

TEST(BeamTest, EachBendingPlaneUsesItsOwnSecondMoment) {
  // Rectangular-like section with Iy = 2 Iz: a z load bends about d1 = y (Iy),
  // a y load bends about d2 = z (Iz). Shear off to isolate the second moments.
  const Section round = circularSection(kRadius, kSteelPoisson);
  const Section s = customSection(round.area, 2 * round.iz, round.iz, round.torsion, 0.0, kRadius);
  const double e = steel().youngModulus;
  const double p = kSmallAlpha * e * s.iz / (kLength * kLength);
  Cantilever cz = solveCantilever(kLength, 8, s, Vec3(0, 0, -p), Vec3::Zero());
  Cantilever cy = solveCantilever(kLength, 8, s, Vec3(0, -p, 0), Vec3::Zero());
  EXPECT_TRUE(nearRel("z load uses Iy", -cz.state.rods[0].x[8].z(), p * std::pow(kLength, 3) / (3 * e * s.iy),
                      kSmallDeflection));
  EXPECT_TRUE(nearRel("y load uses Iz", -cy.state.rods[0].x[8].y(), p * std::pow(kLength, 3) / (3 * e * s.iz),
                      kSmallDeflection));
}

// ---- Objectivity -----------------------------------------------------------

Model helixModel() {
  const double length = 0.03;
  const int beams = 60;
  RodDef r = rodWithRest(makeHelix(length, beams, 0.007, 0.002, true), length, beams, platinum(),
                         circularSection(1.8e-4, kPlatinumPoisson));
  return compileModel(modelOf({r}));
}

// Rigid motion x -> R x + t, q -> R q of every node.
void moveRigidly(RodState& r, const Quat& rot, const Vec3& t) {
  for (size_t i = 0; i < r.x.size(); ++i) {
    r.x[i] = rot * r.x[i] + t;
    r.q[i] = (rot * r.q[i]).normalized();
  }
}

// Rotations including one near pi, where the log map is most delicate.
const Quat kRotations[] = {
    Quat(Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized())),
    Quat(Eigen::AngleAxisd(3.0, Vec3(-2, 0.5, 1).normalized())),
    Quat(Eigen::AngleAxisd(M_PI / 2, Vec3::UnitZ())),
};
const Vec3 kTranslation(0.05, -0.02, 0.03);

// The helix with every node moved by ~amplitude of a beam and turned by ~10
// amplitude rad, at random.
State deformedHelix(const Model& m, double amplitude) {
  State a = makeState(m);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1, 1);
  const double ds = 0.03 / 60;
  for (size_t i = 1; i < a.rods[0].x.size(); ++i) {
    a.rods[0].x[i] += amplitude * ds * Vec3(u(rng), u(rng), u(rng));
    a.rods[0].q[i] = (quatExp(10 * amplitude * Vec3(u(rng), u(rng), u(rng))) * a.rods[0].q[i]).normalized();
  }
  return a;
}

TEST(BeamTest, RigidMotionRotatesForcesAndKeepsEnergy) {
  const Model m = helixModel();
  State a = deformedHelix(m, 1e-3);
  const double energyA = assembleAt(m, a);
  ASSERT_GT(energyA, 0.0);
  double forceScale = 0;
  for (const Vec6& f : a.rods[0].work.force) forceScale = std::max(forceScale, f.norm());
  const Eigen::MatrixXd kA = toDense(a.rods[0].work.stiffness);

  // Coordinates of size 0.06 m carry 1e-17 m of round-off, 5e-11 of the
  // 2.5e-7 m perturbation; 1e-8 leaves room for the dozen operations per force.
  const Tolerance forceTol{1e-8 * forceScale, "round-off of 0.06 m coordinates against 2.5e-7 m deformations"};
  const Tolerance energyTol{1e-8 * energyA, "same round-off argument, energy is quadratic in the deformation"};
  for (const Quat& rot : kRotations) {
    State b = a;
    moveRigidly(b.rods[0], rot, kTranslation);
    const double energyB = assembleAt(m, b);
    EXPECT_TRUE(nearAbs("energy after rigid motion", energyB, energyA, energyTol));
    const Mat3 rm = rot.toRotationMatrix();
    double worst = 0;
    for (size_t i = 0; i < a.rods[0].x.size(); ++i) {
      const Vec6& fa = a.rods[0].work.force[i];
      const Vec6& fb = b.rods[0].work.force[i];
      worst = std::max(worst, (fb.head<3>() - rm * fa.head<3>()).norm());
      worst = std::max(worst, (fb.tail<3>() - rm * fa.tail<3>()).norm());
    }
    EXPECT_TRUE(small("force / moment after rigid motion minus rotated", worst, forceTol));
    // The tangent is covariant too: K_b = blockdiag(R) K_a blockdiag(R)^T.
    const int n = int(kA.rows());
    Eigen::MatrixXd rBig = Eigen::MatrixXd::Zero(n, n);
    for (int k = 0; k < n / 3; ++k) rBig.block<3, 3>(3 * k, 3 * k) = rm;
    const Eigen::MatrixXd kB = toDense(b.rods[0].work.stiffness);
    EXPECT_TRUE(small("tangent after rigid motion minus rotated (relative)",
                      (kB - rBig * kA * rBig.transpose()).norm() / kA.norm(),
                      {1e-12, "pure rotation of the same blocks: a few ulps per entry"}));
  }
}

TEST(BeamTest, RigidlyMovedRestShapeHasNoForce) {
  const Model m = helixModel();
  State rest = makeState(m);
  const RodModel& rm = m.rods[0];
  // Force scale: the axial force of a strain of 1e-6, EA * 1e-6.
  const double axial = rm.material.youngModulus * rm.section.area * 1e-6;
  for (const Quat& rot : kRotations) {
    State s = rest;
    moveRigidly(s.rods[0], rot, kTranslation);
    const double energy = assembleAt(m, s);
    double worst = 0;
    for (const Vec6& f : s.rods[0].work.force) worst = std::max(worst, f.head<3>().norm());
    // Round-off of 0.06 m coordinates (1e-17 m) over 5e-4 m beams is a strain
    // of ~3e-14 per operation: far below the 1e-6 strain that sets the scale.
    EXPECT_TRUE(small("force in a rigidly moved rest shape / EA 1e-6", worst / axial,
                      {1e-5, "coordinate round-off is a strain ~1e-13, the scale is a strain of 1e-6"}));
    EXPECT_TRUE(small("energy of a rigidly moved rest shape / (EA L 1e-12)",
                      energy / (rm.material.youngModulus * rm.section.area * 0.03 * 1e-12),
                      {1e-6, "energy is quadratic in the round-off strain"}));
  }
}

// Resultants of the internal forces of a deformed rod, and their scales
// (largest nodal force; largest nodal force times the rod length).
struct Resultant {
  Vec3 force = Vec3::Zero(), moment = Vec3::Zero();
  double forceScale = 0, momentScale = 0;
};

Resultant internalResultant(double amplitude) {
  const Model m = helixModel();
  State s = deformedHelix(m, amplitude);
  assembleAt(m, s);
  Resultant r;
  for (size_t i = 0; i < s.rods[0].x.size(); ++i) {
    const Vec6& f = s.rods[0].work.force[i];
    r.force += f.head<3>();
    r.moment += s.rods[0].x[i].cross(f.head<3>()) + f.tail<3>();
    r.forceScale = std::max(r.forceScale, f.head<3>().norm());
  }
  r.momentScale = r.forceScale * 0.03;
  return r;
}

// 61 nodal forces, each a sum of a few rotated products: ~1e3 eps.
const Tolerance kResultant = roundoff(1.0, 1e3, "sum of 61 nodal forces of similar size");

TEST(BeamTest, InternalForcesHaveZeroResultantForce) {
  for (const double amplitude : {1e-3, 1e-2, 1e-1}) {
    const Resultant r = internalResultant(amplitude);
    EXPECT_TRUE(small("resultant internal force / largest nodal force, amplitude " + std::to_string(amplitude),
                      r.force.norm() / r.forceScale, kResultant));
  }
}

TEST(BeamTest, InternalForcesHaveZeroResultantMoment) {
  SKIP_IF_OPEN(kElementMomentImbalance);
  for (const double amplitude : {1e-3, 1e-2, 1e-1}) {
    const Resultant r = internalResultant(amplitude);
    EXPECT_TRUE(small("resultant internal moment / (largest force * L), amplitude " + std::to_string(amplitude),
                      r.moment.norm() / r.momentScale, kResultant));
  }
}

}  // namespace
}  // namespace coilsim::test
