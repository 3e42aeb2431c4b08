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

}  // namespace
}  // namespace coilsim
