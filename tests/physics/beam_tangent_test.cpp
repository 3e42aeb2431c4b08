// The fast global tangent of evalBeam (outer products of the element axes)
// must equal the textbook co-rotational tangent T K T^T, T = diag(R, R, R, R),
// computed here independently by dense 12x12 products; so must the dynamic
// step's scaled tangent and its product with the nodes' velocities.
#include <gtest/gtest.h>

#include "physics/beam.h"

namespace coilsim {
namespace {

// A skew element, deformed (node b moved and turned a little) and then
// turned a lot as a whole; `izFactor` != 1 makes the section non-round.
struct DeformedBeam {
  BeamRest rest;
  BeamEval ev;
  Mat12 T = Mat12::Zero();  // diag(R, R, R, R) of the element frame
  DeformedBeam(double izFactor, bool withTangent) {
    const Material mat{7.5e9, shearModulusOf(7.5e9, 0.39), 21450};
    Section sec = circularSection(0.3e-3, 0.39);
    sec.iz *= izFactor;
    const Quat qa = Quat(Eigen::AngleAxisd(0.3, Vec3(1, 2, 3).normalized()));
    const Quat qb = Quat(Eigen::AngleAxisd(0.35, Vec3(1, 2.2, 3).normalized()));
    const Vec3 xa(0.001, -0.002, 0.0005), xb = xa + qa * Vec3(0.0005, 0.00002, -0.00001);
    rest = makeBeamRest(xa, qa, xb, qb, mat, sec);
    const Quat big(Eigen::AngleAxisd(2.0, Vec3(-1, 0.5, 0.2).normalized()));
    evalBeam(rest, big * xa, big * qa, big * (xb + Vec3(1e-5, 2e-5, -1e-5)), big * quatExp(Vec3(0.01, -0.02, 0.03)) * qb,
             withTangent, ev);
    const Mat3 R = ev.frame.toRotationMatrix();
    for (int k = 0; k < 4; ++k) T.block<3, 3>(3 * k, 3 * k) = R;
  }
};

TEST(BeamTangent, EqualsRotatedLocalStiffness) {
  const DeformedBeam b(1.7, true);  // unequal bending stiffness: exercises both shear terms separately
  const BeamEval& ev = b.ev;
  const Mat12 K = b.T * b.rest.stiffness * b.T.transpose();
  const double scale = K.cwiseAbs().maxCoeff();
  EXPECT_LT((ev.kaa - K.block<6, 6>(0, 0)).cwiseAbs().maxCoeff(), 1e-12 * scale);
  EXPECT_LT((ev.kba - K.block<6, 6>(6, 0)).cwiseAbs().maxCoeff(), 1e-12 * scale);
  EXPECT_LT((ev.kbb - K.block<6, 6>(6, 6)).cwiseAbs().maxCoeff(), 1e-12 * scale);
}

// Round sections fill the blocks entry by entry (beam_tangent.cpp): scaled
// blocks added into a chain that already holds something, and s K v.
TEST(BeamTangent, ScaledChainBlocksAndVelocityProduct) {
  for (const double izFactor : {1.0, 1.7}) {  // round, then the general path
    const DeformedBeam b(izFactor, false);
    const double s = 1.3e-6;
    const Mat12 K = s * b.T * b.rest.stiffness * b.T.transpose();
    const Mat6 before = Mat6::Constant(0.25);  // what the previous beam left in the shared diagonal block
    Mat6 diagA = before, lower = Mat6::Constant(7.0), diagB = Mat6::Constant(-3.0);
    Vec6 vel[2], product[2];
    vel[0] << 0.1, -0.2, 0.3, 4.0, -5.0, 6.0;
    vel[1] << -0.3, 0.1, 0.2, -2.0, 1.0, 3.0;
    product[0] = Vec6::Constant(0.5), product[1] = Vec6::Constant(-0.5);
    addBeamTangent(b.rest, b.ev.rotation, s, diagA, lower, diagB, vel, product);
    const double scale = K.cwiseAbs().maxCoeff();
    EXPECT_LT((diagA - before - K.block<6, 6>(0, 0)).cwiseAbs().maxCoeff(), 1e-12 * scale) << izFactor;
    EXPECT_LT((lower - K.block<6, 6>(6, 0)).cwiseAbs().maxCoeff(), 1e-12 * scale) << izFactor;
    EXPECT_LT((diagB - K.block<6, 6>(6, 6)).cwiseAbs().maxCoeff(), 1e-12 * scale) << izFactor;
    Eigen::Matrix<double, 12, 1> v, kv;
    v << vel[0], vel[1];
    kv = K * v;
    const double pscale = kv.cwiseAbs().maxCoeff();
    EXPECT_LT((product[0] - Vec6::Constant(0.5) - kv.head<6>()).cwiseAbs().maxCoeff(), 1e-12 * pscale) << izFactor;
    EXPECT_LT((product[1] + Vec6::Constant(0.5) - kv.tail<6>()).cwiseAbs().maxCoeff(), 1e-12 * pscale) << izFactor;
  }
}

// The geometric stiffness of tension. A stretched straight element of a
// wound coil (EA 3.9 kN, B 1.8e-9 N m^2, l 0.5 mm) with its node frames
// held: moving node b across the axis turns the chord, and node b's force
// changes by the bending shear 12 B / l^3 plus the turned tension N / l
// (N = EA u / l, 0.39 N here: the string term is four times the bending
// one). The reference is the derivative itself, by central differences of
// evalBeam's forces; the material tangent alone misses the N / l, and
// `string` = N / l puts it in the blocks and in the velocity product.
TEST(BeamTangent, StringTermIsTheTensionsShareOfTheForcesDerivative) {
  const Material mat{168e9, shearModulusOf(168e9, 0.38), 21450};
  Section sec;
  sec.area = 2.3e-8, sec.iy = sec.iz = 1.09e-20, sec.torsion = 3.6e-20, sec.shearFactor = 0, sec.radius = 1.27e-4;
  const double l0 = 5e-4;
  const BeamRest rest = makeBeamRest(Vec3::Zero(), Quat::Identity(), Vec3(l0, 0, 0), Quat::Identity(), mat, sec);
  const Vec3 xb(l0 * (1 + 1e-4), 0, 0);
  const auto forceB = [&](const Vec3& x) {
    BeamEval e;
    evalBeam(rest, Vec3::Zero(), Quat::Identity(), x, Quat::Identity(), false, e);
    return Vec3(e.forceB.head<3>());
  };
  Mat3 derivative;  // d(-force_b) / d(x_b)
  const double eps = 1e-9;
  for (int j = 0; j < 3; ++j) {
    const Vec3 d = eps * Vec3::Unit(j);
    derivative.col(j) = -(forceB(xb + d) - forceB(xb - d)) / (2 * eps);
  }
  BeamEval ev;
  evalBeam(rest, Vec3::Zero(), Quat::Identity(), xb, Quat::Identity(), false, ev);
  const double tension = rest.axial[0] * ev.deformation[0], string = tension / xb.norm();
  ASSERT_GT(string, 3 * rest.axial[1]) << "the case must be one where the string term dominates";
  Mat6 diagA = Mat6::Zero(), lower, diagB, diagA0 = Mat6::Zero(), lower0, diagB0;
  Vec6 vel[2], product[2] = {Vec6::Zero(), Vec6::Zero()}, product0[2] = {Vec6::Zero(), Vec6::Zero()};
  vel[0] << 0.1, -0.2, 0.3, 4.0, -5.0, 6.0;
  vel[1] << -0.3, 0.1, 0.2, -2.0, 1.0, 3.0;
  addBeamTangent(rest, ev.rotation, 1.0, diagA, lower, diagB, vel, product, string);
  addBeamTangent(rest, ev.rotation, 1.0, diagA0, lower0, diagB0, vel, product0);
  const Mat3 withString = diagB.topLeftCorner<3, 3>(), material = diagB0.topLeftCorner<3, 3>();
  for (int j : {1, 2}) {
    // The material part uses the rest length, the forces the current one: 3e-4 apart.
    EXPECT_NEAR(withString(j, j), derivative(j, j), 1e-3 * derivative(j, j)) << "across the axis, " << j;
    EXPECT_GT(std::abs(material(j, j) - derivative(j, j)), 0.5 * derivative(j, j)) << j;
  }
  EXPECT_NEAR(withString(0, 0), derivative(0, 0), 1e-6 * derivative(0, 0)) << "along the axis: EA / l, no string";
  const Mat3 g = string * (Mat3::Identity() - Vec3::UnitX() * Vec3::UnitX().transpose());
  const Vec3 expected = g * (vel[0].head<3>() - vel[1].head<3>());
  EXPECT_LT((product[0].head<3>() - product0[0].head<3>() - expected).norm(), 1e-12 * expected.norm());
  EXPECT_LT((product[1].head<3>() - product0[1].head<3>() + expected).norm(), 1e-12 * expected.norm());
  EXPECT_EQ(product[0].tail<3>(), product0[0].tail<3>());
  EXPECT_LT((lower.topLeftCorner<3, 3>() - lower0.topLeftCorner<3, 3>() + g).norm(), 1e-9 * g.norm());
}

}  // namespace
}  // namespace coilsim
